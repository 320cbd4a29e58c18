#include "panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <hooke/calibrate/model_factory.hpp>
#include <hooke/calibrate/model_settings.hpp>
#include <hooke/core/error.hpp>
#include <hooke/interactive/picking.hpp>
#include <string>
#include <vector>

namespace hooke::viewer {
namespace {

// A combo box over names; returns true when the choice changed.
bool combo(const char* label, std::string& current, const std::vector<std::string>& names) {
  bool changed = false;
  if (ImGui::BeginCombo(label, current.c_str())) {
    for (const std::string& n : names)
      if (ImGui::Selectable(n.c_str(), n == current)) {
        changed = n != current;
        current = n;
      }
    ImGui::EndCombo();
  }
  return changed;
}

// One control per live model setting but the method (above, with "file"), generated from its declaration
// (interactive::live_model_settings): a combo for a choice, an input for a number or integer, a checkbox for a flag.
// The library checks each value (range, names); a refused one is shown under the controls. Returns true when one
// changed.
bool model_settings(calibrate::ModelOptions& model, std::string& error) {
  const auto rows = calibrate::model_settings();
  bool changed = false;
  for (const settings::Description& d : interactive::live_model_settings()) {
    if (d.name == "method") continue;
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.name == d.name; });
    std::string text = row->get(model), label = d.name + (d.unit.empty() ? "" : " (" + d.unit + ")");
    bool edited = false;
    switch (d.type) {
      case settings::Type::kChoice: edited = combo(label.c_str(), text, d.choices); break;
      case settings::Type::kFlag: {
        bool on = text == "on";
        if ((edited = ImGui::Checkbox(label.c_str(), &on))) text = on ? "on" : "off";
        break;
      }
      case settings::Type::kInteger: {
        int v = settings::parse_integer(d.name, text);
        if ((edited = ImGui::InputInt(label.c_str(), &v, 1, 1, ImGuiInputTextFlags_EnterReturnsTrue)))
          text = std::to_string(v);
        break;
      }
      case settings::Type::kNumber:
      case settings::Type::kText: {
        char buffer[64];
        std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
        if ((edited = ImGui::InputText(label.c_str(), buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue)))
          text = buffer;
        break;
      }
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", d.long_help().c_str());
    if (!edited) continue;
    try {
      settings::set(rows, model, d.name, text);
      error.clear();
      changed = true;
    } catch (const Error& e) {
      error = e.what();
    }
  }
  if (!error.empty()) ImGui::TextWrapped("%s", error.c_str());
  return changed;
}

void rates(const interactive::PhysicsStats& s, double draw_rate, const interactive::HapticStats& h) {
  if (h.target_rate > 0.0) {  // multirate: the haptic loop and the deformation at their own rates
    ImGui::Text("haptics %.0f Hz (target %.0f), period p99 %.2f ms, tick p99 %.3f ms%s", h.achieved_rate, h.target_rate,
                h.period_ms_p99, h.tick_ms_p99, h.realtime_priority ? ", real-time priority" : "");
    ImGui::Text("deformation %.1f models/s", h.model_rate);
  }
  ImGui::Text("%s %.0f steps/s (target %.0f), draw %.0f fps", h.target_rate > 0.0 ? "deformation" : "physics",
              s.achieved_rate, s.target_rate, draw_rate);
  ImGui::Text("step %.3f ms median, %.3f ms p99; %ld steps, t = %.3f s", s.step_ms_median, s.step_ms_p99, s.steps,
              s.sim_time);
  if (s.behind)
    ImGui::TextColored(ImVec4(0.85f, 0.1f, 0.1f, 1.0f),
                       "behind real time: %.0f of %.0f steps/s (%ld steps longer than dt)", s.achieved_rate,
                       s.target_rate, s.overruns);
  if (s.paused) ImGui::TextColored(ImVec4(0.1f, 0.3f, 0.8f, 1.0f), "paused (Space)");
  // The whole run beside the last second's rate: a run can keep the rate now and have lost time to a stall.
  if (s.steps > 0)
    ImGui::Text("run: %.2f s simulated in %.2f s (%.0f %% of real time); %d of %ld steps (%.1f %%) above tolerance",
                s.sim_time, s.wall_time, 100.0 * interactive::real_time_fraction(s), s.not_converged, s.steps,
                100.0 * interactive::fraction_above_tolerance(s));
  if (!s.error.empty()) ImGui::TextColored(ImVec4(0.85f, 0.1f, 0.1f, 1.0f), "%s", s.error.c_str());
}

void probe(ViewState& state, const interactive::Snapshot& snap) {
  const double f = snap.probe_force.size() > 0 ? snap.probe_force.norm() : 0.0;
  if (snap.grabbed.empty() && state.press_mode)
    ImGui::Text("press: left-drag on the surface to press the sphere into it");
  else if (snap.grabbed.empty())
    ImGui::Text("probe: left-drag on the surface to grab");
  else
    ImGui::Text("probe: %zu node(s), |F| = %.4g N, offset %.3g mm", snap.grabbed.size(), f,
                1e3 * snap.probe_offset.norm());
  std::vector<float> values;
  for (const auto& [t, v] : state.force_history) values.push_back(v);
  if (!values.empty())
    ImGui::PlotLines(snap.tool ? "|F| tool (N), 5 s" : "|F| (N), 5 s", values.data(), static_cast<int>(values.size()),
                     0, nullptr, 0.0f, FLT_MAX, ImVec2(0, 60));
  float radius_mm = static_cast<float>(1e3 * state.grab_radius);
  if (ImGui::SliderFloat("grab radius (mm)", &radius_mm, 0.0f, 20.0f)) state.grab_radius = 1e-3 * radius_mm;
}

// The mouse's mode and the pressing tool: its shape, where it is, the force the body exerts on it.
void tool(ViewState& state, const interactive::Snapshot& snap) {
  int mode = state.press_mode ? 1 : 0;
  ImGui::Text("left mouse (T):");
  ImGui::SameLine();
  ImGui::RadioButton("grab", &mode, 0);
  ImGui::SameLine();
  ImGui::RadioButton("press", &mode, 1);
  state.press_mode = mode == 1;
  if (state.press_mode) {
    float radius_mm = static_cast<float>(1e3 * state.tool_radius), mu = static_cast<float>(state.tool_friction);
    if (ImGui::SliderFloat("sphere radius (mm, 0: auto)", &radius_mm, 0.0f, 20.0f))
      state.tool_radius = 1e-3 * radius_mm;
    if (ImGui::SliderFloat("friction mu", &mu, 0.0f, 1.0f)) state.tool_friction = mu;
  }
  if (!snap.tool) return;
  const interactive::LiveTool& t = *snap.tool;
  const Vec3& c = t.tool.pose().position;
  ImGui::Text("tool %s at %.4g, %.4g, %.4g mm", t.tool.description().c_str(), 1e3 * c.x(), 1e3 * c.y(), 1e3 * c.z());
  ImGui::Text("contact force %.4g N (%.3g, %.3g, %.3g); %d nodes in contact", t.force.norm(), t.force.x(), t.force.y(),
              t.force.z(), t.active);
  ImGui::Text("smallest gap %.3g um (contact distance %.3g um)", 1e6 * t.smallest_gap, 1e6 * t.contact_distance);
}

}  // namespace

PanelRequests draw_panel(ViewState& state, const interactive::Snapshot& snap, int node_count) {
  PanelRequests r;
  ImGui::SetNextWindowPos(ImVec2(8, 8), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowSize(ImVec2(kPanelWidth, 0), ImGuiCond_FirstUseEver);
  ImGui::Begin("hooke");
  ImGui::Text("%s model, %d nodes", snap.settings.model.method.c_str(), node_count);
  rates(snap.stats, state.draw_rate, state.haptic);
  ImGui::Separator();
  probe(state, snap);
  tool(state, snap);
  ImGui::Separator();

  interactive::LiveSettings& e = state.edit;
  // A model whose constants hooke cannot remake ("file": a hand-tuned model file) keeps its material.
  const bool fixed_material = calibrate::model_kind_of_method(e.model.method) == calibrate::ModelKind::kFile;
  if (fixed_material)
    ImGui::TextWrapped("This model's constants are its own: E and nu are fixed (choose a method to recalibrate).");
  ImGui::BeginDisabled(fixed_material);
  // With regions (docs/regions.md) the sliders edit the chosen tissue: a listed region, or the regions not listed.
  if (state.tissue >= static_cast<int>(e.model.regions.size())) state.tissue = -1;
  if (!e.model.regions.empty()) {
    std::vector<std::string> tissues{"other regions"};
    for (const calibrate::RegionMaterial& t : e.model.regions) tissues.push_back("region " + std::to_string(t.region));
    std::string chosen = tissues[static_cast<std::size_t>(state.tissue + 1)];
    if (combo("tissue", chosen, tissues))
      state.tissue = static_cast<int>(std::find(tissues.begin(), tissues.end(), chosen) - tissues.begin()) - 1;
  }
  double& young = state.tissue < 0 ? e.material.youngs_modulus
                                   : e.model.regions[static_cast<std::size_t>(state.tissue)].youngs_modulus;
  double& poisson = state.tissue < 0 ? e.material.poisson_ratio
                                     : e.model.regions[static_cast<std::size_t>(state.tissue)].poisson_ratio;
  float log_e = static_cast<float>(std::log10(young));
  ImGui::SliderFloat("log10 E (Pa)", &log_e, 2.0f, 9.0f, "%.2f");
  if (ImGui::IsItemEdited()) young = std::pow(10.0, static_cast<double>(log_e));
  r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SameLine();
  ImGui::Text("%.3g", young);
  float nu = static_cast<float>(poisson);
  ImGui::SliderFloat("Poisson nu", &nu, -0.2f, 0.499f, "%.3f");
  if (ImGui::IsItemEdited()) poisson = nu;
  r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::EndDisabled();
  std::vector<std::string> methods = calibrate::model_method_names();
  methods.insert(methods.begin(), std::string(calibrate::model_kind_name(calibrate::ModelKind::kFile)));
  r.apply_settings |= combo("method", e.model.method, methods);
  r.apply_settings |= model_settings(e.model, state.setting_error);
  std::string integrator(solve::integrator_name(e.simulator.integrator));
  std::vector<std::string> integrators;
  for (const std::string_view name : solve::integrator_names()) integrators.emplace_back(name);
  if (combo("integrator", integrator, integrators)) {
    e.simulator.integrator = solve::integrator_from_name(integrator);
    r.apply_settings = true;
  }
  if (e.simulator.integrator == solve::Integrator::kLocalGlobal) {
    std::string global(solve::global_solve_name(e.simulator.global_solve));
    if (combo("global solve", global, {"direct", "chebyshev"})) {
      e.simulator.global_solve = solve::global_solve_from_name(global);
      r.apply_settings = true;
    }
    if (e.simulator.global_solve == solve::GlobalSolve::kChebyshev)  // its accuracy beside its speed
      ImGui::TextWrapped(
          "chebyshev: measured 1.6e-3 of the largest displacement off a converged step on 1 089 nodes and "
          "2.6e-2 on 11 425 (300 steps; `hooke bench` measures it on other meshes)");
    int iterations = e.simulator.local_global_iterations;
    if (ImGui::SliderInt("iterations", &iterations, 1, 30)) e.simulator.local_global_iterations = iterations;
    r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  }
  if (e.simulator.integrator == solve::Integrator::kQuasiNewton) {
    int iterations = e.simulator.quasi_newton.max_iterations;
    if (ImGui::SliderInt("max iterations", &iterations, 1, 30)) e.simulator.quasi_newton.max_iterations = iterations;
    r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  }
  float dt_ms = static_cast<float>(1e3 * e.dynamics.dt);
  if (ImGui::InputFloat("dt (ms)", &dt_ms, 0.1f, 1.0f, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue) && dt_ms > 0.0f) {
    e.dynamics.dt = 1e-3 * dt_ms;
    r.apply_settings = true;
  }
  float alpha = static_cast<float>(e.dynamics.damping_mass),
        beta = static_cast<float>(1e3 * e.dynamics.damping_stiffness);
  ImGui::SliderFloat("damping alpha (1/s)", &alpha, 0.0f, 50.0f);
  if (ImGui::IsItemEdited()) e.dynamics.damping_mass = alpha;
  r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  ImGui::SliderFloat("damping beta (ms)", &beta, 0.0f, 10.0f);
  if (ImGui::IsItemEdited()) e.dynamics.damping_stiffness = 1e-3 * beta;
  r.apply_settings |= ImGui::IsItemDeactivatedAfterEdit();
  r.apply_settings |= ImGui::Checkbox("gravity", &e.dynamics.gravity);
  ImGui::Separator();

  std::string field = interactive::color_field_name(state.field);
  if (combo("colour", field, {"none", "displacement", "error", "strain", "weights", "young"}))
    state.field = interactive::color_field_from_name(field);
  std::string ghost = state.ghost == Ghost::kOff ? "off" : state.ghost == Ghost::kLinear ? "linear" : "stvk";
  if (combo("FEM ghost", ghost, {"off", "linear", "stvk"})) {
    state.ghost = ghost == "off" ? Ghost::kOff : ghost == "linear" ? Ghost::kLinear : Ghost::kStVK;
    r.solve_ghost = state.ghost != Ghost::kOff;
  }
  if (state.ghost != Ghost::kOff) {
    ImGui::SameLine();
    r.solve_ghost |= ImGui::Button("solve");
    if (!state.ghost_message.empty()) ImGui::TextWrapped("FEM: %s", state.ghost_message.c_str());
    if (state.ghost_force.size() > 0) ImGui::Text("FEM holding force %.4g N", state.ghost_force.norm());
  }
  ImGui::Separator();
  r.toggle_pause = ImGui::Button(state.paused ? "resume (Space)" : "pause (Space)");
  ImGui::SameLine();
  r.reset = ImGui::Button("reset (R)");
  ImGui::TextDisabled("left-drag: grab or press (T)  right-drag: orbit  middle-drag: pan  wheel: zoom");
  ImGui::End();
  return r;
}

void draw_overlays(const ViewState& state, const interactive::Snapshot& snap, const Camera& camera, int width,
                   int height, int dim, double scene_size) {
  ImDrawList* draw = ImGui::GetForegroundDrawList();
  // The reaction force: an arrow from the grabbed nodes' driven position, a fifth of the scene per largest force seen.
  if (!snap.grabbed.empty() && snap.probe_force.size() == dim) {
    const Vec3 at =
        interactive::positions_3d(snap.grab_positions.head(dim) + snap.probe_offset, dim).row(0).transpose();
    float largest = 1e-12f;
    for (const auto& [t, v] : state.force_history) largest = std::max(largest, v);
    const Vec3 f = interactive::positions_3d(snap.probe_force, dim).row(0).transpose();
    const Vec3 tip = at + (0.2 * scene_size / largest) * f;
    Eigen::Vector2d a, b;
    if (camera.project(at, width, height, a) && camera.project(tip, width, height, b)) {
      const ImU32 red = IM_COL32(220, 30, 30, 255);
      draw->AddLine(ImVec2(static_cast<float>(a(0)), static_cast<float>(a(1))),
                    ImVec2(static_cast<float>(b(0)), static_cast<float>(b(1))), red, 3.0f);
      const Eigen::Vector2d d = (b - a).norm() > 1e-9 ? Eigen::Vector2d((b - a).normalized()) : Eigen::Vector2d(0, -1);
      const Eigen::Vector2d n(-d(1), d(0)), l = b - 12.0 * d + 6.0 * n, rr = b - 12.0 * d - 6.0 * n;
      draw->AddTriangleFilled(ImVec2(static_cast<float>(b(0)), static_cast<float>(b(1))),
                              ImVec2(static_cast<float>(l(0)), static_cast<float>(l(1))),
                              ImVec2(static_cast<float>(rr(0)), static_cast<float>(rr(1))), red);
      draw->AddCircleFilled(ImVec2(static_cast<float>(a(0)), static_cast<float>(a(1))), 4.0f, IM_COL32(0, 0, 0, 255));
      char label[64];
      std::snprintf(label, sizeof(label), "%.3g N", snap.probe_force.norm());
      draw->AddText(ImVec2(static_cast<float>(b(0)) + 6.0f, static_cast<float>(b(1))), red, label);
    }
  }
  // The colour bar: bottom right, 20 steps of the map, the range and the unit.
  if (state.field != interactive::ColorField::kNone) {
    const float x0 = static_cast<float>(width) - 60.0f, y0 = static_cast<float>(height) - 260.0f, h = 200.0f;
    for (int k = 0; k < 20; ++k) {
      const auto c0 = interactive::colormap(1.0 - k / 20.0), c1 = interactive::colormap(1.0 - (k + 1) / 20.0);
      auto col = [](const std::array<float, 3>& c) {
        return IM_COL32(static_cast<int>(255 * c[0]), static_cast<int>(255 * c[1]), static_cast<int>(255 * c[2]), 255);
      };
      draw->AddRectFilledMultiColor(ImVec2(x0, y0 + h * k / 20.0f), ImVec2(x0 + 20.0f, y0 + h * (k + 1) / 20.0f),
                                    col(c0), col(c0), col(c1), col(c1));
    }
    std::string unit = interactive::color_field_unit(state.field);
    if (unit == "1") unit.clear();  // dimensionless: the number alone
    char hi[64], lo[64];
    std::snprintf(hi, sizeof(hi), "%.3g %s", state.colour_hi, unit.c_str());
    std::snprintf(lo, sizeof(lo), "%.3g %s", state.colour_lo, unit.c_str());
    const ImU32 black = IM_COL32(0, 0, 0, 255);
    draw->AddText(ImVec2(x0 - 40.0f, y0 - 36.0f), black, interactive::color_field_name(state.field).c_str());
    draw->AddText(ImVec2(x0 - 40.0f, y0 - 18.0f), black, hi);
    draw->AddText(ImVec2(x0 - 40.0f, y0 + h + 4.0f), black, lo);
  }
}

}  // namespace hooke::viewer
