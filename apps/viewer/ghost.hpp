#pragma once
// The FEM ghost: the static solution of the FEM (linear or StVK) under the probe's current displacement, drawn as a
// wireframe over the model and behind the error colour map.
#include <hooke/interactive/latest_job.hpp>
#include <hooke/interactive/live_simulation.hpp>
#include <hooke/interactive/physics_loop.hpp>

#include "view_state.hpp"

namespace hooke::viewer {

class GhostSolver {
 public:
  /// Solves the ghost state.ghost asks for (nothing for Ghost::kOff) under `snap`'s probe: now (scripted runs: the
  /// physics waits for it) or in the background (interactive: the window stays live; poll picks it up).
  void solve(interactive::PhysicsLoop& loop, const interactive::Snapshot& snap, ViewState& state, bool now);
  /// Moves the newest finished solve into state (its positions, holding force and message; an error's message).
  void poll(ViewState& state);

 private:
  interactive::LatestJob<interactive::ProbeEquilibrium> m_job;
};

}  // namespace hooke::viewer
