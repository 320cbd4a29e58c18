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

/// What a tet's volume term carries in a stiffness fit (docs/methods/any_nu.md).
enum class VolumeTerm {
  kNone,    ///< springs only
  kFitted,  ///< k_V fitted with the springs to ||K_FEM - K_MSM - K_V||_F (Lloyd Sec. 4.2.2; Eq. 14 on a regular tet)
  kVolumetric,  ///< k_V = lambda_V V0 of cauchy_split(), springs fitted to the rest (`stiffness-fit-volume`)
};

struct StiffnessFitOptions {
  VolumeTerm volume = VolumeTerm::kNone;  ///< tets only; default kNone
  /// Tets only. true (default): fit the springs to the part of the FEM matrix a spring network can carry (the
  /// tet4 matrix at nu = 1/4 with E for springs only, with E_s of cauchy_split() beside a kVolumetric term); false: to
  /// the tet4 matrix at the material's nu itself (the paper's Sec. 4.2.1 literally).
  bool network_target = true;
};

/// Fits every element of a triangle, quad or tet mesh to its FEM matrix (CST, Q4, tet4) and sums the
/// per-element coefficients of shared springs. On tets the target is what a spring network can represent (see
/// StiffnessFitOptions::network_target): the literal fit at nu is its full symmetrisation, lambda' = mu' =
/// (lambda + 2 mu)/3, 17 times too stiff in shear at nu = 0.49 (docs/methods/any_nu.md). Quads get edge and diagonal
/// springs with a fitted prestrain (Eq. 11 generalised: the isotropic part k(1 - l0/l) of each spring's stiffness is
/// fitted as a multiple of the element's self-stress, so the rest shape stays an equilibrium); on a square at nu = 1/3
/// this is Eq. 10-11.
/// @throws InvalidArgument when a quad is so distorted that a fitted spring gets k <= 0
/// @param materials  one material, or one per element
SpringModel stiffness_fit(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                          const StiffnessFitOptions& options = {});

}  // namespace hooke::calibrate
