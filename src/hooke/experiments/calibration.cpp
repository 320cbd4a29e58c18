#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/experiments/calibration.hpp>
#include <hooke/experiments/certify.hpp>
#include <hooke/experiments/term_law_fit.hpp>

namespace hooke::experiments {
namespace {

using settings::Setting;
using Settings = CalibrationSettings;

// The range fit runs in calibrate and in the batch table's jobs; the certificate options are calibrate's (a batch job
// always certifies, at its own strain column).
constexpr unsigned kRange = settings::kCalibrate | settings::kBatch;

std::vector<Setting<Settings>> rows() {
  std::vector<Setting<Settings>> r = settings::lift<Settings>(
      calibrate::model_settings(), [](Settings& s) -> calibrate::ModelOptions& { return s.model; });
  r.push_back(settings::choice<Settings>(
      "law", kRange, "The FEM law the model follows at large strain, with strain-range",
      [] {
        return std::vector<std::string>{"linear", "stvk", "neohookean"};
      },
      [](Settings& s, std::string_view t) { s.law = material::law_from_name(t); },
      [](const Settings& s) { return std::string(material::law_name(s.law)); }));
  r.push_back(settings::number<Settings>(
      "strain-range", "", 0.0, 0.5, kRange,
      "Fit the springs' and volume terms' large-strain law to law up to this strain (displacement-controlled "
      "stretch, compression, shear at S/2 and S; 0: no fit); the certificate then measures 1 % and S against it",
      [](Settings& s) -> double& { return s.strain_range; }));
  r.push_back(settings::integer<Settings>(
      "fit-refinements", 0, 8, kRange,
      "The range fit's pattern-search steps after its grid, halving from 1/2 (3: exponents to 1/8; each step more "
      "costs a few FEM-sized solves per case)",
      [](Settings& s) -> int& { return s.fit_refinements; }));
  r.push_back(settings::flag<Settings>(
      "certify", settings::kCalibrate,
      "Also measure the model against the FEM (stretch, compress, shear) and store the errors in the model",
      [](Settings& s) -> bool& { return s.certify; }));
  Setting<Settings> strain = settings::number<Settings>("certify-strain", "", 0.0, 0.5, settings::kCalibrate,
                                                        "The certificate's mean strain without a strain range",
                                                        [](Settings& s) -> double& { return s.certify_strain; });
  strain.exclusive_min = true;
  r.push_back(strain);
  r.push_back(settings::integer<Settings>("layers", 1, 64, settings::kCalibrate,
                                          "surface: layers of the radial tetrahedralisation for the certificate",
                                          [](Settings& s) -> int& { return s.layers; }));
  return r;
}

}  // namespace

std::span<const settings::Setting<CalibrationSettings>> calibration_settings() {
  static const std::vector<settings::Setting<CalibrationSettings>> table = rows();
  return table;
}

calibrate::CalibratedModel finish_calibration(calibrate::CalibratedModel model, const CalibrationSettings& s,
                                              bool automatic) {
  if (!(s.strain_range >= 0.0)) throw InvalidArgument("the strain range must be >= 0");
  if (s.strain_range > 0.0) {
    TermLawFitOptions fo;
    fo.law = s.law;
    fo.strain_range = s.strain_range;
    fo.refinements = s.fit_refinements;
    model = automatic ? choose_for_range(model, fo) : with_fitted_law(model, fo);
  } else if (s.law != material::Law::kLinear) {
    throw InvalidArgument("law " + std::string(material::law_name(s.law)) +
                          " needs a strain range (the strain up to which the model follows it)");
  }
  if (s.certify)
    model.certificate = s.strain_range > 0.0 ? certify_range(model, s.law, s.strain_range, s.layers)
                                             : certify(model, s.certify_strain, s.layers);
  return model;
}

calibrate::CalibratedModel calibrate_with(const mesh::Mesh& mesh, const material::Material& material,
                                          const CalibrationSettings& s) {
  calibrate::CalibratedModel model = calibrate::calibrate_model(mesh, material, s.model);
  const bool automatic = s.model.method == "auto" && !model.surface;
  return finish_calibration(std::move(model), s, automatic);
}

}  // namespace hooke::experiments
