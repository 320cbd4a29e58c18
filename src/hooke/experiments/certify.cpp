#include <cmath>
#include <hooke/core/error.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/experiments/compare.hpp>

namespace hooke::experiments {

std::vector<calibrate::CertificateCase> certify(const calibrate::CalibratedModel& model, double strain, int layers,
                                                const std::vector<model::LoadKind>& loads) {
  if (!(strain > 0.0) || !std::isfinite(strain)) throw InvalidArgument("certify: the strain must be > 0");
  if (loads.empty()) throw InvalidArgument("certify: no load case to certify");
  CompareOptions o;
  o.strain = strain;
  // Certificates are taken at small strains (1 % by default), where Newton reaches the equilibrium from rest in one
  // load step; a step that fails is halved as before, and the state is still checked for stability. Each
  // factorisation is about 9 s on the Stanford bunny's 233 000 DOFs: the load cases share the FEM's (one linear
  // solve per case) and the model's first one (the stability of the rest state, and modified Newton's start).
  o.load_steps = 1;
  std::vector<calibrate::CertificateCase> out;
  const std::vector<Comparison> cases = compare_calibrated_cases(model, loads, o, layers);
  for (size_t k = 0; k < loads.size(); ++k) {
    const Comparison& c = cases[k];
    solve::require_converged(c.fem_report);
    solve::require_converged(c.spring_report);
    out.push_back({std::string(model::load_kind_name(loads[k])), strain, c.max_error, c.mean_error, c.relative_l2});
  }
  return out;
}

std::vector<calibrate::CertificateCase> certify_range(const calibrate::CalibratedModel& model, material::Law law,
                                                      double strain_range, int layers,
                                                      const std::vector<model::LoadKind>& loads) {
  if (!(strain_range > 0.0) || !std::isfinite(strain_range))
    throw InvalidArgument("certify: the strain range must be > 0");
  if (loads.empty()) throw InvalidArgument("certify: no load case to certify");
  std::vector<calibrate::CertificateCase> out;
  for (double strain : {0.01, strain_range}) {
    CompareOptions o;
    o.strain = strain;
    o.reference = law;
    o.control = model::LoadControl::kDisplacement;
    const std::vector<Comparison> cases = compare_calibrated_cases(model, loads, o, layers);
    for (size_t k = 0; k < loads.size(); ++k) {
      const Comparison& c = cases[k];
      solve::require_converged(c.fem_report);
      solve::require_converged(c.spring_report);
      calibrate::CertificateCase one{std::string(model::load_kind_name(loads[k])), strain, c.max_error, c.mean_error,
                                     c.relative_l2};
      one.control = std::string(model::load_control_name(model::LoadControl::kDisplacement));
      one.reference = std::string(material::law_name(law));
      one.force_error = c.reaction_error;
      out.push_back(std::move(one));
    }
  }
  return out;
}

}  // namespace hooke::experiments
