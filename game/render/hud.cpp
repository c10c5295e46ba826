#include "render/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cstdio>

#include "tire/engine.h"

namespace game {

namespace {
constexpr ImGuiWindowFlags kOverlay = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                      ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                      ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs;

const char* const kKeys[][2] = {
    {"Left / A", "steer left (hold)"},
    {"Right / D", "steer right (hold)"},
    {"Space / Up / W", "jump (when on the ground)"},
    {"Shift", "inflate (hold): stiffer, bouncier, rolls faster"},
    {"Down / S", "deflate (hold): a wider patch that grips, squeezes under low gaps"},
    {"R", "restart the level"},
    {"P", "pause / resume"},
    {". (period)", "one tick forward while paused"},
    {"N / B", "next / previous level"},
    {"G", "show / hide the ghost of your best run"},
    {"Esc", "level menu"},
    {"F1", "this help"},
    {"F2", "tuning panel"},
    {"F3", "debug drawing and numbers (sleeping tires darker)"},
    {"F5", "save a replay of this session into replays/"},
    {"E / F6", "edit this level (and back to playing it)"},
    {"M", "mute / unmute the sound"},
    {"Left click (empty space)", "spawn a tire"},
    {"Left drag (on a tire)", "grab and pull it"},
};

// Driving a car (a level whose player is a vehicle: levels 13 to 15).
const char* const kCar[][2] = {
    {"Right / D, Left / A", "throttle forward, reverse (hold)"},
    {"Space", "brake (hold): holds the car on a slope"},
    {"Up / W, Down / S", "lean back, lean forward (hold): lifts or drops the nose, turns it in the air"},
    {"Pad: left stick", "throttle (x) and lean (y); A held brakes"},
};

// A game controller (any SDL knows; plugged in at any time).
const char* const kPad[][2] = {
    {"Left stick / d-pad", "steer (the stick in proportion)"},
    {"A", "jump; in a menu or after a level: choose"},
    {"Right / left trigger", "inflate / deflate (in proportion)"},
    {"Start", "pause / resume"},
    {"Back", "restart the level"},
    {"Right / left shoulder", "next / previous level"},
    {"B", "level menu (and back); d-pad up/down chooses"},
};

void key_table(const char* id, const char* const (*rows)[2], std::size_t count) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV)) return;
  for (std::size_t i = 0; i < count; ++i) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextColored({1.0f, 0.8f, 0.35f, 1.0f}, "%s", rows[i][0]);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(rows[i][1]);
  }
  ImGui::EndTable();
}
}  // namespace

bool format_asleep_line(std::span<char> out, std::size_t asleep, std::size_t tires) {
  if (tires == 0 || out.empty()) return false;
  std::snprintf(out.data(), out.size(), "asleep %7zu / %zu", asleep, tires);
  return true;
}

double time_left(double limit, double time) { return std::max(0.0, limit - time); }

void format_clock_line(std::span<char> out, double time, std::optional<double> limit) {
  if (out.empty()) return;
  if (limit)
    std::snprintf(out.data(), out.size(), "time left %6.1f s", time_left(*limit, time));
  else
    std::snprintf(out.data(), out.size(), "time      %7.2f s", time);
}

void draw_hud(const HudInfo& info, const DevInfo& dev) {
  ImGui::SetNextWindowPos({10, 10});
  ImGui::SetNextWindowBgAlpha(0.55f);
  if (ImGui::Begin("##hud", nullptr, kOverlay)) {
    ImGui::TextUnformatted(info.level.data(), info.level.data() + info.level.size());
    ImGui::Separator();
    char clock[64];
    format_clock_line(clock, info.time, info.time_limit);
    // The last ten seconds of a time limit in red.
    if (info.time_limit && time_left(*info.time_limit, info.time) <= 10.0)
      ImGui::TextColored({1.0f, 0.4f, 0.35f, 1.0f}, "%s", clock);
    else
      ImGui::TextUnformatted(clock);
    if (!info.target.empty())
      ImGui::TextColored({1.0f, 0.85f, 0.35f, 1.0f}, "%.*s", static_cast<int>(info.target.size()),
                         info.target.data());
    if (!info.over) {
      ImGui::Text("speed     %5.0f km/h", info.speed * 3.6);
      if (info.grounded)
        ImGui::TextDisabled("on the ground");
      else
        ImGui::TextColored({0.55f, 0.8f, 1.0f, 1.0f}, "in the air");
    }
    if (info.paused) ImGui::TextColored({1.0f, 0.85f, 0.3f, 1.0f}, "PAUSED  (P resume, . step)");
    if (dev.shown) {
      ImGui::Separator();
      ImGui::TextDisabled("F3: for developers");
      ImGui::Text("tick    %llu", static_cast<unsigned long long>(dev.tick));
      ImGui::Text("FPS     %6.0f", dev.fps);
      ImGui::Text("physics %6.2f ms/frame (%d ticks)", dev.physics_ms, dev.steps_last_frame);
      ImGui::Text("speed   %6.2f m/s", info.speed);
      ImGui::Text("tires   %6zu", dev.tires);
      char asleep[64];
      if (format_asleep_line(asleep, dev.asleep, dev.tires)) ImGui::TextUnformatted(asleep);
      if (dev.failed_solves > 0)
        ImGui::TextColored({1.0f, 0.4f, 0.3f, 1.0f}, "failed solves %llu",
                           static_cast<unsigned long long>(dev.failed_solves));
    }
    ImGui::TextDisabled("F1 help   F2 tuning   F3 debug   Esc levels");
  }
  ImGui::End();
}

void draw_help(bool* open) {
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x * 0.5f, vp->Size.y * 0.5f}, ImGuiCond_Always, {0.5f, 0.5f});
  if (ImGui::Begin("Keys and gamepad (F1 closes)", open,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoSavedSettings)) {
    ImGui::TextDisabled("Keyboard and mouse");
    key_table("keys", kKeys, std::size(kKeys));
    ImGui::Spacing();
    ImGui::TextDisabled("Gamepad");
    key_table("pad", kPad, std::size(kPad));
    ImGui::Spacing();
    ImGui::TextDisabled("Driving a car (its driver's head must not touch the ground)");
    key_table("car", kCar, std::size(kCar));
    ImGui::Spacing();
    ImGui::TextDisabled("Edit the level file while playing: it reloads on save.");
  }
  ImGui::End();
}

void draw_script_messages(const tire::Simulation& simulation, ImFont* big) {
  const std::span<const tire::ScriptMessage> messages = simulation.messages();
  if (messages.empty()) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  const float max_width = vp->Size.x * 0.8f;
  ImGui::SetNextWindowPos({vp->Size.x * 0.5f, std::max(vp->Size.y * 0.3f, 250.0f)}, ImGuiCond_Always,
                          {0.5f, 0.5f});
  ImGui::SetNextWindowSizeConstraints({0, 0}, {max_width, vp->Size.y * 0.5f});
  ImGui::SetNextWindowBgAlpha(0.6f);
  if (ImGui::Begin("##messages", nullptr, kOverlay)) {
    if (big) ImGui::PushFont(big);
    const float wrap = max_width - 2.0f * ImGui::GetStyle().WindowPadding.x;
    for (const tire::ScriptMessage& m : messages) {
      const float w = ImGui::CalcTextSize(m.text.c_str()).x;
      if (w > wrap) {
        // Too long for one line: wrap it at the window's width.
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + wrap);
        ImGui::TextUnformatted(m.text.c_str());
        ImGui::PopTextWrapPos();
        continue;
      }
      // Centre each line in the window.
      const float avail = ImGui::GetWindowContentRegionMax().x - ImGui::GetWindowContentRegionMin().x;
      if (avail > w) ImGui::SetCursorPosX(ImGui::GetCursorPosX() + (avail - w) * 0.5f);
      ImGui::TextUnformatted(m.text.c_str());
    }
    if (big) ImGui::PopFont();
  }
  ImGui::End();
}

void draw_level_errors(const std::string& file, const std::vector<std::string>& errors) {
  if (errors.empty()) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({vp->Size.x * 0.5f, vp->Size.y - 12.0f}, ImGuiCond_Always, {0.5f, 1.0f});
  ImGui::SetNextWindowSizeConstraints({300, 0}, {vp->Size.x - 40.0f, vp->Size.y * 0.45f});
  ImGui::PushStyleColor(ImGuiCol_WindowBg, IM_COL32(70, 0, 0, 235));
  ImGui::PushStyleColor(ImGuiCol_TitleBg, IM_COL32(150, 20, 20, 255));
  ImGui::PushStyleColor(ImGuiCol_TitleBgActive, IM_COL32(170, 25, 25, 255));
  const std::string title = "Level errors: " + file + " (still playing the last good level)";
  if (ImGui::Begin(title.c_str(), nullptr,
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing)) {
    for (const std::string& e : errors) ImGui::TextColored({1.0f, 0.45f, 0.45f, 1.0f}, "%s", e.c_str());
  }
  ImGui::End();
  ImGui::PopStyleColor(3);
}

void draw_warnings(const std::vector<std::string>& warnings) {
  if (warnings.empty()) return;
  const ImGuiViewport* vp = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos({10, vp->Size.y - 10.0f}, ImGuiCond_Always, {0.0f, 1.0f});
  ImGui::SetNextWindowBgAlpha(0.7f);
  if (ImGui::Begin("##warnings", nullptr, kOverlay))
    for (const std::string& w : warnings) ImGui::TextColored({1.0f, 0.6f, 0.2f, 1.0f}, "%s", w.c_str());
  ImGui::End();
}

}  // namespace game
