// hooke simulate (MESH --young PA --poisson NU --method NAME | --model MODEL.json) --integrator NAME --dt S
// --steps N [...] -o DIR: dynamics of a calibrated model with a ParaView time series and a timing report.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <hooke/contact/rigid_tool.hpp>
#include <hooke/contact/tool_path.hpp>
#include <hooke/core/atomic_file.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/quantile.hpp>
#include <hooke/io/series.hpp>
#include <hooke/solve/simulation.hpp>
#include <memory>
#include <string>

#include "commands.hpp"

namespace hooke::cli {
namespace {

struct SimulateCli {
  ModelSource in;
  IntegratorInput integrator;
  std::string out_dir;
  solve::SimulationOptions run;
  bool free_body = false, no_reorder = false;
  std::vector<double> probe_offset, probe_force;
  std::string tool, tool_path;         ///< --tool sphere:R|capsule:R,L|plane, --tool-path FILE (m, s)
  std::vector<std::string> obstacles;  ///< --obstacle plane:X,Y,Z[,NX,NY,NZ] (m)
};

VecX as_vector(const std::vector<double>& v) {
  return Eigen::Map<const VecX>(v.data(), static_cast<Eigen::Index>(v.size()));
}

void print_summary(const SimulateCli& o, const calibrate::CalibratedModel& model, const solve::SimulationSummary& s,
                   const std::string& pvd, int frames) {
  const auto steps = static_cast<double>(s.step_ms.size());
  std::printf("hooke simulate: %s, %d nodes, %s model, %s, dt %.3g s, %zu steps (%.4g s)\n", model.mesh.source.c_str(),
              model.mesh.node_count(), model.method.c_str(),
              std::string(solve::integrator_name(o.run.simulator.integrator)).c_str(), o.run.dynamics.dt,
              s.step_ms.size(), s.time);
  std::printf("  time      %.4g ms/step median, %.4g ms/step p95; %.3g solver iterations per step\n",
              quantile(s.step_ms, 0.5), quantile(s.step_ms, 0.95), static_cast<double>(s.iterations) / steps);
  std::printf("  energy    %.6g J at start, %.6g J at end (kinetic %.6g J)\n", s.energy_start, s.energy_end,
              s.kinetic_end);
  if (o.run.probe_node >= 0) std::printf("  probe     max force on the device %.6g N\n", s.max_probe_force);
  if (!s.tool_force.empty()) {
    double largest = 0.0;
    for (const auto& f : s.tool_force) largest = std::max(largest, std::hypot(f[1], f[2], f[3]));
    const auto& last = s.tool_force.back();
    std::printf(
        "  tool      %s: force on it %.6g, %.6g, %.6g N at the end (largest %.6g N); smallest gap %.3g m "
        "(activation %.3g m), %d nodes pushed out of its way\n",
        o.run.tool->description().c_str(), last[1], last[2], last[3], largest, s.smallest_gap, s.contact_distance,
        s.pushed_nodes);
  }
  for (std::size_t k = 0; k < s.obstacle_force.size(); ++k)
    std::printf("  obstacle  %s: force on it %.6g, %.6g, %.6g N at the end; smallest gap %.3g m\n",
                o.obstacles[k].c_str(), s.obstacle_force[k][0], s.obstacle_force[k][1], s.obstacle_force[k][2],
                s.obstacle_gap.empty() ? 0.0 : s.obstacle_gap[k]);
  if (s.creep_velocity > 0.0)
    std::printf("  friction  coefficient %.3g, creep velocity %.3g m/s\n", o.run.friction, s.creep_velocity);
  if (s.beyond_stable_dt > 0)
    std::printf("  warning   %d steps beyond the explicit stability limit %.4g s\n", s.beyond_stable_dt,
                s.stable_time_step);
  if (s.not_converged > 0) std::printf("  warning   %d steps ended above the Newton tolerance\n", s.not_converged);
  std::printf("  wrote     %s (%d frames)\n", pvd.c_str(), frames);
}

int run_simulate(SimulateCli o) {
  const calibrate::CalibratedModel model = load_model(o.in);
  apply_integrator_options(o.integrator, o.run.simulator);
  o.run.clamp_bottom = !o.free_body;
  o.run.reorder = !o.no_reorder;
  o.run.probe_offset = as_vector(o.probe_offset);
  o.run.probe_force = as_vector(o.probe_force);
  if (o.tool.empty() != o.tool_path.empty()) throw InvalidArgument("--tool and --tool-path go together");
  if (!o.tool.empty()) {
    o.run.tool = std::make_shared<contact::RigidTool>(contact::parse_tool(o.tool));
    o.run.tool_path = contact::read_tool_path(o.tool_path);
  }
  for (const std::string& text : o.obstacles) o.run.obstacles.push_back(contact::parse_obstacle(text));
  io::SeriesWriter series(o.out_dir, model.mesh);  // frames appear only when the whole run succeeded
  const int d = model.mesh.dim();
  const solve::SimulationSummary s = solve::simulate(model, o.run, [&](int, double t, const VecX& u, const VecX& v) {
    series.write(t, {{"displacement", d, u}, {"velocity", d, v}});
  });
  const int frames = series.frame_count();
  const std::string pvd = series.commit().string();
  if (!s.tool_force.empty())
    write_file_atomically(std::filesystem::path(o.out_dir) / "tool_force.csv", [&](std::ostream& out) {
      out << "t,fx,fy,fz\n";
      char row[128];
      for (const auto& f : s.tool_force) {
        std::snprintf(row, sizeof row, "%.9g,%.9g,%.9g,%.9g\n", f[0], f[1], f[2], f[3]);
        out << row;
      }
    });
  print_summary(o, model, s, pvd, frames);
  return 0;
}

}  // namespace

Action add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateCli>();
  o->in.law = "stvk";
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate a calibrated model (or the FEM model) in time");
  add_model_source_options(cmd, o->in, settings::kSimulate);
  cmd->add_option("--law", o->in.law, "FEM law with --method fem: linear, stvk, neohookean")->capture_default_str();
  add_integrator_options(cmd, o->integrator, o->run.simulator);
  add_dynamics_options(cmd, o->run.dynamics);
  cmd->add_option("--steps", o->run.steps, "Number of steps")->capture_default_str();
  cmd->add_flag("--free", o->free_body, "Do not clamp the bottom nodes");
  cmd->add_flag("--allow-unconverged", o->run.allow_unconverged,
                "Keep going (with a warning) when a step ends above the Newton tolerance instead of failing (exit 3)");
  cmd->add_flag(
      "--no-reorder", o->no_reorder,
      "Simulate in the file's node order instead of reverse Cuthill-McKee (outputs are in file order either way)");
  cmd->add_option("--probe-node", o->run.probe_node, "Node grabbed by the probe");
  cmd->add_option("--probe-offset", o->probe_offset, "Drive the probe node by this offset (m), ramped over the run")
      ->delimiter(',');
  cmd->add_option("--probe-force", o->probe_force, "Push the probe node with this force (N), ramped over the run")
      ->delimiter(',');
  cmd->add_option("--tool", o->tool,
                  "A rigid tool pressing the body (docs/contact.md): sphere:R, capsule:R,L (m) or plane; with "
                  "--tool-path");
  cmd->add_option("--tool-path", o->tool_path,
                  "The tool's poses over time: CSV with columns t,x,y,z (s, m) and optionally qw,qx,qy,qz; "
                  "writes DIR/tool_force.csv (t,fx,fy,fz: the force the body exerts on the tool, N)");
  cmd->add_option("--obstacle", o->obstacles,
                  "A static obstacle the body may rest on (with --friction's coefficient): plane:X,Y,Z (a floor "
                  "through that point, m), plane:X,Y,Z,NX,NY,NZ (with that outward normal) or mesh:FILE[,ROUNDING] (a "
                  "closed triangle surface where the file puts it, m); repeatable. With --free and --gravity a body "
                  "rests on it instead of being clamped");
  cmd->add_option("--contact-distance", o->run.contact_distance,
                  "The contact barrier's activation distance, m (0: 1 % of the mean boundary edge)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--friction", o->run.friction,
                  "Coulomb friction coefficient of the tool's and the obstacles' contacts (0: frictionless)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--creep-velocity", o->run.creep_velocity,
                  "With friction: the slip velocity below which friction acts as a stiff drag, m/s (a contact below "
                  "the friction limit creeps slower than this; 0: 1e-2 of the body's bounding-box diagonal per s)")
      ->check(CLI::NonNegativeNumber)
      ->capture_default_str();
  cmd->add_option("--every", o->run.every, "Write a frame every this many steps (default: about 100 frames)");
  cmd->add_option("-o,--output", o->out_dir, "Folder for simulation.pvd and frames/")->required();
  return [o] { return run_simulate(*o); };
}

}  // namespace hooke::cli
