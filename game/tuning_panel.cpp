#include "tuning_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace game {

namespace {

// A logarithmic slider over [min, max] that shows the value in scientific notation. (ImGui's own
// logarithmic flag derives its zero epsilon from the format's precision, which "%e" breaks, so the
// slider moves the exponent instead.)
bool log_slider(const char* label, double& value, double min, double max, const char* tip) {
  double exponent = std::log10(std::clamp(value, min, max));
  const double lo = std::log10(min), hi = std::log10(max);
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", value);  // no '%' left: ImGui shows it as it is
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &exponent, &lo, &hi, text,
                                           ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  if (changed) value = std::pow(10.0, exponent);
  return changed;
}

bool slider(const char* label, double& value, double min, double max, const char* format, const char* tip,
            ImGuiSliderFlags flags = 0) {
  const double before = value;
  const bool changed =
      ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format, flags | ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  // Ctrl+click lets the player type a value; ImGui reads "nan" and "inf" with %lf, and clamping
  // lets NaN through (every comparison with it is false): such text leaves the value as it was.
  if (changed && !std::isfinite(value)) {
    value = before;
    return false;
  }
  return changed;
}

bool int_slider(const char* label, double& value, int min, int max, const char* tip) {
  int v = static_cast<int>(value);
  const bool changed = ImGui::SliderInt(label, &v, min, max, "%d", ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  value = v;
  return changed;
}

}  // namespace

std::vector<TuneEvent> draw_tuning_panel(const Tuning& current, const Tuning& level_defaults, DebugOptions& debug,
                                         bool* open) {
  Tuning t = current;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x - 10.0f, 10.0f}, ImGuiCond_Appearing, {1.0f, 0.0f});
  ImGui::SetNextWindowSize({430, 0}, ImGuiCond_Appearing);
  if (ImGui::Begin("Tuning (F2)", open, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::PushItemWidth(230);
    ImGui::TextDisabled("Applies live to every tire in the world.");
    if (ImGui::CollapsingHeader("Compliance (inverse stiffness)", ImGuiTreeNodeFlags_DefaultOpen)) {
      log_slider("outer ring", t.compliance_outer, 1e-9, 1e-1, "tread segments (m/N): larger is softer");
      log_slider("inner ring", t.compliance_inner, 1e-9, 1e-1, "rim segments (m/N)");
      log_slider("spokes", t.compliance_spoke, 1e-9, 1e-1, "sidewall spokes (m/N)");
      log_slider("pressure##c", t.compliance_pressure, 1e-8, 1e0, "the air (m^4/J): larger lets the area change more");
    }
    if (ImGui::CollapsingHeader("Tire", ImGuiTreeNodeFlags_DefaultOpen)) {
      slider("pressure", t.pressure, 0.1, 4.0, "%.2f", "target area / rest area: above 1 inflates");
      slider("mass scale", t.mass_scale, 0.1, 10.0, "%.2f x", "each tire's mass times this", ImGuiSliderFlags_Logarithmic);
      slider("friction", t.friction, 0.0, 3.0, "%.2f", "static and kinetic friction coefficient");
      log_slider("material damping", t.material_damping, 1e-5, 1.0, "Kelvin-Voigt damping time (s)");
    }
    if (ImGui::CollapsingHeader("World and solver", ImGuiTreeNodeFlags_DefaultOpen)) {
      slider("gravity x", t.gravity_x, -30.0, 30.0, "%.2f m/s2", "horizontal gravity");
      slider("gravity y", t.gravity_y, -30.0, 30.0, "%.2f m/s2", "vertical gravity (-9.81 is Earth)");
      slider("damping", t.solver_damping, 0.0, 100.0, "%.2f 1/s", "solver.damping: decay rate of non-rigid motion",
             ImGuiSliderFlags_Logarithmic);
      int_slider("substeps", t.substeps, 1, 256, "solver.substeps: the most effective accuracy knob");
      int_slider("iterations", t.iterations, 1, 64, "solver.iterations: constraint sweeps per substep");
    }
    if (ImGui::Button("Reset to the level's values")) t = level_defaults;
    ImGui::PopItemWidth();
    if (ImGui::CollapsingHeader("Debug drawing", ImGuiTreeNodeFlags_DefaultOpen)) {
      ImGui::Checkbox("debug drawing on (F3)", &debug.enabled);
      ImGui::Checkbox("inner ring and spokes", &debug.structure);
      ImGui::SameLine(220);
      ImGui::Checkbox("contacts", &debug.contacts);
      ImGui::Checkbox("velocities", &debug.velocities);
      ImGui::SameLine(220);
      ImGui::Checkbox("AABBs", &debug.aabbs);
      ImGui::Checkbox("broad-phase queries", &debug.broadphase);
      ImGui::SameLine(220);
      ImGui::Checkbox("regions", &debug.regions);
    }
  }
  ImGui::End();
  return tuning_changes(current, t);
}

}  // namespace game
