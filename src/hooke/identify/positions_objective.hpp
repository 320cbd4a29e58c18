#pragma once
/// Lloyd et al. 2007, Eq. 1: the distance between a spring model's static equilibria and reference deformations,
/// with its gradient by the adjoint method (one extra linear solve per case).
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/identify/parameter_layout.hpp>
#include <hooke/identify/reference_case.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <vector>

namespace hooke::identify {

/// The static equilibrium of `model` under a reference case: its applied forces on the free DOFs, its supports and
/// prescribed DOFs held at their reference positions, Newton from `start` (flat positions, m; empty: the reference
/// positions, or with prescribed DOFs from rest with their move ramped by the load factor, since a spring model need
/// not be stable at another model's deformed state).
solve::StaticResult reference_equilibrium(std::shared_ptr<const model::Model> model, const ReferenceCase& reference,
                                          const solve::StaticOptions& statics, const VecX& start = {});

/// Per case, |x_c - p_ref,c| / |p_ref,c - X| with x_c the equilibrium of `springs` on `mesh` under case c
/// (+infinity where no stable equilibrium is found): the relative L2 error of `hooke compare`, per case.
/// @param force_errors  if given, per case reaction_error at x_c (-1 for a case without prescribed DOFs, +infinity
///                      where no equilibrium was found)
std::vector<double> position_errors(const mesh::Mesh& mesh, const calibrate::SpringModel& springs,
                                    const std::vector<ReferenceCase>& cases, const solve::StaticOptions& statics = {},
                                    std::vector<double>* force_errors = nullptr);

/// The error of the force an instrument feels, as `hooke compare` reports it: |sum R - sum R_ref| / |sum R_ref| over
/// the case's prescribed DOFs, R = `gradient` (dE/dx at the equilibrium, flat, N) and R_ref its measured forces,
/// summed over the nodes per axis (`dim` entries). -1 for a case without prescribed DOFs.
double reaction_error(const ReferenceCase& reference, const VecX& gradient, int dim);

class PositionsObjective {
 public:
  /// @param mesh     the rest mesh (the orientation guard's elements), m
  /// @param layout   the unknowns, without rest-length offsets (kept by reference)
  /// @param cases    the cases to match (all of them; held_out is not looked at)
  /// @param statics  options of the static solves
  /// @throws InvalidArgument for a layout with offsets or bad cases
  PositionsObjective(const mesh::Mesh& mesh, const ParameterLayout& layout, std::vector<ReferenceCase> cases,
                     const solve::StaticOptions& statics = {});

  /// G(theta) = sum_c |x_c(theta) - p_ref,c|^2 / sum_c |p_ref,c - X|^2 (dimensionless), x_c the equilibrium of the
  /// spring model of theta under case c's forces with its supports at their reference positions (warm-started from
  /// the last equilibrium found). +infinity when an equilibrium is not found or not stable. Under displacement control
  /// the positions alone do not fix the stiffness's scale (every k times c has the same equilibria), so cases with
  /// prescribed DOFs add the mean over them of |S (R_c(theta) - R_ref,c)|^2 / |S R_ref,c|^2, R_c = U_P(x_c) theta the
  /// force holding them per DOF and S its sum over the nodes: the total force the instrument feels, as reaction_error
  /// reports it (every case weighs the same, so shear counts as much as compression). With
  /// `gradient`: dG/dtheta = -2/G_ref sum_c U(x_c)^T lambda_c with H(x_c) lambda_c = x_c - p_ref,c on the free DOFs (H
  /// the model's Hessian there; equilibrium U(x) theta = f differentiated in theta); the force term adds 2 U^T v_c with
  /// v_P = w_c S^T S (R_c - R_ref,c), w_c the case's weight, and H_FF v_F = -H_FP v_P.
  /// @pre theta >= 0 (layout.size())
  double value(const VecX& theta, VecX* gradient = nullptr);
  /// Per case, the relative distance |x_c - p_ref,c| / |p_ref,c - X| of the last value() call.
  const std::vector<double>& case_errors() const { return m_case_errors; }
  /// Equilibria of the last value() call (flat positions, m), one per case.
  const std::vector<VecX>& equilibria() const { return m_equilibria; }
  int static_solves() const { return m_solves; }

 private:
  const mesh::Mesh& m_mesh;
  const ParameterLayout& m_layout;
  std::vector<ReferenceCase> m_cases;
  solve::StaticOptions m_statics;
  std::vector<VecX> m_equilibria;
  std::vector<double> m_case_errors;
  double m_reference = 0.0;
  /// per case 1 / (cases with prescribed DOFs x |S R_ref,c|^2), 1/N^2; 0 for a case without
  std::vector<double> m_force_weights;
  int m_solves = 0;
};

}  // namespace hooke::identify
