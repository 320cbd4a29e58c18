#pragma once
// The colour of every node for the viewer's colour map (displacement, error against the FEM ghost, spring strain,
// Eq. 4 weights), with the colour bar's range.
#include <array>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/interactive/physics_loop.hpp>
#include <vector>

#include "view_state.hpp"

namespace hooke::viewer {

class ColourField {
 public:
  /// Per-node RGB of state.field on `snap` (rest: the rest positions, flat, m); sets state.colour_lo / colour_hi.
  /// The springs and blocks it needs are taken from `loop` once per model version, and evaluated outside its lock.
  std::vector<std::array<float, 3>> colours(interactive::PhysicsLoop& loop, const interactive::Snapshot& snap,
                                            const VecX& rest, int dim, ViewState& state);

 private:
  // The field's value per node and its range [lo, hi].
  VecX values(interactive::PhysicsLoop& loop, const interactive::Snapshot& snap, const VecX& rest, int dim,
              const ViewState& state, double& lo, double& hi);

  calibrate::SpringModel m_springs;
  long m_springs_version = -1;
  calibrate::BuiltModel m_built;  // the model's blocks, for the Eq. 4 weights
  long m_built_version = -1;
  VecX m_young;  // E per node, Pa
  long m_young_version = -1;
};

}  // namespace hooke::viewer
