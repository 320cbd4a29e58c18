#include <cstdio>
#include <hooke/core/error.hpp>
#include <hooke/solve/tool_press.hpp>
#include <string>

namespace hooke::solve {

std::vector<ToolPressStep> press_quasi_statically(const model::Problem& problem, const contact::ContactBlock& block,
                                                  contact::RigidTool& tool, const std::vector<contact::Pose>& poses,
                                                  const StaticOptions& options) {
  if (&block.tool() != &tool) throw InvalidArgument("press: the contact block does not hold this tool");
  std::vector<ToolPressStep> out;
  VecX x = model::initial_positions(problem);
  for (std::size_t k = 0; k < poses.size(); ++k) {
    block.lag(x);  // friction, if any, resists the slip from the last equilibrium to the next
    tool.set_pose(poses[k]);
    block.push_out(x, 0.5 * block.activation());
    StaticOptions o = options;
    o.start = x;
    StaticResult r = static_equilibrium(problem, o);
    if (r.report.status != SolveStatus::kConverged) {
      char where[160];
      std::snprintf(where, sizeof where,
                    "press: no stable equilibrium at pose %zu of %zu (tool at %.6g, %.6g, %.6g m): ", k + 1,
                    poses.size(), poses[k].position.x(), poses[k].position.y(), poses[k].position.z());
      throw SolverFailure(where + r.report.message);
    }
    x = r.positions;
    if (!(block.smallest_distance(x) > 0.0))  // never reported as an equilibrium (static_equilibrium refuses it too)
      throw SolverFailure("press: the equilibrium at pose " + std::to_string(k + 1) + " has a node inside the tool");
    ToolPressStep step;
    step.pose = poses[k];
    step.tool_force = block.tool_force(x);
    step.active = block.active_count(x);
    step.smallest_distance = block.smallest_distance(x);
    step.positions = x;
    step.report = std::move(r.report);
    out.push_back(std::move(step));
  }
  return out;
}

int move_tool(Simulator& sim, const contact::ContactBlock& block, contact::RigidTool& tool, const contact::Pose& pose) {
  if (&block.tool() != &tool) throw InvalidArgument("move_tool: the contact block does not hold this tool");
  tool.set_pose(pose);
  if (block.smallest_distance(sim.positions()) >= 0.5 * block.activation()) return 0;  // no copy of the state
  VecX x = sim.positions();
  const int pushed = block.push_out(x, 0.5 * block.activation());
  if (pushed > 0) sim.set_state(x, sim.velocities());
  return pushed;
}

}  // namespace hooke::solve
