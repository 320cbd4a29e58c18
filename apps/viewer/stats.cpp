#include "stats.hpp"

#include <utility>
#include <vector>

namespace hooke::viewer {

void write_viewer_stats(const std::string& path, const interactive::Snapshot& snap, const ViewState& state,
                        const DrawCounts& draw, int node_count, int dim, bool haptics) {
  const VecX f = snap.probe_force.size() > 0 ? snap.probe_force : VecX::Zero(dim);
  std::vector<std::pair<std::string, double>> extra{
      {"draw_rate_hz", draw.seconds > 0.0 ? draw.timed_frames / draw.seconds : state.draw_rate},
      {"frames", draw.frames},
      {"nodes", static_cast<double>(node_count)},
      {"grabbed_nodes", static_cast<double>(snap.grabbed.size())},
      {"probe_force_n", f.norm()},
      {"young_pa", snap.settings.material.youngs_modulus},
      {"poisson", snap.settings.material.poisson_ratio},
      {"dt_s", snap.settings.dynamics.dt}};
  for (int a = 0; a < dim; ++a) extra.emplace_back(std::string("probe_force_") + "xyz"[a], f(a));
  if (state.ghost_force.size() == dim) extra.emplace_back("fem_holding_force_n", state.ghost_force.norm());
  if (snap.tool) {  // the pressing tool after the last step
    const interactive::LiveTool& t = *snap.tool;
    extra.insert(extra.end(), {{"tool_force_n", t.force.norm()},
                               {"tool_force_x", t.force.x()},
                               {"tool_force_y", t.force.y()},
                               {"tool_force_z", t.force.z()},
                               {"tool_contact_nodes", static_cast<double>(t.active)},
                               {"tool_smallest_gap_m", t.smallest_gap},
                               {"tool_contact_distance_m", t.contact_distance},
                               {"tool_x", t.tool.pose().position.x()},
                               {"tool_y", t.tool.pose().position.y()},
                               {"tool_z", t.tool.pose().position.z()}});
  }
  if (haptics) {
    const interactive::HapticStats& h = state.haptic;
    extra.insert(extra.end(), {{"haptic_target_rate_hz", h.target_rate},
                               {"haptic_rate_hz", h.achieved_rate},
                               {"haptic_period_ms_median", h.period_ms_median},
                               {"haptic_period_ms_p99", h.period_ms_p99},
                               {"haptic_tick_ms_p99", h.tick_ms_p99},
                               {"haptic_ticks", static_cast<double>(h.ticks)},
                               {"deformation_models_per_s", h.model_rate},
                               {"haptic_force_n", state.haptic_force.size() > 0 ? state.haptic_force.norm() : 0.0}});
  }
  interactive::write_stats(path, snap.stats, extra);
}

}  // namespace hooke::viewer
