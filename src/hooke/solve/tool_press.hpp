#pragma once
/// A rigid tool moved through a sequence of poses against a body, quasi-statically: at each pose the static
/// equilibrium of the body with the contact block (docs/contact.md). The force-depth curve of an indentation, and the
/// static reference a pressing instrument's dynamics settles on.
#include <hooke/contact/contact_block.hpp>
#include <hooke/model/problem.hpp>
#include <hooke/solve/simulator.hpp>
#include <hooke/solve/static_equilibrium.hpp>
#include <vector>

namespace hooke::solve {

struct ToolPressStep {
  contact::Pose pose;
  VecX positions;                  ///< the equilibrium, flat, m
  Vec3 tool_force = Vec3::Zero();  ///< the force the body exerts on the tool, N (ContactBlock::tool_force)
  int active = 0;                  ///< contact nodes within the activation distance
  double smallest_distance = 0.0;  ///< of a contact node to the tool, m (> 0: no node inside)
  SolveReport report;
};

/// Moves `tool` through `poses` in order; at each pose the nodes the tool has passed are pushed out to half the
/// activation distance (ContactBlock::push_out: an admissible start), then Newton from the last equilibrium. With
/// friction, each pose's slip is measured from the last equilibrium (ContactBlock::lag before the tool moves): the
/// block's slip distance is then per pose.
/// @param problem  the body with its supports and loads; its model holds `block`, whose tool is `tool`
/// @throws SolverFailure naming the pose when a step has no stable equilibrium (the steps before it are kept in the
///         exception's message only: make the poses finer); InvalidArgument when block's tool is not `tool`
std::vector<ToolPressStep> press_quasi_statically(const model::Problem& problem, const contact::ContactBlock& block,
                                                  contact::RigidTool& tool, const std::vector<contact::Pose>& poses,
                                                  const StaticOptions& options = {});

/// Moves `tool` to `pose` between two time steps of `sim` (whose model holds `block`, whose tool is `tool`): nodes the
/// tool has passed (it outran their gap) are put back outside it at half the activation distance, their velocities
/// kept, so that the next step starts from an admissible state. Returns how many nodes moved.
/// @throws InvalidArgument when block's tool is not `tool` or the pose is not finite or not a rotation
int move_tool(Simulator& sim, const contact::ContactBlock& block, contact::RigidTool& tool, const contact::Pose& pose);

}  // namespace hooke::solve
