// hooke calibrate MESH --young PA --poisson NU [--method M] [--density KG_M3] [--certify] -o MODEL: the calibrated
// model as a file (.json, .vtu, .csv; docs/model_format.md), optionally with its measured error against FEM.
#include <cstdio>
#include <hooke/calibrate/model_file.hpp>
#include <memory>
#include <string>

#include "commands.hpp"

namespace hooke::cli {
namespace {

struct CalibrateCli {
  ModelSource in;  ///< the mesh or model file and every calibration setting (the range fit's, the certificate's)
  std::string output;
};

void print_model(const calibrate::CalibratedModel& m) {
  const int d = m.mesh.dim();
  double total = 0.0;
  for (int i = 0; i < m.mesh.node_count(); ++i) total += m.masses(d * i);
  std::printf("hooke calibrate: %s, %d nodes, %d %s elements, method %s\n", m.mesh.source.c_str(), m.mesh.node_count(),
              m.mesh.element_count(), std::string(mesh::element_kind_name(m.mesh.kind)).c_str(), m.method.c_str());
  std::printf("  equation  %s\n", m.equation.c_str());
  std::printf("  model     %zu springs (k %.4g .. %.4g N/m), %ld volume terms%s, mass %.6g kg\n",
              m.springs.pairs.size(), m.springs.pairs.empty() ? 0.0 : m.springs.stiffness.minCoeff(),
              m.springs.pairs.empty() ? 0.0 : m.springs.stiffness.maxCoeff(),
              static_cast<long>(m.springs.volume_tets.rows()), m.surface ? ", anchors at every node" : "", total);
  if (!m.regions.empty())
    for (const std::string& line : calibrate::describe_region_materials(m.mesh, m.material, m.regions))
      std::printf("  material  %s\n", line.c_str());
  if (!m.meshing.empty()) std::printf("  meshing   %s\n", m.meshing.c_str());
  for (const auto& w : m.warnings) std::printf("  warning   %s\n", w.c_str());
}

void print_certificate(const std::vector<calibrate::CertificateCase>& cases, double height) {
  const bool range = !cases.empty() && cases.front().control == "displacement";
  if (range)
    std::printf(
        "  certificate against the %s FEM, displacement control (max / mean node error, relative L2, "
        "force on the top):\n",
        cases.front().reference.c_str());
  else
    std::printf("  certificate against the linear FEM (max / mean node error, relative L2):\n");
  for (const auto& c : cases) {
    std::printf("    %-9s %.3g %% strain: max %.4g m (%.3f %% of height), mean %.4g m, relative L2 %.4g",
                c.load.c_str(), 100.0 * c.strain, c.max_error, 100.0 * c.max_error / height, c.mean_error,
                c.relative_l2);
    if (range) std::printf(", force error %.4g", c.force_error);
    std::printf("\n");
  }
}

int run_calibrate(const CalibrateCli& o) {
  const experiments::CalibrationSettings settings = calibration_settings(o.in);
  calibrate::CalibratedModel model = load_model(o.in);
  // auto (a mesh given, no --model): the any-nu models fitted beside the small-strain pick, the best kept.
  const bool automatic = settings.model.method == "auto" && o.in.model_path.empty() && !model.surface;
  model = experiments::finish_calibration(std::move(model), settings, automatic);
  print_model(model);
  if (settings.strain_range > 0.0)
    std::printf("  term law  spring exponent %g, volume exponent %g: %s\n", model.springs.spring_exponent,
                model.springs.volume_exponent, model.choice.c_str());
  if (settings.certify) {
    const auto& n = model.mesh.nodes;
    print_certificate(model.certificate, n.col(n.cols() - 1).maxCoeff() - n.col(n.cols() - 1).minCoeff());
  }
  calibrate::write_model(o.output, model);
  std::printf("  wrote     %s\n", o.output.c_str());
  return 0;
}

}  // namespace

Action add_calibrate_command(CLI::App& app) {
  auto o = std::make_shared<CalibrateCli>();
  CLI::App* cmd = app.add_subcommand("calibrate", "Calibrate a spring model from E and nu and write it to a file");
  add_model_source_options(cmd, o->in, settings::kCalibrate);
  cmd->add_option("-o,--output", o->output, "Model file: .json (the whole model), .vtu (ParaView) or .csv (springs)")
      ->required();
  return [o] { return run_calibrate(*o); };
}

}  // namespace hooke::cli
