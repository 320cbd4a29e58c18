#pragma once
// The viewer's --stats file: the physics' measured rates and step times, the drawing rate, the probe force, the FEM
// ghost's holding force and, with multirate haptics, the haptic loop's rates.
#include <hooke/interactive/physics_loop.hpp>
#include <string>

#include "view_state.hpp"

namespace hooke::viewer {

/// Frames drawn and the wall time they took.
struct DrawCounts {
  int frames = 0;           ///< frames drawn in all
  double timed_frames = 0;  ///< frames within whole measured seconds
  double seconds = 0.0;     ///< wall time of those, s
};

/// Writes the stats as JSON to `path` (interactive::write_stats: atomically). `haptics`: the haptic loop ran, its
/// figures are in state.haptic.
/// @throws IoError when the file cannot be written
void write_viewer_stats(const std::string& path, const interactive::Snapshot& snap, const ViewState& state,
                        const DrawCounts& draw, int node_count, int dim, bool haptics);

}  // namespace hooke::viewer
