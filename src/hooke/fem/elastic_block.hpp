#pragma once
/// FEM term block: all elements of a triangle, quad or tet mesh with a hyperelastic law.
#include <hooke/core/element_schedule.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <hooke/model/model.hpp>
#include <hooke/model/term_block.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace hooke::fem {

/// Energy E = sum_e sum_q w_q psi(F_q) over the elements of a mesh. F is built from the reference
/// shape-function gradients: one point for CST and tet4, 2 x 2 Gauss points for Q4; w_q includes the
/// thickness t in 2D. With the linear law its Hessian is the assembled linear stiffness K (constant).
/// energy() is +infinity where any element is inverted (det F <= 0 at a quadrature point), for every law, so
/// that solvers never accept a state in which the body has passed through itself.
class ElasticBlock final : public model::TermBlock {
 public:
  /// @param mesh       validated triangle, quad or tet mesh (positions in m)
  /// @param materials  one material per element, or a single one for all (validated here)
  /// @throws InvalidArgument for a surface mesh; InvalidMesh for an element with non-positive Jacobian;
  ///         InvalidMaterial for bad parameters
  ElasticBlock(const mesh::Mesh& mesh, const std::vector<material::Material>& materials);

  std::string_view name() const override { return "fem"; }
  double energy(const Eigen::Ref<const VecX>& x) const override;
  void add_gradient(const Eigen::Ref<const VecX>& x, Eigen::Ref<VecX> gradient) const override;
  RowMatXi element_nodes() const override { return m_elements; }
  void add_hessian_values(const Eigen::Ref<const VecX>& x, const model::HessianScatter& scatter, double* values,
                          bool project_psd) const override;

  /// Energy (J), gradient (N, size dim*npe) and Hessian (N/m) of element `e` alone at x.
  void element_derivatives(const Eigen::Ref<const VecX>& x, int e, double& energy, VecX& gradient, MatX& hessian) const;

 private:
  // Energy (added to *energy), gradient and Hessian of element e; null outputs are skipped.
  // Returns false where the energy is infinite (an inverted element under the Neo-Hookean law).
  bool element_terms(const Eigen::Ref<const VecX>& x, int e, double* energy, VecX* gradient, MatX* hessian) const;

  mesh::ElementKind m_kind;
  int m_dim;
  int m_npe;
  RowMatXi m_elements;
  std::vector<material::Law> m_law;    // per element
  std::vector<material::Lame> m_lame;  // per element
  std::vector<int> m_first_point;      // per element + 1: range of its quadrature points
  std::vector<double> m_weight;        // per quadrature point: reference measure (m^3, or m^2 * t)
  std::vector<double> m_grad;          // per quadrature point: npe x dim dN/dX, row-major
  ElementSchedule m_schedule;
};

/// Convenience: one material for every element.
std::unique_ptr<ElasticBlock> make_elastic_block(const mesh::Mesh& mesh, const material::Material& material);

/// The FEM model of `mesh`: one ElasticBlock over every element, at the mesh's rest positions (m), with
/// `materials` (one, or one per element) under their own laws, or all under `law` when given.
/// @throws as ElasticBlock
std::shared_ptr<model::Model> elastic_model(const mesh::Mesh& mesh, std::vector<material::Material> materials,
                                            std::optional<material::Law> law = std::nullopt);

/// The linear FEM model of `mesh` (elastic_model under the linear law): its Hessian is the stiffness K, N/m.
inline std::shared_ptr<model::Model> linear_model(const mesh::Mesh& mesh,
                                                  const std::vector<material::Material>& materials) {
  return elastic_model(mesh, materials, material::Law::kLinear);
}

}  // namespace hooke::fem
