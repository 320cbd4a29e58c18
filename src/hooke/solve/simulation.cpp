#include <algorithm>
#include <chrono>
#include <cmath>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/contact/contact_block.hpp>
#include <hooke/core/error.hpp>
#include <hooke/mesh/measure.hpp>
#include <hooke/mesh/reorder.hpp>
#include <hooke/model/load_case.hpp>
#include <hooke/solve/simulation.hpp>
#include <hooke/solve/tool_press.hpp>
#include <limits>
#include <numeric>
#include <string>

namespace hooke::solve {
namespace {

void check_options(const SimulationOptions& o, int dim, int nodes) {
  validate(o.dynamics);
  if (o.steps < 1) throw InvalidArgument("the number of steps must be at least 1");
  if (o.tool && o.tool_path.empty()) throw InvalidArgument("a tool needs a path (its pose over time)");
  if (o.tool && dim != 3) throw InvalidArgument("a tool presses 3D bodies only");
  if (!(o.friction >= 0.0 && std::isfinite(o.friction)))
    throw InvalidArgument("the friction coefficient must be a finite number >= 0, not " + std::to_string(o.friction));
  if (!(o.creep_velocity >= 0.0 && std::isfinite(o.creep_velocity)))
    throw InvalidArgument("the creep velocity must be a finite number >= 0 m/s, not " +
                          std::to_string(o.creep_velocity));
  if (o.probe_node < 0) return;
  const bool drive = o.probe_offset.size() > 0, push = o.probe_force.size() > 0;
  const VecX& v = drive ? o.probe_offset : o.probe_force;
  if (drive == push || v.size() != dim)
    throw InvalidArgument("a probe needs exactly one of an offset and a force, with " + std::to_string(dim) +
                          " components");
  if (!v.allFinite()) throw InvalidArgument("the probe's offset or force is not finite");
  if (o.probe_node >= nodes)
    throw InvalidArgument("probe node " + std::to_string(o.probe_node) + " is not a node of the model (it has " +
                          std::to_string(nodes) + ")");
}

[[noreturn]] void fail_step(const char* what, int k, const SimulationOptions& o, double limit) {
  throw SolverFailure("step " + std::to_string(k) + " " + what + " (" +
                      std::string(integrator_name(o.simulator.integrator)) + ", dt " + std::to_string(o.dynamics.dt) +
                      " s; explicit stability limit " + std::to_string(limit) +
                      " s): use a smaller dt or an implicit integrator");
}

}  // namespace

SimulationSummary simulate(const calibrate::CalibratedModel& file_model, const SimulationOptions& o,
                           const FrameSink& frames) {
  const int d = file_model.mesh.dim(), n = file_model.mesh.node_count();
  check_options(o, d, n);
  // Reverse Cuthill-McKee order for cache locality (same trajectory: tests/solve/test_simulator.cpp); frames and
  // the probe node stay in the model's numbering.
  std::vector<int> new_to_old(static_cast<size_t>(n));
  std::iota(new_to_old.begin(), new_to_old.end(), 0);
  if (o.reorder && file_model.mesh.element_count() > 0) new_to_old = mesh::rcm_order(file_model.mesh);
  const calibrate::CalibratedModel cm = calibrate::permute_nodes(file_model, new_to_old);
  std::vector<int> old_to_new(new_to_old.size());
  for (size_t k = 0; k < new_to_old.size(); ++k) old_to_new[static_cast<size_t>(new_to_old[k])] = static_cast<int>(k);
  VecX out_u(d * n), out_v(d * n);
  const calibrate::BuiltModel built = calibrate::build_model(cm);
  const VecX& rest = built.model->rest_positions();
  const double creep =
      o.creep_velocity > 0.0 ? o.creep_velocity : contact::default_creep_velocity(mesh::bounding_box_diagonal(cm.mesh));
  const contact::Friction friction{o.friction, creep * o.dynamics.dt};
  const contact::ContactBlock* contact = nullptr;
  if (o.tool) {  // the barrier against the tool joins the model's terms (docs/contact.md)
    o.tool->set_pose(o.tool_path.at(0.0));
    auto block = contact::boundary_contact(cm.mesh, cm.material.youngs_modulus, o.tool, o.contact_distance);
    block->set_friction(friction);
    contact = block.get();
    built.model->add(std::move(block));
  }

  std::vector<const contact::ContactBlock*> floors;  // the obstacles' contact blocks
  for (const contact::RigidTool& obstacle : o.obstacles) {
    auto block = contact::boundary_contact(cm.mesh, cm.material.youngs_modulus,
                                           std::make_shared<contact::RigidTool>(obstacle), o.contact_distance);
    if (!(block->smallest_distance(rest) > 0.0))
      throw InvalidArgument("the body starts inside the obstacle " + obstacle.description() + " at " +
                            std::to_string(obstacle.pose().position.x()) + ", " +
                            std::to_string(obstacle.pose().position.y()) + ", " +
                            std::to_string(obstacle.pose().position.z()) + " m");
    block->set_friction(friction);
    floors.push_back(block.get());
    built.model->add(std::move(block));
  }
  model::Problem problem = model::make_problem(built.model);
  if (o.clamp_bottom && !cm.surface)
    model::fix_nodes(problem,
                     model::make_load_case(cm.mesh, model::LoadKind::kStretch, 0.0, cm.material.thickness).fixed_nodes);
  Simulator sim(problem, make_dynamics(o.dynamics, cm.masses, d), o.simulator);
  Probe probe;
  if (o.probe_node >= 0) {
    probe.nodes = {old_to_new[static_cast<size_t>(o.probe_node)]};
    probe.drive_position = o.probe_offset.size() > 0;
    probe.offset = probe.force = VecX::Zero(d);
    sim.set_probe(probe);
    if (built.volume_penalty) {  // the weights of Eq. 4 follow the probe (Arnab & Raja, Fig. 11)
      const double radius = influence_radius(o.dynamics, mesh::bounding_box_diagonal(cm.mesh));
      const VecX& v = probe.drive_position ? o.probe_offset : o.probe_force;
      if (v.norm() > 0.0) {
        sim.problem().interaction = model::Interaction{cm.mesh.nodes.row(probe.nodes[0]).transpose(), Vec3(v), radius};
        model::require_valid(*sim.problem().interaction);
      }
    }
  }
  SimulationSummary s;
  s.stable_time_step = sim.stable_time_step();
  if (o.friction > 0.0) s.creep_velocity = creep;

  // Before a step the tool moves; nodes it has passed (it outran their gap) are put back outside it, so the step
  // starts from an admissible state.
  auto place_tool = [&](double t) { s.pushed_nodes += solve::move_tool(sim, *contact, *o.tool, o.tool_path.at(t)); };
  if (contact) {
    s.contact_distance = contact->activation();
    s.smallest_gap = std::numeric_limits<double>::infinity();
    place_tool(0.0);
  }
  auto emit = [&](int k) {
    if (!std::isfinite(sim.potential_energy()))
      fail_step(
          contact || !floors.empty() ? "inverted an element or entered a tool or obstacle" : "inverted an element", k,
          o, s.stable_time_step);
    for (int i = 0; i < n; ++i) {
      const int j = old_to_new[static_cast<size_t>(i)];
      out_u.segment(d * i, d) = sim.positions().segment(d * j, d) - rest.segment(d * j, d);
      out_v.segment(d * i, d) = sim.velocities().segment(d * j, d);
    }
    frames(k, sim.time(), out_u, out_v);
  };
  const int every = o.every > 0 ? o.every : std::max(1, o.steps / 100);
  emit(0);
  s.energy_start = sim.kinetic_energy() + sim.potential_energy();
  s.step_ms.reserve(static_cast<size_t>(o.steps));
  for (int k = 1; k <= o.steps; ++k) {
    if (o.probe_node >= 0) {  // the probe ramps linearly to its offset or force over the run
      const double ramp = static_cast<double>(k) / o.steps;
      (probe.drive_position ? probe.offset : probe.force) =
          ramp * (probe.drive_position ? o.probe_offset : o.probe_force);
      sim.set_probe(probe);
    }
    if (contact) place_tool(k * o.dynamics.dt);
    const auto t0 = std::chrono::steady_clock::now();
    const StepReport r = sim.step(o.dynamics.dt);
    s.step_ms.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
    if (!sim.positions().allFinite() || !sim.velocities().allFinite())
      fail_step("produced non-finite positions", k, o, s.stable_time_step);
    if (!r.converged && !o.allow_unconverged)
      throw SolverFailure("step " + std::to_string(k) + " ended above the Newton tolerance (residual " +
                          std::to_string(r.residual) + " N after " + std::to_string(r.iterations) + " iterations, " +
                          std::string(integrator_name(o.simulator.integrator)) +
                          "): use a smaller dt, more Newton iterations, or allow unconverged steps");
    s.not_converged += r.converged ? 0 : 1;
    s.iterations += r.iterations;
    s.beyond_stable_dt += r.beyond_stable_dt ? 1 : 0;
    s.obstacle_gap.resize(floors.size(), std::numeric_limits<double>::infinity());
    for (std::size_t f = 0; f < floors.size(); ++f)
      s.obstacle_gap[f] = std::min(s.obstacle_gap[f], floors[f]->smallest_distance(sim.positions()));
    if (contact) {
      const Vec3 f = contact->tool_force(sim.positions());
      s.tool_force.push_back({sim.time(), f.x(), f.y(), f.z()});
      s.smallest_gap = std::min(s.smallest_gap, contact->smallest_distance(sim.positions()));
    }
    if (r.probe_force.size() > 0) s.max_probe_force = std::max(s.max_probe_force, r.probe_force.norm());
    if (k % every == 0 || k == o.steps) emit(k);
  }
  for (const contact::ContactBlock* floor : floors) {
    const Vec3 f = floor->tool_force(sim.positions());
    s.obstacle_force.push_back({f.x(), f.y(), f.z()});
  }
  s.energy_end = sim.kinetic_energy() + sim.potential_energy();
  s.kinetic_end = sim.kinetic_energy();
  s.time = sim.time();
  return s;
}

}  // namespace hooke::solve
