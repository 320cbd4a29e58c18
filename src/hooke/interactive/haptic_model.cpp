#include <hooke/core/name_table.hpp>
#include <hooke/interactive/haptic_model.hpp>

namespace hooke::interactive {
namespace {

constexpr NameTable<HapticStiffness, 3> kStiffnesses{"haptic stiffness",
                                                     {{{HapticStiffness::kNone, "none"},
                                                       {HapticStiffness::kCondensed, "condensed"},
                                                       {HapticStiffness::kSecant, "secant"}}}};

}  // namespace

HapticStiffness haptic_stiffness_from_name(std::string_view name) { return kStiffnesses.from_name(name); }
std::string_view haptic_stiffness_name(HapticStiffness stiffness) { return kStiffnesses.name(stiffness); }

MatX curvature_along(const MatX& curvature, const VecX& s) {
  const Eigen::Index d = s.size();
  MatX out = MatX::Zero(d, d);
  for (Eigen::Index a = 0; a < d; ++a) out.col(a) = curvature.middleCols(a * d, d) * s;
  return out;
}

}  // namespace hooke::interactive
