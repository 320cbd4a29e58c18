// Lloyd et al. 2007 Sec. 3.3 (and 4.2.1) numerically: per element the springs of least ||K_FEM - K_MSM||_F
// (stiffness_fit), then one factor on all springs from Eq. 1 under self-weight (stiffness_scale).
#include <hooke/calibrate/methods/families.hpp>
#include <hooke/calibrate/stiffness_fit.hpp>
#include <hooke/calibrate/stiffness_scale.hpp>
#include <hooke/core/log.hpp>
#include <string>

namespace hooke::calibrate::methods {
namespace {

SpringModel fitted(const mesh::Mesh& m, const std::vector<material::Material>& materials, Method method) {
  const SpringModel fit = stiffness_fit(
      m, materials, {.volume = method == Method::kStiffnessFit ? VolumeTerm::kNone : VolumeTerm::kVolumetric});
  const StiffnessScale scale = fit_self_weight_scale(m, materials, fit);
  if (!scale.note.empty())
    log_warning(std::string(method_name(method)) + ": the fitted springs are left unscaled: " + scale.note);
  else
    log(LogLevel::kInfo, std::string(method_name(method)) + ": springs scaled by c = " + std::to_string(scale.factor) +
                             " (self-weight, Eq. 1; relative error " + std::to_string(scale.error_before) + " -> " +
                             std::to_string(scale.error_after) + ")");
  return with_scaled_springs(fit, scale.factor);
}

bool any_mesh(const mesh::Mesh&) { return true; }  // stiffness_fit names what it refuses

}  // namespace

std::vector<MethodEntry> stiffness_fit_methods() {
  return {method(Method::kStiffnessFit,
                 "Lloyd et al. 2007, Sec. 3.3 numerically: per element min ||K_FEM - K_MSM||_F, k >= 0 (tets: K_FEM at "
                 "E, nu = 1/4, what springs can carry), then all k times one c fitted by Eq. 1 to the linear FEM under "
                 "self-weight",
                 any_mesh, "", fitted),
          method(Method::kStiffnessFitVolume,
                 "hooke's any-nu fit: per tet min ||K_FEM(5 mu/2, 1/4) - K_MSM||_F, k >= 0, and a volume term "
                 "k_V = (lambda - mu) V0 for nu >= 1/4 (App. C.2); the springs times one c fitted by Eq. 1 to the "
                 "linear FEM under self-weight",
                 any_mesh, "", fitted)};
}

}  // namespace hooke::calibrate::methods
