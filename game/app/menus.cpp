#include "app/menus.h"

#include <imgui.h>

#include <cstdio>
#include <string>

#include "progress/progress.h"

namespace game {

namespace {
void centred_text(const char* text, ImVec4 color) {
  const float w = ImGui::CalcTextSize(text).x;
  const float avail = ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
  if (avail > w) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + (avail - w) * 0.5f);
  ImGui::TextColored(color, "%s", text);
}
ImVec4 medal_colour(tire::Medal medal) {
  switch (medal) {
    case tire::Medal::gold: return {1.0f, 0.84f, 0.2f, 1.0f};
    case tire::Medal::silver: return {0.82f, 0.85f, 0.9f, 1.0f};
    case tire::Medal::bronze: return {0.85f, 0.55f, 0.3f, 1.0f};
    case tire::Medal::none: break;
  }
  return {0.7f, 0.7f, 0.7f, 1.0f};
}

// The medal earned, the three times (the earned one in its colour) and the time of the next one.
void draw_medals(tire::Medal earned, const tire::LevelMedals& medals, bool won) {
  if (earned != tire::Medal::none) centred_text((medal_title(earned) + "!").c_str(), medal_colour(earned));
  char line[160];
  std::snprintf(line, sizeof line, "Gold %.2f s    Silver %.2f s    Bronze %.2f s", medals.gold,
                medals.silver, medals.bronze);
  centred_text(line, {0.75f, 0.75f, 0.75f, 1.0f});
  const tire::Medal next = tire::next_medal(earned);
  if (won && next != tire::Medal::none) {
    std::snprintf(line, sizeof line, "%s within %.2f s", medal_title(next).c_str(),
                  *tire::medal_time(medals, next));
    centred_text(line, medal_colour(next));
  }
}

}  // namespace

MenuChoice draw_level_menu(const std::vector<LevelEntry>& levels, const std::vector<std::string>& notes,
                           std::size_t& selected, std::optional<std::size_t> current,
                           const std::string& levels_dir, ImFont* big) {
  MenuChoice choice = MenuChoice::none;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x * 0.5f, vp->Size.y * 0.5f}, ImGuiCond_Always, {0.5f, 0.5f});
  ImGui::SetNextWindowSizeConstraints({420, 0}, {vp->Size.x - 40.0f, vp->Size.y - 40.0f});
  if (ImGui::Begin("##levelmenu", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings)) {
    if (big) ImGui::PushFont(big);
    centred_text("Levels", {1.0f, 0.8f, 0.35f, 1.0f});
    if (big) ImGui::PopFont();
    ImGui::TextDisabled("%s", levels_dir.c_str());
    ImGui::Separator();
    if (levels.empty()) ImGui::TextColored({1.0f, 0.5f, 0.5f, 1.0f}, "No *.json levels in this directory.");
    for (std::size_t i = 0; i < levels.size(); ++i) {
      const LevelEntry& e = levels[i];
      std::string label = e.path.filename().string() + "   " + (e.valid ? e.name : "(does not load)");
      const std::string note = i < notes.size() ? notes[i] : "";
      if (!note.empty()) label += "   (" + note + ")";
      // Not won yet (or only on an earlier version of the level): the time to win within for gold.
      if (e.medals && (!note.starts_with("best") || note.ends_with(kEarlierVersion))) {
        char gold[64];
        std::snprintf(gold, sizeof gold, "   gold within %.2f s", e.medals->gold);
        label += gold;
      }
      if (current && *current == i) label += "   [playing]";
      label += "##" + std::to_string(i);
      const bool is_selected = selected == i;
      int colours = 0;
      if (!e.valid) ImGui::PushStyleColor(ImGuiCol_Text, IM_COL32(255, 120, 120, 255)), ++colours;
      if (is_selected) ImGui::PushStyleColor(ImGuiCol_Header, IM_COL32(230, 150, 40, 200)), ++colours;
      if (ImGui::Selectable(((is_selected ? "> " : "   ") + label).c_str(), is_selected)) {
        selected = i;
        choice = MenuChoice::load;
      }
      ImGui::PopStyleColor(colours);
    }
    ImGui::Separator();
    if (ImGui::Button("Resume (Esc)")) choice = MenuChoice::resume;
    ImGui::SameLine();
    if (ImGui::Button("Quit")) choice = MenuChoice::quit;
    ImGui::SameLine();
    ImGui::TextDisabled("Up/Down choose, Enter loads");
  }
  ImGui::End();
  return choice;
}

const char* end_title(tire::ScriptStatus status, tire::EndReason reason) {
  if (status == tire::ScriptStatus::won) return "Level complete!";
  switch (reason) {
    case tire::EndReason::time_limit: return "Time's up";
    case tire::EndReason::out_of_bounds: return "Off the edge";
    case tire::EndReason::head_hit: return "Crashed";
    default: return "You lost";
  }
}

std::string medal_title(tire::Medal medal) {
  switch (medal) {
    case tire::Medal::gold: return "Gold medal";
    case tire::Medal::silver: return "Silver medal";
    case tire::Medal::bronze: return "Bronze medal";
    case tire::Medal::none: break;
  }
  return "";
}

EndChoice draw_end_screen(tire::ScriptStatus status, tire::EndReason reason, const std::string& level,
                          double time, const std::string& note, tire::Medal medal,
                          const std::optional<tire::LevelMedals>& medals, ImFont* big) {
  EndChoice choice = EndChoice::none;
  const bool won = status == tire::ScriptStatus::won;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x * 0.5f, vp->Size.y * 0.38f + 30.0f}, ImGuiCond_Always, {0.5f, 0.0f});
  ImGui::SetNextWindowSizeConstraints({380, 0}, {vp->Size.x, vp->Size.y});
  ImGui::PushStyleColor(ImGuiCol_WindowBg, won ? IM_COL32(20, 70, 35, 235) : IM_COL32(80, 20, 20, 235));
  if (ImGui::Begin("##end", nullptr,
                   ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                       ImGuiWindowFlags_NoSavedSettings)) {
    if (big) ImGui::PushFont(big);
    centred_text(end_title(status, reason),
                 won ? ImVec4{0.6f, 1.0f, 0.6f, 1.0f} : ImVec4{1.0f, 0.6f, 0.6f, 1.0f});
    if (big) ImGui::PopFont();
    char line[256];
    std::snprintf(line, sizeof line, "%s  -  %.2f s", level.c_str(), time);
    centred_text(line, {0.9f, 0.9f, 0.9f, 1.0f});
    if (reason == tire::EndReason::time_limit)
      centred_text("The time limit ran out before the finish.", {0.9f, 0.9f, 0.9f, 1.0f});
    else if (reason == tire::EndReason::out_of_bounds)
      centred_text("The tire left the level.", {0.9f, 0.9f, 0.9f, 1.0f});
    else if (reason == tire::EndReason::head_hit)
      centred_text("The driver's head hit the ground.", {0.9f, 0.9f, 0.9f, 1.0f});
    if (!note.empty()) centred_text(note.c_str(), {1.0f, 0.85f, 0.35f, 1.0f});
    if (medals) draw_medals(won ? medal : tire::Medal::none, *medals, won);
    ImGui::Spacing();
    if (won) {
      if (ImGui::Button("Next level (N / Enter)")) choice = EndChoice::next;
      ImGui::SameLine();
      if (ImGui::Button("Retry (R)")) choice = EndChoice::retry;
    } else {
      if (ImGui::Button("Retry (R / Enter)")) choice = EndChoice::retry;
      ImGui::SameLine();
      if (ImGui::Button("Skip to next level (N)")) choice = EndChoice::next;
    }
  }
  ImGui::End();
  ImGui::PopStyleColor();
  return choice;
}

}  // namespace game
