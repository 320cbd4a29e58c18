// hooke simulate MESH --young PA --poisson NU --method NAME --integrator NAME --dt S --steps N [...] -o DIR:
// dynamics of a calibrated spring model (or the FEM model) with a ParaView time series and a timing report.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <hooke/calibrate/method.hpp>
#include <hooke/calibrate/surface_model.hpp>
#include <hooke/core/error.hpp>
#include <hooke/core/units.hpp>
#include <hooke/experiments/load_case.hpp>
#include <hooke/fem/elastic_block.hpp>
#include <hooke/io/mesh_io.hpp>
#include <hooke/io/pvd.hpp>
#include <hooke/io/vtu.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/reorder.hpp>
#include <hooke/model/mass.hpp>
#include <hooke/solve/simulator.hpp>
#include <memory>
#include <numeric>
#include <string>

#include "commands.hpp"

namespace hooke::cli {
namespace {

struct SimulateCli {
  ModelInput in;
  std::string method = "lloyd-tet", law = "stvk", integrator = "implicit-euler", linear_solver = "cholesky",
              global_solve = "direct", out_dir;
  SurfaceInput surface;
  double density = 1000.0, dt = 1e-3, damping_mass = 0.0, damping_stiffness = 0.0, influence_radius = 0.0;
  int steps = 100, every = 0, probe_node = -1, iterations = 10;
  bool gravity = false, free_body = false, no_reorder = false;
  std::vector<double> probe_offset, probe_force;
};

double percentile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[static_cast<size_t>(q * static_cast<double>(v.size() - 1) + 0.5)];
}

int run_simulate(const SimulateCli& o) {
  io::ReadOptions ro;
  ro.metres_per_unit = metres_per_unit(o.in.unit);
  const mesh::Mesh file_mesh = io::read_mesh(o.in.mesh_path, ro);
  const int d = file_mesh.dim();
  // Simulate in reverse Cuthill-McKee order (cache locality; same trajectory, tests/solve/test_simulator.cpp);
  // node numbers in options and outputs stay the file's.
  std::vector<int> new_to_old(static_cast<size_t>(file_mesh.node_count()));
  std::iota(new_to_old.begin(), new_to_old.end(), 0);
  if (!o.no_reorder) new_to_old = mesh::rcm_order(file_mesh);
  const mesh::Mesh m = mesh::permute_nodes(file_mesh, new_to_old);
  std::vector<int> old_to_new(new_to_old.size());
  for (size_t k = 0; k < new_to_old.size(); ++k) old_to_new[static_cast<size_t>(new_to_old[k])] = static_cast<int>(k);
  auto in_file_order = [&](const VecX& field) {
    VecX out(field.size());
    for (size_t k = 0; k < new_to_old.size(); ++k)
      out.segment(d * new_to_old[k], d) = field.segment(d * static_cast<Eigen::Index>(k), d);
    return out;
  };
  material::Material mat{material::Law::kLinear, o.in.young, o.in.poisson, material::Plane::kStress, o.in.thickness};
  material::validate(mat);
  const VecX rest = Eigen::Map<const VecX>(m.nodes.data(), m.nodes.size());
  std::shared_ptr<model::Model> model;
  VecX masses;
  const surface::VolumePenaltyBlock* volume = nullptr;
  if (o.method == "surface") {
    // Arnab & Raja's surface model (docs/surface.md): the anchors hold the body, no node is clamped.
    calibrate::SurfaceOptions so = surface_options(o.surface);
    so.density = o.density;
    const calibrate::SurfaceModel s = calibrate::make_surface_model(m, mat, so);
    model = s.model;
    masses = s.masses;
    volume = s.volume;
  } else if (o.method == "fem") {
    mat.law = material::law_from_name(o.law);
    model = std::make_shared<model::Model>(d, rest);
    model->add(fem::make_elastic_block(m, mat));
  } else {
    model = calibrate::make_model(m, calibrate::calibrate(m, {mat}, calibrate::method_from_name(o.method)));
  }
  model::Problem problem = model::make_problem(model);
  if (!o.free_body && o.method != "surface")
    model::fix_nodes(problem,
                     experiments::make_load_case(m, experiments::LoadKind::kStretch, 0.0, o.in.thickness).fixed_nodes);
  if (masses.size() == 0) masses = model::lumped_masses(m, o.density, o.in.thickness);
  solve::Dynamics dyn{masses, VecX(), o.damping_mass, o.damping_stiffness};
  if (o.gravity) {
    dyn.gravity = VecX::Zero(d);
    dyn.gravity(d - 1) = -9.81;  // along -y in 2D, -z in 3D: the meshes' vertical axis
  }
  solve::SimulatorOptions so;
  so.integrator = solve::integrator_from_name(o.integrator);
  so.linear_solver = solve::newton_linear_solver_from_name(o.linear_solver);
  so.global_solve = solve::global_solve_from_name(o.global_solve);
  if (o.iterations < 1) throw InvalidArgument("--iterations must be at least 1");
  so.local_global_iterations = o.iterations;
  solve::Simulator sim(problem, dyn, so);
  solve::Probe probe;
  if (o.probe_node >= 0) {
    const auto& v = o.probe_offset.empty() ? o.probe_force : o.probe_offset;
    if (v.size() != static_cast<size_t>(d) || (!o.probe_offset.empty() && !o.probe_force.empty()))
      throw InvalidArgument("--probe-node needs exactly one of --probe-offset and --probe-force, with " +
                            std::to_string(d) + " components");
    if (o.probe_node >= m.node_count())
      throw InvalidArgument("--probe-node " + std::to_string(o.probe_node) + " is not a node of " + o.in.mesh_path);
    probe.nodes = {old_to_new[static_cast<size_t>(o.probe_node)]};
    probe.drive_position = !o.probe_offset.empty();
    probe.offset = probe.force = VecX::Zero(d);
    sim.set_probe(probe);
    if (volume) {  // the weights of Eq. 4 follow the probe (Arnab & Raja, Fig. 11)
      const double radius = o.influence_radius > 0.0 ? o.influence_radius : 0.5 * mesh::bounding_box_diagonal(m);
      Vec3 direction;
      for (int a = 0; a < 3; ++a) direction(a) = v[static_cast<size_t>(a)];
      if (direction.norm() > 0.0) volume->set_interaction({m.nodes.row(probe.nodes[0]).transpose(), direction, radius});
    }
  }
  if (o.steps < 1) throw InvalidArgument("--steps must be at least 1");
  const int every = o.every > 0 ? o.every : std::max(1, o.steps / 100);
  // Frames go to frames.partial/ and become frames/ only when the whole run succeeded.
  const std::filesystem::path dir(o.out_dir), frames_dir = dir / "frames.partial";
  std::filesystem::remove_all(frames_dir);
  std::filesystem::create_directories(frames_dir);
  std::vector<io::PvdFrame> frames;
  auto write_frame = [&](int k) {
    if (!std::isfinite(sim.potential_energy()))
      throw SolverFailure("step " + std::to_string(k) + " inverted an element (" + o.integrator + ", dt " +
                          std::to_string(o.dt) + " s; explicit stability limit " +
                          std::to_string(sim.stable_time_step()) + " s): use a smaller dt or an implicit integrator");
    const std::string name = "frame_" + std::to_string(k) + ".vtu";
    io::write_vtu(
        frames_dir / name, file_mesh,
        {{"displacement", d, in_file_order(sim.positions() - rest)}, {"velocity", d, in_file_order(sim.velocities())}});
    frames.push_back({sim.time(), "frames/" + name});
  };
  struct Cleanup {  // a failed run leaves no partial series behind
    std::filesystem::path partial;
    bool done = false;
    ~Cleanup() {
      std::error_code ec;
      if (!done) std::filesystem::remove_all(partial, ec);
    }
  } cleanup{frames_dir};
  write_frame(0);
  const double e0 = sim.kinetic_energy() + sim.potential_energy();
  std::vector<double> ms;
  int not_converged = 0, beyond_dt = 0;
  long iterations = 0;
  double max_probe = 0.0;
  for (int k = 1; k <= o.steps; ++k) {
    if (o.probe_node >= 0) {  // the probe ramps linearly to its offset or force over the run
      const double s = static_cast<double>(k) / o.steps;
      for (int a = 0; a < d; ++a)
        (probe.drive_position ? probe.offset : probe.force)(a) =
            s * (probe.drive_position ? o.probe_offset : o.probe_force)[static_cast<size_t>(a)];
      sim.set_probe(probe);
    }
    const auto t0 = std::chrono::steady_clock::now();
    const solve::StepReport r = sim.step(o.dt);
    ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (!sim.positions().allFinite() || !sim.velocities().allFinite())
      throw SolverFailure("step " + std::to_string(k) + " produced non-finite positions (" + o.integrator + ", dt " +
                          std::to_string(o.dt) + " s; explicit limit " + std::to_string(sim.stable_time_step()) +
                          " s)");
    not_converged += r.converged ? 0 : 1;
    iterations += r.iterations;
    beyond_dt += r.beyond_stable_dt ? 1 : 0;
    if (r.probe_force.size() > 0) max_probe = std::max(max_probe, r.probe_force.norm());
    if (k % every == 0 || k == o.steps) write_frame(k);
  }
  std::filesystem::remove_all(dir / "frames");
  std::filesystem::rename(frames_dir, dir / "frames");
  cleanup.done = true;
  io::write_pvd(dir / "simulation.pvd", frames);
  const double e1 = sim.kinetic_energy() + sim.potential_energy();
  std::printf("hooke simulate: %s, %d nodes, %s model, %s, dt %.3g s, %d steps (%.4g s)\n", o.in.mesh_path.c_str(),
              m.node_count(), o.method.c_str(), o.integrator.c_str(), o.dt, o.steps, sim.time());
  std::printf("  time      %.4g ms/step median, %.4g ms/step p95; %.3g solver iterations per step\n",
              percentile(ms, 0.5), percentile(ms, 0.95), static_cast<double>(iterations) / o.steps);
  std::printf("  energy    %.6g J at start, %.6g J at end (kinetic %.6g J)\n", e0, e1, sim.kinetic_energy());
  if (o.probe_node >= 0) std::printf("  probe     max force on the device %.6g N\n", max_probe);
  if (beyond_dt > 0)
    std::printf("  warning   %d steps beyond the explicit stability limit %.4g s\n", beyond_dt, sim.stable_time_step());
  if (not_converged > 0) std::printf("  warning   %d steps ended above the Newton tolerance\n", not_converged);
  std::printf("  wrote     %s (%zu frames)\n", (dir / "simulation.pvd").string().c_str(), frames.size());
  return 0;
}

}  // namespace

Action add_simulate_command(CLI::App& app) {
  auto o = std::make_shared<SimulateCli>();
  CLI::App* cmd = app.add_subcommand("simulate", "Simulate a calibrated spring model (or the FEM model) in time");
  add_model_input_options(cmd, o->in);
  cmd->add_option("--method", o->method,
                  "Calibration method, fem for the FEM model, or surface for Arnab & Raja's surface model (a closed "
                  "triangle surface)")
      ->capture_default_str();
  add_surface_options(cmd, o->surface);
  cmd->add_option("--influence-radius", o->influence_radius,
                  "surface: radius of influence of the probe's interaction weights (Eq. 4), m (default: half the "
                  "bounding-box diagonal)");
  cmd->add_option("--law", o->law, "FEM law with --method fem: linear, stvk, neohookean")->capture_default_str();
  cmd->add_option("--integrator", o->integrator,
                  "symplectic-euler, velocity-verlet, implicit-euler, local-global, quasi-static")
      ->capture_default_str();
  cmd->add_option("--linear-solver", o->linear_solver, "Newton steps: cholesky or cg")->capture_default_str();
  cmd->add_option("--global-solve", o->global_solve,
                  "local-global: direct (prefactored Cholesky) or chebyshev (Chebyshev-accelerated Jacobi)")
      ->capture_default_str();
  cmd->add_option("--iterations", o->iterations, "local-global: iterations per step")->capture_default_str();
  cmd->add_option("--dt", o->dt, "Time step, s")->capture_default_str();
  cmd->add_option("--steps", o->steps, "Number of steps")->capture_default_str();
  cmd->add_option("--density", o->density, "Density, kg/m^3")->capture_default_str();
  cmd->add_flag("--gravity", o->gravity, "Gravity 9.81 m/s^2 down the vertical axis (y in 2D, z in 3D)");
  cmd->add_option("--damping-mass", o->damping_mass, "Rayleigh alpha, 1/s")->capture_default_str();
  cmd->add_option("--damping-stiffness", o->damping_stiffness, "Rayleigh beta, s")->capture_default_str();
  cmd->add_flag("--free", o->free_body, "Do not clamp the bottom nodes");
  cmd->add_flag(
      "--no-reorder", o->no_reorder,
      "Simulate in the file's node order instead of reverse Cuthill-McKee (outputs are in file order either way)");
  cmd->add_option("--probe-node", o->probe_node, "Node grabbed by the probe");
  cmd->add_option("--probe-offset", o->probe_offset, "Drive the probe node by this offset (m), ramped over the run")
      ->delimiter(',');
  cmd->add_option("--probe-force", o->probe_force, "Push the probe node with this force (N), ramped over the run")
      ->delimiter(',');
  cmd->add_option("--every", o->every, "Write a frame every this many steps (default: about 100 frames)");
  cmd->add_option("-o,--output", o->out_dir, "Folder for simulation.pvd and frames/")->required();
  return [o] { return run_simulate(*o); };
}

}  // namespace hooke::cli
