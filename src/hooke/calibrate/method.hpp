#pragma once
/// Calibration methods: spring stiffness from Young's modulus and Poisson's ratio. Stable names are shared
/// by the library, the CLI and reports; docs/methods/ describes each with its equation and validity.
#include <hooke/calibrate/spring_model.hpp>
#include <hooke/material/material.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace hooke::calibrate {

enum class Method {
  kVanGelder,           ///< "vangelder": k = sum_e E t A_e / l^2 (triangles); sum_e E V_e / l^2 (tets)
  kLloydEquilateral,    ///< "lloyd-equilateral": Eq. 8, k = sum_e E t sqrt(3)/4 (triangles)
  kLloydTriangle,       ///< "lloyd-triangle": Eq. 9, k = sum_e E t sqrt(3)/4 A_e/A_0, A_0 = sqrt(3)/4 l^2
  kLloydSquare,         ///< "lloyd-square": Eq. 10-11, edges 5/16 t E (l0 = 6/5 l), diagonals 7/16 t E (l0 = 6/7 l)
  kLloydTet,            ///< "lloyd-tet": Eq. 12 with Eq. 13, k = sum_e 2 sqrt(2)/25 l_e E
  kLloydTetVolume,      ///< "lloyd-tet-volume": Eq. 14, springs plus volume terms
  kStiffnessFit,        ///< "stiffness-fit": per element, non-negative least squares on ||K_FEM - K_MSM||_F, then one
                        ///< factor on all springs from Eq. 1 under self-weight (fit_self_weight_scale)
  kStiffnessFitVolume,  ///< "stiffness-fit-volume": springs fitted at (E_s, nu = 1/4) plus k_V = lambda_V V0 per tet,
                        ///< the springs then scaled as in stiffness-fit
  kAnyNuTet,            ///< "any-nu-tet": Eq. 12-13 springs at E_s plus k_V = lambda_V V0 per tet (cauchy_split)
  kAnyNuTriangle  ///< "any-nu-triangle": Eq. 9 springs at E_s plus k_A = lambda_A t A0 per triangle (cauchy_split_2d)
};

Method method_from_name(std::string_view name);  ///< @throws InvalidArgument listing the names
std::string_view method_name(Method method);
/// Every calibration method's name, in the order of Method.
std::vector<std::string_view> method_names();
/// The paper and equation `method` implements, one line (hooke calibrate's report, the model file's "equation").
std::string_view method_equation(Method method);

/// Where `method` leaves the assumptions of its derivation on this mesh and material, one sentence each
/// (empty when it is applied where it is exact): lloyd-equilateral needs equilateral triangles and nu = 1/3
/// (Eq. 8), lloyd-triangle nu = 1/3 (Eq. 9 is an approximation on other shapes), lloyd-square squares and
/// nu = 1/3 (Eq. 10-11), lloyd-tet and lloyd-tet-volume nu = 1/4 (Eq. 12, 14). Shapes count as regular within 1 %.
std::vector<std::string> validity_warnings(const mesh::Mesh& mesh, const std::vector<material::Material>& materials,
                                           Method method);

/// Calibrates a mass-spring model on `mesh` (springs on the element edges; also the diagonals of quads).
/// @param materials  one material, or one per element (E in Pa, nu, thickness t in m for 2D)
/// Logs each of validity_warnings() as a warning.
/// @throws InvalidArgument when the method does not apply to the mesh's element kind
SpringModel calibrate(const mesh::Mesh& mesh, const std::vector<material::Material>& materials, Method method);

}  // namespace hooke::calibrate
