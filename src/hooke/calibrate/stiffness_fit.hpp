#pragma once
/// The paper's identification done numerically (Lloyd et al. 2007, Sec. 3.3 and 4.2.1): for each element,
/// the non-negative spring coefficients (and k_V) minimising ||K_FEM - K_MSM||_F^2, then assembled.
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/material/material.hpp>
#include <vector>

namespace hooke::calibrate {

/// Non-negative least squares min ||target - sum_s c_s basis_s||_F over c >= 0, exact for up to 12 bases
/// (every support set is tried). Returns c; `residual` receives the minimal Frobenius norm.
VecX fit_nonnegative(const MatX& target, const std::vector<MatX>& bases, double* residual = nullptr);

struct StiffnessFitOptions {
  bool volume_terms = false;  ///< tets only: also fit k_V of a volume term per tet (App. C.2), default false
};

/// Fits every element of a triangle, quad or tet mesh to its FEM matrix (CST, Q4, tet4) and sums the
/// per-element coefficients of shared springs. Quads get edge and diagonal springs with a fitted prestrain
/// (Eq. 11 generalised: the isotropic part k(1 - l0/l) of each spring's stiffness is fitted as a multiple of the
/// element's self-stress, so the rest shape stays an equilibrium); on a square at nu = 1/3 this is Eq. 10-11.
/// @throws InvalidArgument when a quad is so distorted that a fitted spring gets k <= 0
/// @param materials  one material, or one per element
SpringModel stiffness_fit(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                          const StiffnessFitOptions& options = {});

}  // namespace hooke::calibrate
