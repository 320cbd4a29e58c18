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

}  // namespace hooke::calibrate
