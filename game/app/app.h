// The game's window and main loop: input, the fixed-timestep simulation (Simulation::step through
// GameSession), interpolated drawing, the HUD and panels, the level menu, win/lose screens and hot
// reload. Wall-clock time paces the loop and feeds the FPS and physics-time readouts; it never
// reaches the simulation, which only ever advances by whole ticks of the level's dt.
#pragma once

#include <SDL.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/frame_stats.h"
#include "app/hot_reload.h"
#include "app/imgui_layer.h"
#include "app/level_list.h"
#include "editor/editor_mode.h"
#include "input/gamepad.h"
#include "input/key_script.h"
#include "input/pad_script.h"
#include "play/game_session.h"
#include "play/session_recorder.h"
#include "progress/best_runs.h"
#include "render/camera.h"
#include "render/draw.h"
#include "render/ghost_draw.h"
#include "render/renderer.h"
#include "sound/sound_system.h"

namespace game {

struct GameOptions {
  std::filesystem::path level;       // the level to start with
  std::filesystem::path levels_dir;  // where the level menu and next/previous look
  std::optional<long long> frames;   // run exactly this many frames, one tick each, then exit
  KeyScript keys;                    // scripted key presses (--press)
  std::string screenshot;            // save the last frame here (BMP)
  std::string record;                // save the session's replay here on exit
  std::filesystem::path edit;        // open the editor on this level (made when it does not exist)
  std::vector<PadPress> pads;        // a scripted virtual game controller (--pad)
  // Where progress.json and the ghosts are kept; nullopt: neither read nor written (--no-progress).
  std::optional<std::filesystem::path> data_dir;
  sound::SoundOptions sound;  // --volume, --audio-log
};

// How many frames the exit summary's frame times cover at most: all of a --frames run up to this,
// otherwise (and beyond it) the latest ones.
constexpr std::size_t kFrameSamples = 1 << 20;
constexpr std::size_t kFrameSamplesInteractive = 1 << 16;

class App {
 public:
  // At most this many ticks per rendered frame; time beyond it is dropped (no spiral of death).
  static constexpr int kMaxStepsPerFrame = 5;

  explicit App(GameOptions options);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // Runs until the window closes (or the frame count is reached). Exit code: 0 done, 1 no window,
  // 2 the level does not load, an output is refused (check_outputs) or an output failed (the
  // screenshot, the audio log, the --record replay).
  int run();

  // run()'s parts, for a host that drives the frames itself (the browser's main loop calls frame()
  // once per animation frame): start() loads the level and opens the window (nothing: ready; else
  // run()'s exit code), frame() runs one frame (false: the loop is over), finish() saves the
  // recording and prints the exit summary (run()'s exit code).
  std::optional<int> start();
  bool frame();
  int finish();
  // The exit summary's one line of JSON, once finish() has run.
  const std::string& summary() const { return summary_; }
  // Counts the writes to the data folder (progress, ghosts): the browser build persists on a change.
  std::uint64_t data_writes() const { return best_runs_.writes(); }
  SDL_Window* window() const { return window_; }

 private:
  bool open_window();
  bool load_level(const std::filesystem::path& file);
  // The editor: opened on a level file, left to play the edited level, come back to.
  bool open_editor(const std::filesystem::path& file);
  void play_edited_level();
  void back_to_editor();
  void editor_frame();
  void go_to_level(int delta);
  void restart();
  void after_level_change();

  void handle_event(const SDL_Event& event);
  void key_down(SDL_Scancode key);
  void take_clicks();
  void mouse_down(int x, int y);
  void mouse_motion(int x, int y);
  void mouse_up();
  tire::Vec2 mouse_to_world(int x, int y) const;

  void advance(double frame_seconds);
  void step_once();
  tire::TickInput tick_input() const;
  void draw_frame(double wall_seconds);
  void draw_ui();
  std::string summary_json(long long frames) const;
  bool level_over() const;
  std::optional<tire::TireView> player_view() const;             // the player tire, if there is one
  std::optional<tire::VehicleView> player_vehicle_view() const;  // the player vehicle, if there is one
  void warn(const std::string& text);
  void save_replay();
  // "" when the outputs asked for (--record, --screenshot, --audio-log) may be written, else why
  // not: one is the level being played, or (written atomically) a directory, FIFO or device.
  std::string check_outputs() const;
  // Gamepads (gamepad.h), progress and the ghost (best_runs.h).
  void pad_event(const SDL_Event& event);
  void level_finished();

  GameOptions options_;
  SDL_Window* window_ = nullptr;
  SDL_Renderer* renderer_ = nullptr;
  std::unique_ptr<Draw> draw_;  // one batch for the whole run: drawing reuses its vertex buffer
  std::unique_ptr<ImGuiLayer> imgui_;
  bool sdl_started_ = false;

  std::unique_ptr<Editor> editor_;
  bool editing_ = false;
  std::vector<SDL_Event> editor_mouse_;  // the mouse's events, handed over after ImGui's next frame

  GameSession session_;
  SessionRecorder recorder_;  // every session is recorded; F5 saves
  std::uint64_t seen_generation_ = 0;
  Tuning level_tuning_;
  Camera camera_;
  tire::Aabb bounds_;
  WorldRenderer world_renderer_;
  DebugOptions debug_;

  std::vector<LevelEntry> levels_;
  HotReload hot_reload_;
  std::vector<std::string> level_errors_;
  std::string error_file_;
  struct Warning {
    std::string text;
    double until;  // wall seconds
  };
  std::vector<Warning> warnings_;

  // Input state.
  std::set<SDL_Scancode> held_;
  // Left clicks wait for ImGui's next frame, which knows whether they landed on one of its windows.
  std::vector<SDL_Point> clicks_;
  bool pending_jump_ = false;
  bool step_requested_ = false;
  bool grabbing_ = false;
  bool paused_ = false;
  bool show_help_ = false;
  bool show_tuning_ = false;
  bool menu_open_ = false;
  std::size_t menu_selected_ = 0;
  bool next_level_handled_ = false;
  std::optional<double> finished_at_;  // level time when the level was won or lost
  bool quit_ = false;
  bool output_failed_ = false;  // an output could not be written: the exit code says so

  // Timing.
  Uint64 run_start_ = 0;    // performance counter when the loop started
  long long frame_ = 0;     // frames run
  double last_wall_ = 0.0;  // now_ at the last frame
  std::string summary_;
  double accumulator_ = 0.0;  // s of simulated time owed, < dt after each frame
  double now_ = 0.0;          // wall seconds since start
  double fps_ = 0.0;
  double physics_ms_ = 0.0;
  double frame_physics_seconds_ = 0.0;
  int steps_this_frame_ = 0;
  FrameStats frame_stats_;  // per frame: simulation, rendering, whole frame (for the exit summary)

  // Gamepads, progress and the ghost of the best run.
  Gamepads gamepads_;
  VirtualPad virtual_pad_;
  BestRuns best_runs_;
  GhostRenderer ghost_renderer_;
  std::optional<RunResult> run_result_;  // the finished level's time and whether it is a best
  std::string hud_target_;               // the HUD's time to beat (BestRuns::note)
  int respawns_seen_ = 0;                // Simulation::respawns() already told
  // Heard after every tick (sound/sound_system.h).
  sound::SoundSystem sound_;
};

}  // namespace game
