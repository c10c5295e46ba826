#include "play/tuning_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

#include "tire/io/level_format.h"

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
  const bool changed = ImGui::SliderScalar(label, ImGuiDataType_Double, &value, &min, &max, format,
                                           flags | ImGuiSliderFlags_AlwaysClamp);
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
  const bool changed = ImGui::SliderInt(label, &v, min, max, "%d",
                                        ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tip);
  value = v;
  return changed;
}

}  // namespace

std::vector<TuneEvent> draw_tuning_panel(const Tuning& current, const Tuning& level_defaults,
                                         DebugOptions& debug, SoundSettings& sound, bool* open) {
  Tuning t = current;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x - 10.0f, 10.0f}, ImGuiCond_Appearing, {1.0f, 0.0f});
  ImGui::SetNextWindowSize({430, 0}, ImGuiCond_Appearing);
  if (ImGui::Begin("Tuning (F2)", open, ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::PushItemWidth(230);
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped("Applies live to every tire, those spawned later too, and wakes them.");
    ImGui::PopStyleColor();
    // A material preset (tire::material_presets()) sets the tire's sliders at once; any slider
    // moved after it makes the tire "custom".
    const tire::MaterialPreset* now = material_of(t);
    if (ImGui::BeginCombo("material", now ? std::string(now->name).c_str() : "custom")) {
      for (const tire::MaterialPreset& m : tire::material_presets()) {
        if (ImGui::Selectable(std::string(m.name).c_str(), &m == now)) t = with_material(t, m);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("%.*s", static_cast<int>(m.description.size()), m.description.data());
      }
      ImGui::EndCombo();
    }
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("A preset for every tire's compliances, damping, friction, restitution and pressure");
    // The keys are the parameter table's (tuning_keys()); each is shown in its slider's section,
    // in the table's order, within the table's range.
    const auto& rows = tuning_parameters();
    const auto& sections = slider_sections();
    for (std::size_t section = 0; section < sections.size(); ++section) {
      if (!ImGui::CollapsingHeader(sections[section], ImGuiTreeNodeFlags_DefaultOpen)) continue;
      for (std::size_t i = 0; i < rows.size(); ++i) {
        const tire::TunableParameter& p = *rows[i];
        const SliderSpec* spec = slider_spec(p.key);
        // A key the panel has no spec for goes, as a plain slider, into the last section.
        if (spec ? std::string_view(spec->section) != sections[section] : section + 1 != sections.size())
          continue;
        const SliderRange range = slider_range(p);
        double& value = t.values[i];
        const std::string key(p.key);
        const char* label = spec ? spec->label : key.c_str();
        // A key without a spec shows the table's description, its {range} written out.
        static const std::vector<std::string> descriptions = [&rows] {
          std::vector<std::string> out;
          for (const tire::TunableParameter* row : rows)
            out.push_back(tire::described(row->description, row->range));
          return out;
        }();
        const char* tip = spec ? spec->tip : descriptions[i].c_str();
        switch (spec ? spec->scale : p.integer ? SliderScale::integer : SliderScale::linear) {
          case SliderScale::exponent: log_slider(label, value, range.min, range.max, tip); break;
          case SliderScale::integer:
            int_slider(label, value, static_cast<int>(std::ceil(range.min)),
                       static_cast<int>(std::floor(range.max)), tip);
            break;
          case SliderScale::linear:
            slider(label, value, range.min, range.max, spec ? spec->format : "%.3g", tip);
            break;
          case SliderScale::logarithmic:
            slider(label, value, range.min, range.max, spec->format, tip, ImGuiSliderFlags_Logarithmic);
            break;
        }
      }
      // The last section, the world's and the solver's, ends with the sleep and rolling hold
      // checkboxes.
      if (section + 1 == sections.size()) {
        ImGui::Checkbox("sleep", &t.sleep);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("solver.sleep: tires that rest stop being simulated until something wakes them");
        ImGui::Checkbox("rolling hold", &t.rolling_hold);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip(
              "solver.rolling_hold: a tire that rolling resistance stopped stays put on a slope gentler than "
              "its rolling_resistance (the global method; tires touching no other tire)");
      }
    }
    if (ImGui::Button("Reset to the level's values")) t = level_defaults;
    if (ImGui::CollapsingHeader("Sound", ImGuiTreeNodeFlags_DefaultOpen)) {
      float volume = static_cast<float>(sound.volume);
      if (ImGui::SliderFloat("volume", &volume, 0.0f, 1.0f, "%.2f")) sound.volume = volume;
      ImGui::Checkbox("mute (M)", &sound.muted);
    }
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
