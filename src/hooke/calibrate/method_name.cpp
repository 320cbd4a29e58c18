// The calibration methods' stable names (method.hpp), apart from the methods themselves so that a program that only
// reads model files (tests/fuzz) needs none of the calibration code.
#include <hooke/calibrate/method.hpp>
#include <hooke/core/name_table.hpp>

namespace hooke::calibrate {
namespace {

constexpr NameTable<Method, 10> kNames{"calibration method",
                                       {{{Method::kVanGelder, "vangelder"},
                                         {Method::kLloydEquilateral, "lloyd-equilateral"},
                                         {Method::kLloydTriangle, "lloyd-triangle"},
                                         {Method::kLloydSquare, "lloyd-square"},
                                         {Method::kLloydTet, "lloyd-tet"},
                                         {Method::kLloydTetVolume, "lloyd-tet-volume"},
                                         {Method::kStiffnessFit, "stiffness-fit"},
                                         {Method::kStiffnessFitVolume, "stiffness-fit-volume"},
                                         {Method::kAnyNuTet, "any-nu-tet"},
                                         {Method::kAnyNuTriangle, "any-nu-triangle"}}}};

}  // namespace

Method method_from_name(std::string_view name) { return kNames.from_name(name); }
std::string_view method_name(Method method) { return kNames.name(method); }

std::vector<std::string_view> method_names() { return kNames.names(); }

std::string_view method_equation(Method method) {
  switch (method) {  // no default: a method without its equation does not compile (-Wswitch)
    case Method::kVanGelder: return "van Gelder 1998: k = sum_e E t A_e / l^2 (tets: E V_e / l^2)";
    case Method::kLloydEquilateral: return "Lloyd et al. 2007, Eq. 8: k = sum_e sqrt(3)/4 E t";
    case Method::kLloydTriangle: return "Lloyd et al. 2007, Eq. 9: k = sum_e sqrt(3)/4 E t A_e / A_0";
    case Method::kLloydSquare: return "Lloyd et al. 2007, Eq. 10-11: edge 5/16 E t, diagonal 7/16 E t, prestrained";
    case Method::kLloydTet: return "Lloyd et al. 2007, Eq. 12 with the equivalent edge length of Eq. 13";
    case Method::kLloydTetVolume: return "Lloyd et al. 2007, Eq. 14 with the equivalent edge length of Eq. 13";
    case Method::kStiffnessFit:
      return "Lloyd et al. 2007, Sec. 3.3 numerically: per element min ||K_FEM - K_MSM||_F, k >= 0 (tets: K_FEM at "
             "E, nu = 1/4, what springs can carry), then all k times one c fitted by Eq. 1 to the linear FEM under "
             "self-weight";
    case Method::kStiffnessFitVolume:
      return "hooke's any-nu fit: per tet min ||K_FEM(5 mu/2, 1/4) - K_MSM||_F, k >= 0, and a volume term "
             "k_V = (lambda - mu) V0 for nu >= 1/4 (App. C.2); the springs times one c fitted by Eq. 1 to the "
             "linear FEM under self-weight";
    case Method::kAnyNuTet:
      return "hooke's any-nu split: Lloyd et al. 2007 Eq. 12-13 springs at E_s = 5 mu / 2 and a volume term "
             "k_V = (lambda - mu) V0 per tet (App. C.2) for nu >= 1/4; below, Eq. 12-13 at E (lloyd-tet)";
    case Method::kAnyNuTriangle:
      return "hooke's any-nu split: Lloyd et al. 2007 Eq. 9 springs at E_s = 8 mu / 3 and an area term "
             "k_A = (lambda* - mu) t A0 per triangle for lambda* >= mu (nu >= 1/3 in plane stress); below, Eq. 9 at E";
  }
  return {};
}

}  // namespace hooke::calibrate
