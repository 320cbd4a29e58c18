#pragma once
/// The one global factor that `stiffness-fit` and `stiffness-fit-volume` put on their fitted springs: Lloyd et
/// al. 2007, Eq. 1 with a single parameter theta = c, against the linear FEM of the same mesh under its own weight.
///
/// Why: the per-element Frobenius fit (Sec. 4.2.1) has the right shape but the wrong size on irregular tets; the
/// assembled network is 8-45 % too compliant, more so at high nu (docs/methods/any_nu.md, "Why the fitted springs
/// are too compliant"). Self-weight is the load every object carries; it deforms the whole body smoothly, so its
/// compliance is that of the low modes a user sees, and it is none of the papers' test loads (stretch, compression
/// and shear by a top traction), on which the factor is then checked held out.
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/material/material.hpp>
#include <hooke/mesh/mesh.hpp>
#include <string>
#include <vector>

namespace hooke::calibrate {

struct StiffnessScale {
  double factor = 1.0;      ///< c, dimensionless (> 0); 1 when the fit could not be made (see `note`)
  int held_nodes = 0;       ///< nodes held during the fit: the bottom face (min of the last coordinate) or slab
  int gauss_newton = 0;     ///< Gauss-Newton steps on the full model (0: closed form, or the reduced start held)
  int factorizations = 0;   ///< sparse factorisations made: the FEM's, then K(c) for each c evaluated
  double error_before = 0;  ///< sqrt(G(1) / dim): RMS over the loads of the relative node error, unscaled springs
  double error_after = 0;   ///< the same at c
  std::string note;         ///< why c = 1 was kept, when it was (empty otherwise)
};

/// Fits c so that the model whose springs are multiplied by c (volume or area terms kept as they are) comes
/// closest to the linear FEM of `mesh` and `materials` under self-weight along each axis a (a unit body force,
/// nodal forces from the lumped volumes, both models held at the nodes of the bottom face), in the sum of squared
/// relative node errors G(c) = sum_a |u_a(c) - u_FEM,a|^2 / |u_FEM,a|^2 (Eq. 1 with each load weighted by its own
/// size). Linear in the regime of small loads, so with springs alone u(c) = u(1) / c and
/// c = sum_a w_a |u_a(1)|^2 / sum_a w_a u_a(1) . u_FEM,a in closed form; with volume terms G is minimised by
/// Gauss-Newton on c (dG/dc from one extra solve per step), started from the minimiser of G on a Krylov subspace
/// built from the first factorisation (solves only), so that the full model normally needs one more factorisation.
/// When the bottom face does not hold the body (a mesh standing on a point or an edge), the nodes within 5 %,
/// 10 %, then 20 % of the height from the bottom are held. When no such support gives positive-definite
/// matrices, c = 1 is returned with a note; this function never throws for a valid mesh and model.
/// @param mesh       validated triangle, quad or tet mesh, m
/// @param materials  one material, or one per element (E in Pa, nu; t in m in 2D)
/// @param springs    the fitted model on mesh's nodes
StiffnessScale fit_self_weight_scale(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                     const SpringModel& springs);

/// `springs` with every spring stiffness k multiplied by `factor` (> 0); volume and area terms unchanged.
SpringModel with_scaled_springs(SpringModel springs, double factor);

}  // namespace hooke::calibrate
