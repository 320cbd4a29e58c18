#pragma once
// The viewer's Dear ImGui panel (rates, probe force and its plot, material, method, integrator, colour map, FEM
// ghost) and the overlays drawn over the scene (the force arrow, the colour bar).
#include <hooke/interactive/physics_loop.hpp>

#include "camera.hpp"
#include "view_state.hpp"

namespace hooke::viewer {

inline constexpr float kPanelWidth = 440.0f;  ///< pixels, at the left edge

/// Draws the panel for `snapshot` and returns what the user changed. `state.edit` is edited in place.
PanelRequests draw_panel(ViewState& state, const interactive::Snapshot& snapshot, int node_count);

/// The reaction force as an arrow from the grabbed point (scaled to a fifth of the view), the probe's target, and
/// the colour bar with its range and unit.
void draw_overlays(const ViewState& state, const interactive::Snapshot& snapshot, const Camera& camera, int width,
                   int height, int dim, double scene_size);

}  // namespace hooke::viewer
