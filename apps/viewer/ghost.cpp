#include "ghost.hpp"

namespace hooke::viewer {

void GhostSolver::solve(interactive::PhysicsLoop& loop, const interactive::Snapshot& snap, ViewState& state, bool now) {
  if (state.ghost == Ghost::kOff) return;
  calibrate::CalibratedModel model;
  std::vector<int> clamped;
  bool gravity = false;
  loop.with([&](const interactive::LiveSimulation& sim) {
    model = sim.model();
    clamped = sim.clamped_nodes();
    gravity = sim.settings().dynamics.gravity;
  });
  const int dim = model.mesh.dim();
  const std::vector<int> grabbed = snap.grabbed;
  VecX targets = snap.grab_positions;
  for (size_t k = 0; k < grabbed.size(); ++k)
    targets.segment(dim * static_cast<Eigen::Index>(k), dim) += snap.probe_offset;
  const material::Law law = state.ghost == Ghost::kLinear ? material::Law::kLinear : material::Law::kStVK;
  auto job = [model = std::move(model), clamped, grabbed, targets, gravity, law] {
    return interactive::fem_probe_equilibrium(model, law, clamped, grabbed, targets, gravity);
  };
  state.ghost_message = "solving ...";
  if (now) {
    m_job.run_now(job);
  } else {
    m_job.submit(std::move(job));  // an older solve still running is left to finish: its result is dropped
  }
  poll(state);
}

void GhostSolver::poll(ViewState& state) {
  try {
    std::optional<interactive::ProbeEquilibrium> r = m_job.take();
    if (!r) return;
    state.ghost_positions = std::move(r->positions);
    state.ghost_force = std::move(r->holding_force);
    state.ghost_message = r->message;
  } catch (const std::exception& e) {
    state.ghost_positions.reset();
    state.ghost_force.resize(0);
    state.ghost_message = e.what();
  }
}

}  // namespace hooke::viewer
