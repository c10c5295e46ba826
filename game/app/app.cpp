#include "app/app.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/menus.h"
#include "app/screenshot.h"
#include "play/tuning_panel.h"
#include "render/draw.h"
#include "render/hud.h"
#include "tire/io/file_io.h"
#include "tire/math/numbers.h"

namespace game {

namespace {

double seconds_since(Uint64 start) {
  return static_cast<double>(SDL_GetPerformanceCounter() - start) /
         static_cast<double>(SDL_GetPerformanceFrequency());
}

bool is_any(SDL_Scancode k, std::initializer_list<SDL_Scancode> keys) {
  return std::find(keys.begin(), keys.end(), k) != keys.end();
}

}  // namespace

App::App(GameOptions options) : options_(std::move(options)) {}

App::~App() {
  // The scripted pad first: closing the controllers may shut SDL's joysticks down, its handle too.
  virtual_pad_.detach();
  gamepads_.close_all();
  sound_.close();  // before SDL_Quit
  imgui_.reset();
  world_renderer_.release();
  draw_.reset();
  if (renderer_) SDL_DestroyRenderer(renderer_);
  if (window_) SDL_DestroyWindow(window_);
  if (sdl_started_) SDL_Quit();
}

bool App::open_window() {
  const auto fail = [](const char* what) {
    std::cerr << "tire-game: cannot open a window: " << what << ": " << SDL_GetError()
              << ". Set DISPLAY or run headless with SDL_VIDEODRIVER=offscreen, or use build/bin/tirectl.\n";
    return false;
  };
  if (SDL_Init(SDL_INIT_VIDEO | SDL_INIT_EVENTS) != 0) return fail("SDL_Init");
  sdl_started_ = true;
  // With no display SDL quietly falls back to its invisible drivers; only use them when asked to.
  const std::string driver = SDL_GetCurrentVideoDriver() ? SDL_GetCurrentVideoDriver() : "";
  if ((driver == "offscreen" || driver == "dummy" || driver == "evdev") && !SDL_getenv("SDL_VIDEODRIVER")) {
    SDL_SetError("no display found (SDL could only offer its invisible '%s' video driver)", driver.c_str());
    return fail("SDL_Init");
  }
  window_ = SDL_CreateWindow("Soft tire", SDL_WINDOWPOS_CENTERED, SDL_WINDOWPOS_CENTERED, 1280, 720,
                             SDL_WINDOW_RESIZABLE | SDL_WINDOW_ALLOW_HIGHDPI);
  if (!window_) return fail("SDL_CreateWindow");
  const Uint32 vsync = options_.frames ? 0u : static_cast<Uint32>(SDL_RENDERER_PRESENTVSYNC);
  renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_ACCELERATED | vsync);
  if (!renderer_) renderer_ = SDL_CreateRenderer(window_, -1, SDL_RENDERER_SOFTWARE);
  if (!renderer_) return fail("SDL_CreateRenderer");
  SDL_SetRenderDrawBlendMode(renderer_, SDL_BLENDMODE_BLEND);
  draw_ = std::make_unique<Draw>(renderer_);
  imgui_ = std::make_unique<ImGuiLayer>();
  if (!imgui_->init(window_, renderer_)) return fail("Dear ImGui");
  return true;
}

// ---- Levels --------------------------------------------------------------------------------------

bool App::load_level(const std::filesystem::path& file) {
  tire::LevelOpen load = tire::open_level_file(file);
  if (!load.level) {
    level_errors_ = std::move(load.errors);
    error_file_ = file.string();
    return false;
  }
  level_errors_.clear();
  std::shared_ptr<const tire::Level> level = std::move(load.level);
  if (!session_.loaded()) {
    recorder_.begin(file, load.info.gravity);
    session_.start(file.string(), std::move(level));
    session_.set_observer(&recorder_);
  } else {
    session_.queue(LoadLevelEvent{file.string(), std::move(level)});
  }
  hot_reload_.watch(file);
  return true;
}

void App::restart() {
  if (session_.loaded()) session_.queue(LoadLevelEvent{session_.path(), session_.level_ptr()});
}

void App::go_to_level(int delta) {
  levels_ = scan_levels(options_.levels_dir);
  if (levels_.empty()) {
    warn("no levels in " + options_.levels_dir.string());
    return;
  }
  const auto n = static_cast<long long>(levels_.size());
  const auto current = find_level(levels_, session_.path());
  long long next = 0;
  if (current)
    next = ((static_cast<long long>(*current) + delta) % n + n) % n;
  else
    next = delta >= 0 ? 0 : n - 1;
  load_level(levels_[static_cast<std::size_t>(next)].path);
}

// Called when the session has started a new world (load, restart, reload).
void App::after_level_change() {
  seen_generation_ = session_.generation();
  level_tuning_ = session_.tuning();
  bounds_ = level_bounds(session_.simulation());
  world_renderer_.set_underground(underground(session_.simulation()));
  const std::optional<tire::TireView> player = player_view();
  const std::optional<tire::VehicleView> vehicle = player_vehicle_view();
  camera_.snap(vehicle  ? camera_.aim(vehicle->center, {})
               : player ? camera_.aim(player->centroid, {})
                        : (bounds_.min + bounds_.max) * 0.5,
               bounds_);
  accumulator_ = 0.0;
  pending_jump_ = false;
  grabbing_ = false;
  next_level_handled_ = false;
  finished_at_.reset();
  run_result_.reset();
  std::vector<std::string> messages;
  best_runs_.level_started(session_.path(), session_.level_ptr(), messages);
  best_runs_.ticked(session_.simulation().tick());
  for (const std::string& m : messages) warn(m);
  hud_target_ = best_runs_.target(session_.path(), session_.level().medals);
  respawns_seen_ = 0;
  sound_.new_level();
  if (window_) SDL_SetWindowTitle(window_, ("Soft tire - " + session_.level().name).c_str());
}

// ---- Editor --------------------------------------------------------------------------------------

bool App::open_editor(const std::filesystem::path& file) {
  auto ed = std::make_unique<Editor>();
  if (const std::string e = ed->open(file); !e.empty()) {
    level_errors_ = {e};
    error_file_ = file.string();
    return false;
  }
  editor_ = std::move(ed);
  editing_ = true;
  paused_ = false;
  return true;
}

// Plays the level as edited (saved or not); the document stays as it is for the way back.
void App::play_edited_level() {
  const auto& level = editor_->document().level();
  if (!level) {
    warn("cannot play: " + editor_->document().errors().front());
    return;
  }
  const std::string path = editor_->document().file().string();
  if (!session_.loaded()) {
    recorder_.begin(path, editor_->document().info().gravity);
    session_.start(path, level);
    session_.set_observer(&recorder_);
  } else {
    session_.queue(LoadLevelEvent{path, level});
  }
  editing_ = false;
  menu_open_ = false;
  show_tuning_ = false;
  held_.clear();
}

void App::back_to_editor() {
  held_.clear();
  grabbing_ = false;
  if (editor_) {
    editing_ = true;
    return;
  }
  if (!open_editor(session_.path())) warn("cannot edit " + session_.path() + ": " + level_errors_.front());
}

// The editor's side of a frame: its requests, its messages, the window's title.
void App::editor_frame() {
  for (const std::string& m : editor_->take_messages()) warn(m);
  switch (editor_->take_request()) {
    case EditorRequest::play: play_edited_level(); break;
    case EditorRequest::quit: quit_ = true; break;
    case EditorRequest::none: break;
  }
  if (window_) {
    const std::string title = editing_ ? editor_->title() : "Soft tire - " + session_.level().name;
    if (title != SDL_GetWindowTitle(window_)) SDL_SetWindowTitle(window_, title.c_str());
  }
}

bool App::level_over() const { return session_.simulation().status() != tire::ScriptStatus::running; }

std::optional<tire::VehicleView> App::player_vehicle_view() const {
  const tire::Simulation& simulation = session_.simulation();
  for (std::size_t i = 0; const std::optional<tire::VehicleView> v = simulation.vehicle_at(i); ++i)
    if (v->player) return v;
  return std::nullopt;
}

std::optional<tire::TireView> App::player_view() const {
  const std::optional<tire::TireId> id = session_.simulation().player();
  return id ? session_.simulation().tire(*id) : std::nullopt;
}

// Saves the session so far into replays/ beside the levels folder, under a name with the level and
// the time, written atomically and never over an earlier save (a second save in the same second is
// <name>-2.json); the message names the file written.
void App::save_replay() {
  const std::filesystem::path dir = std::filesystem::absolute(options_.levels_dir).parent_path() / "replays";
  std::string error;
  if (const auto file = recorder_.save_new(session_.simulation(), recorder_.default_file(dir), error))
    warn("replay saved: " + file->string() + " (" + std::to_string(recorder_.ticks()) + " ticks)");
  else
    warn("cannot save the replay: " + error);
}

std::string App::check_outputs() const {
  const std::filesystem::path level = options_.edit.empty() ? options_.level : options_.edit;
  struct Output {
    const char* option;
    const std::string& file;
    bool atomic;  // written by tire::write_file_atomically, which refuses what is not a regular file
  };
  // The audio log is a stream (sound/audio_log.h): a FIFO or /dev/stdout may take it.
  const Output outputs[] = {{"--record", options_.record, true},
                            {"--screenshot", options_.screenshot, true},
                            {"--audio-log", options_.sound.log_file, false}};
  for (const Output& out : outputs) {
    if (out.file.empty()) continue;
    if (tire::same_file(out.file, level))
      return std::string(out.option) + " " + out.file + " is the level being played (" + level.string() +
             "); refusing to write over it";
    if (out.atomic)
      if (const std::string error = tire::check_output_file(out.file); !error.empty())
        return std::string(out.option) + ": " + error;
  }
  return "";
}

void App::warn(const std::string& text) {
  std::cerr << "tire-game: " << text << "\n";
  warnings_.push_back({text, now_ + 6.0});
  if (warnings_.size() > 6) warnings_.erase(warnings_.begin());
}

// ---- Input ---------------------------------------------------------------------------------------

void App::handle_event(const SDL_Event& e) {
  if (e.type >= SDL_CONTROLLERAXISMOTION && e.type <= SDL_CONTROLLERDEVICEREMAPPED) {
    pad_event(e);
    return;
  }
  if (editing_) {
    if (e.type == SDL_QUIT) {
      editor_->request_quit();
      return;
    }
    if (e.type == SDL_KEYUP) held_.erase(e.key.keysym.scancode);
    if (e.type == SDL_MOUSEBUTTONDOWN || e.type == SDL_MOUSEBUTTONUP || e.type == SDL_MOUSEMOTION ||
        e.type == SDL_MOUSEWHEEL) {
      // Whether a press lands on an ImGui window is known after ImGui's next frame, which reads
      // the pointer where the press was (a pointer warped there, as xdotool does, may send no
      // motion first); the mouse's events wait for it, in their order.
      imgui_->process_event(e);
      editor_mouse_.push_back(e);
      return;
    }
    imgui_->process_event(e);
    if (e.type == SDL_KEYDOWN && e.key.keysym.scancode == SDL_SCANCODE_F1 && !e.key.repeat)
      show_help_ = !show_help_;
    editor_->handle_event(e, imgui_->wants_mouse(), imgui_->wants_keyboard());
    return;
  }
  if (e.type == SDL_QUIT) {
    quit_ = true;
    return;
  }
  // Key releases always count (a key must never stay held because ImGui had focus).
  if (e.type == SDL_KEYUP) {
    held_.erase(e.key.keysym.scancode);
    imgui_->process_event(e);
    return;
  }
  const bool imgui_wants = imgui_->process_event(e);
  switch (e.type) {
    case SDL_KEYDOWN:
      if (imgui_wants || e.key.repeat) return;
      held_.insert(e.key.keysym.scancode);
      key_down(e.key.keysym.scancode);
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (e.button.button == SDL_BUTTON_LEFT && !menu_open_) clicks_.push_back({e.button.x, e.button.y});
      break;
    case SDL_MOUSEMOTION:
      if (grabbing_) mouse_motion(e.motion.x, e.motion.y);
      break;
    case SDL_MOUSEBUTTONUP:
      if (e.button.button == SDL_BUTTON_LEFT && grabbing_) mouse_up();
      break;
    default: break;
  }
}

void App::key_down(SDL_Scancode k) {
  switch (k) {
    case SDL_SCANCODE_F1: show_help_ = !show_help_; return;
    case SDL_SCANCODE_F2: show_tuning_ = !show_tuning_; return;
    case SDL_SCANCODE_F3: debug_.enabled = !debug_.enabled; return;
    case SDL_SCANCODE_F5: save_replay(); return;
    case SDL_SCANCODE_M: warn(sound_.toggle_mute() ? "sound off (M)" : "sound on (M)"); return;  // menu too
    case SDL_SCANCODE_F6:
    case SDL_SCANCODE_E:
      if (!menu_open_) {
        back_to_editor();
        return;
      }
      break;
    default: break;
  }
  if (menu_open_) {
    if (levels_.empty())
      menu_selected_ = 0;
    else if (is_any(k, {SDL_SCANCODE_UP, SDL_SCANCODE_W}))
      menu_selected_ = (menu_selected_ + levels_.size() - 1) % levels_.size();
    else if (is_any(k, {SDL_SCANCODE_DOWN, SDL_SCANCODE_S}))
      menu_selected_ = (menu_selected_ + 1) % levels_.size();
    else if (is_any(k, {SDL_SCANCODE_RETURN, SDL_SCANCODE_KP_ENTER})) {
      if (load_level(levels_[menu_selected_].path)) menu_open_ = false;
    }
    if (k == SDL_SCANCODE_ESCAPE) menu_open_ = false;
    return;
  }
  if (k == SDL_SCANCODE_ESCAPE) {
    levels_ = scan_levels(options_.levels_dir);
    menu_selected_ = find_level(levels_, session_.path()).value_or(0);
    menu_open_ = true;
    return;
  }
  if (level_over()) {
    const bool won = session_.simulation().status() == tire::ScriptStatus::won;
    if (k == SDL_SCANCODE_N || (won && is_any(k, {SDL_SCANCODE_RETURN, SDL_SCANCODE_KP_ENTER}))) {
      go_to_level(+1);
      return;
    }
    if (k == SDL_SCANCODE_R || (!won && is_any(k, {SDL_SCANCODE_RETURN, SDL_SCANCODE_KP_ENTER}))) {
      restart();
      return;
    }
  }
  switch (k) {
    case SDL_SCANCODE_R: restart(); break;
    case SDL_SCANCODE_P: paused_ = !paused_; break;
    case SDL_SCANCODE_PERIOD:
      if (paused_) step_requested_ = true;
      break;
    case SDL_SCANCODE_N: go_to_level(+1); break;
    case SDL_SCANCODE_B: go_to_level(-1); break;
    case SDL_SCANCODE_G:
      if (best_runs_.ghost().loaded()) {
        best_runs_.ghost().visible = !best_runs_.ghost().visible;
        warn(best_runs_.ghost().visible ? "ghost shown (G hides it)" : "ghost hidden (G shows it)");
      } else {
        warn(best_runs_.enabled() ? "no ghost for this level yet: win it to make one"
                                  : "no ghost: progress is off");
      }
      break;
    case SDL_SCANCODE_SPACE:
    case SDL_SCANCODE_UP:
    case SDL_SCANCODE_W: pending_jump_ = true; break;
    default: break;
  }
}

tire::Vec2 App::mouse_to_world(int x, int y) const {
  // Mouse coordinates are in window points; the camera works in output pixels (high-DPI aware).
  int ww = 1, wh = 1;
  SDL_GetWindowSize(window_, &ww, &wh);
  const double sx = static_cast<double>(camera_.width()) / std::max(ww, 1);
  const double sy = static_cast<double>(camera_.height()) / std::max(wh, 1);
  return camera_.to_world(x * sx, y * sy);
}

void App::take_clicks() {
  if (!imgui_->wants_mouse() && !menu_open_)
    for (const SDL_Point& c : clicks_) mouse_down(c.x, c.y);
  clicks_.clear();
}

void App::mouse_down(int x, int y) {
  const tire::Vec2 p = mouse_to_world(x, y);
  const double radius = std::max(0.2, camera_.metres(14.0));
  const tire::Simulation& simulation = session_.simulation();
  for (std::size_t i = 0; const std::optional<tire::TireView> t = simulation.tire_at(i); ++i) {
    if (length(t->centroid - p) <= t->outer_radius + radius) {
      session_.queue(GrabEvent{p, radius});
      grabbing_ = true;
      return;
    }
  }
  session_.queue(SpawnTireEvent{p});
}

void App::mouse_motion(int x, int y) { session_.queue(MoveGrabEvent{mouse_to_world(x, y)}); }

void App::mouse_up() {
  session_.queue(ReleaseGrabEvent{});
  grabbing_ = false;
}

tire::TickInput App::tick_input() const {
  tire::TickInput in;
  if (menu_open_ || level_over()) return in;
  const auto held = [this](SDL_Scancode a, SDL_Scancode b) { return held_.contains(a) || held_.contains(b); };
  const double keys = (held(SDL_SCANCODE_RIGHT, SDL_SCANCODE_D) ? 1.0 : 0.0) -
                      (held(SDL_SCANCODE_LEFT, SDL_SCANCODE_A) ? 1.0 : 0.0);
  in.steer = std::clamp(keys + gamepads_.steer(), -1.0, 1.0);
  in.jump = pending_jump_;
  const double pump = (held(SDL_SCANCODE_LSHIFT, SDL_SCANCODE_RSHIFT) ? 1.0 : 0.0) -
                      (held(SDL_SCANCODE_DOWN, SDL_SCANCODE_S) ? 1.0 : 0.0);
  in.inflate = std::clamp(pump + gamepads_.inflate(), -1.0, 1.0);
  // A player vehicle: Up/W (or the pad's stick) leans back, Down/S forward, Space (or the pad's A
  // held) brakes; the steer above is its throttle. It neither jumps nor inflates.
  if (player_vehicle_view()) {
    const double lean = (held(SDL_SCANCODE_UP, SDL_SCANCODE_W) ? 1.0 : 0.0) -
                        (held(SDL_SCANCODE_DOWN, SDL_SCANCODE_S) ? 1.0 : 0.0);
    in.lean = std::clamp(lean + gamepads_.lean(), -1.0, 1.0);
    in.brake = held_.contains(SDL_SCANCODE_SPACE) || gamepads_.brake();
    in.jump = false;
    in.inflate = 0.0;
  }
  return in;
}

// ---- Simulation ----------------------------------------------------------------------------------

void App::step_once() {
  const tire::TickInput input = tick_input();
  const Uint64 start = SDL_GetPerformanceCounter();
  session_.step(input);
  frame_physics_seconds_ += seconds_since(start);
  sound_.after_tick(session_.simulation(), input);
  pending_jump_ = false;
  ++steps_this_frame_;
  for (const std::string& w : session_.take_warnings()) warn(w);
  best_runs_.ticked(session_.simulation().tick());
  if (const int respawns = session_.simulation().respawns(); respawns > respawns_seen_) {
    respawns_seen_ = respawns;
    warn("out of the level: back to the checkpoint");
  }
  if (!finished_at_ && level_over()) level_finished();
}

// ---- Gamepads, progress, ghost -------------------------------------------------------------------

// A pad's buttons do what the keys do (the help screen lists both).
void App::pad_event(const SDL_Event& e) {
  std::vector<std::string> messages;
  const PadAction action = gamepads_.handle_event(e, messages);
  for (const std::string& m : messages) warn(m);
  if (editing_ || action == PadAction::none) return;
  const bool choosing = menu_open_ || level_over();
  switch (action) {
    case PadAction::jump: key_down(choosing ? SDL_SCANCODE_RETURN : SDL_SCANCODE_SPACE); break;
    case PadAction::pause: key_down(menu_open_ ? SDL_SCANCODE_ESCAPE : SDL_SCANCODE_P); break;
    case PadAction::restart: key_down(SDL_SCANCODE_R); break;
    case PadAction::next_level: key_down(SDL_SCANCODE_N); break;
    case PadAction::previous_level: key_down(SDL_SCANCODE_B); break;
    case PadAction::menu_up:
      if (menu_open_) key_down(SDL_SCANCODE_UP);
      break;
    case PadAction::menu_down:
      if (menu_open_) key_down(SDL_SCANCODE_DOWN);
      break;
    case PadAction::back: key_down(SDL_SCANCODE_ESCAPE); break;
    case PadAction::none: break;
  }
}

// The level was just won or lost: the time goes into the progress, a best run becomes the ghost.
void App::level_finished() {
  finished_at_ = session_.simulation().time();
  const bool won = session_.simulation().status() == tire::ScriptStatus::won;
  // A level played from the editor with unsaved changes is not the file: its time is not recorded.
  const bool is_file =
      !(editor_ && editor_->document().modified() && editor_->document().file() == session_.path());
  // Nor is a run the tuning panel changed (gravity, friction, the solver...): it is not the level.
  const bool tuned = session_.tuned();
  std::vector<std::string> messages;
  run_result_ = best_runs_.finished(won, *finished_at_, session_.simulation().tick(), is_file && !tuned,
                                    recorder_, session_.simulation(), messages);
  if (tuned) run_result_->medal = tire::Medal::none;  // not the level's times
  if (tuned && best_runs_.enabled()) run_result_->note = "tuned (F2): not a best time";
  for (const std::string& m : messages) warn(m);
  hud_target_ = best_runs_.target(session_.path(), session_.level().medals);
}

void App::advance(double frame_seconds) {
  steps_this_frame_ = 0;
  frame_physics_seconds_ = 0.0;
  const bool running = !paused_ && !menu_open_;
  if (running) accumulator_ += frame_seconds;
  while (running && accumulator_ >= session_.simulation().config().dt &&
         steps_this_frame_ < kMaxStepsPerFrame) {
    accumulator_ -= session_.simulation().config().dt;
    step_once();
    if (session_.generation() != seen_generation_) after_level_change();
    if (session_.simulation().next_level_requested()) break;
  }
  // A slow frame: drop the time the cap left over rather than owe it to the next frames.
  const double dt = session_.simulation().config().dt;
  if (accumulator_ >= dt) accumulator_ = std::fmod(accumulator_, dt);
  if (step_requested_ && paused_) step_once();
  step_requested_ = false;
  // A script asked for the next level.
  if (session_.simulation().next_level_requested() && !next_level_handled_) {
    next_level_handled_ = true;
    go_to_level(+1);
  }
}

// ---- Drawing -------------------------------------------------------------------------------------

void App::draw_frame(double wall_seconds) {
  int w = 0, h = 0;
  SDL_GetRendererOutputSize(renderer_, &w, &h);
  camera_.resize(w, h);
  if (editor_) {
    int ww = 1, wh = 1;
    SDL_GetWindowSize(window_, &ww, &wh);
    editor_->set_window_scale(static_cast<double>(w) / std::max(ww, 1),
                              static_cast<double>(h) / std::max(wh, 1));
  }
  if (editing_) {
    SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
    SDL_RenderClear(renderer_);
    editor_->draw(*draw_, world_renderer_, w, h);
    editor_->draw_ui();
    if (show_help_) draw_help(&show_help_);
    std::erase_if(warnings_, [this](const Warning& warning) { return warning.until < now_; });
    std::vector<std::string> texts;
    for (const Warning& warning : warnings_) texts.push_back(warning.text);
    draw_warnings(texts);
    imgui_->render();
    editor_frame();
    return;
  }

  const double dt = session_.simulation().config().dt;
  const double alpha = paused_ || menu_open_ ? 1.0 : std::clamp(accumulator_ / dt, 0.0, 1.0);
  // The camera holds still while the mouse drags a tire, so the cursor keeps pointing where it pulls,
  // and once the tire has left the level: it watches it fall away rather than follow it down.
  const bool gone = session_.simulation().end_reason() == tire::EndReason::out_of_bounds;
  if (const std::optional<tire::VehicleView> v = player_vehicle_view(); v && !grabbing_ && !gone)
    camera_.follow(camera_.aim(v->center, v->velocity), bounds_, wall_seconds);
  else if (const std::optional<tire::TireView> p = player_view(); p && !grabbing_ && !gone)
    camera_.follow(camera_.aim(session_.interpolated_centroid(*p, alpha), p->velocity), bounds_,
                   wall_seconds);

  SDL_SetRenderDrawColor(renderer_, 0, 0, 0, 255);
  SDL_RenderClear(renderer_);
  world_renderer_.draw(*draw_, camera_, session_, alpha, debug_);
  ghost_renderer_.draw(*draw_, camera_, best_runs_.ghost(), alpha);
  draw_ui();
  imgui_->render();
  if (editor_) editor_frame();
}

void App::draw_ui() {
  const tire::Simulation& simulation = session_.simulation();
  HudInfo hud;
  hud.level = session_.level().name;
  hud.time = finished_at_.value_or(simulation.time());  // the clock stops when the level ends
  hud.time_limit = session_.level().time_limit;
  hud.target = hud_target_;
  if (const std::optional<tire::VehicleView> v = player_vehicle_view()) {
    // A vehicle: its chassis' speed, and on the ground while any wheel touches it (within the jump
    // grace, as a tire's, so that a bumpy ride does not flicker).
    hud.speed = length(v->velocity);
    for (const tire::TireId id : v->wheels()) {
      const std::optional<tire::TireView> wheel = simulation.tire(id);
      hud.grounded = hud.grounded || (wheel && wheel->may_jump);
    }
  } else if (const std::optional<tire::TireView> p = player_view()) {
    hud.speed = length(p->velocity);
    hud.grounded = p->may_jump;
  }
  hud.paused = paused_;
  hud.over = level_over();
  DevInfo dev;
  dev.shown = debug_.enabled;
  dev.tick = simulation.tick();
  dev.fps = fps_;
  dev.physics_ms = physics_ms_;
  dev.steps_last_frame = steps_this_frame_;
  dev.tires = simulation.tire_count();
  dev.asleep = simulation.asleep_count();
  dev.failed_solves = simulation.solver_failures();
  draw_hud(hud, dev);
  draw_script_messages(simulation, imgui_->big_font());

  if (show_tuning_) {
    SoundSettings sound{sound_.volume(), sound_.muted()};
    for (TuneEvent& e : draw_tuning_panel(session_.tuning(), level_tuning_, debug_, sound, &show_tuning_))
      session_.queue(std::move(e));
    if (sound.volume != sound_.volume()) sound_.set_volume(sound.volume);
    if (sound.muted != sound_.muted()) sound_.set_muted(sound.muted);
  }
  if (show_help_) draw_help(&show_help_);

  if (menu_open_) {
    std::vector<std::string> notes;
    for (const LevelEntry& e : levels_) notes.push_back(best_runs_.note(e.path));
    const MenuChoice choice =
        draw_level_menu(levels_, notes, menu_selected_, find_level(levels_, session_.path()),
                        options_.levels_dir.string(), imgui_->big_font());
    if (choice == MenuChoice::load && menu_selected_ < levels_.size() &&
        load_level(levels_[menu_selected_].path))
      menu_open_ = false;
    else if (choice == MenuChoice::resume)
      menu_open_ = false;
    else if (choice == MenuChoice::quit)
      quit_ = true;
  } else if (level_over()) {
    switch (draw_end_screen(simulation.status(), simulation.end_reason(), session_.level().name,
                            finished_at_.value_or(simulation.time()), run_result_ ? run_result_->note : "",
                            run_result_ ? run_result_->medal : tire::Medal::none, session_.level().medals,
                            imgui_->big_font())) {
      case EndChoice::next: go_to_level(+1); break;
      case EndChoice::retry: restart(); break;
      case EndChoice::none: break;
    }
  }
  draw_level_errors(error_file_, level_errors_);
  std::erase_if(warnings_, [this](const Warning& w) { return w.until < now_; });
  std::vector<std::string> texts;
  for (const Warning& w : warnings_) texts.push_back(w.text);
  draw_warnings(texts);
}

// ---- Loop ----------------------------------------------------------------------------------------

int App::run() {
  if (const std::optional<int> failed = start()) return *failed;
  while (frame()) {
  }
  return finish();
}

std::optional<int> App::start() {
  if (const std::string err = check_outputs(); !err.empty()) {
    std::cerr << "tire-game: " << err << "\n";
    return 2;
  }
  for (const std::string& w : best_runs_.open(options_.data_dir, options_.levels_dir)) warn(w);
  const bool edit = !options_.edit.empty();
  if (edit ? !open_editor(options_.edit) : !load_level(options_.level)) {
    for (const std::string& e : level_errors_) std::cerr << e << "\n";
    return 2;
  }
  if (!options_.sound.log_file.empty()) {
    if (const std::string err = sound_.open_log(options_.sound.log_file); !err.empty()) {
      std::cerr << "tire-game: " << err << "\n";
      return 2;
    }
  }
  if (!open_window()) return 1;
  // SDL drops a pad's events while no window has the keyboard focus, which an offscreen window
  // never gets: a scripted pad (headless tests) takes them anyway.
  if (!options_.pads.empty()) SDL_SetHint(SDL_HINT_JOYSTICK_ALLOW_BACKGROUND_EVENTS, "1");
  if (const std::string err = gamepads_.init(); !err.empty()) warn("game controllers unavailable: " + err);
  if (!options_.pads.empty()) {
    for (const PadPress& p : options_.pads) virtual_pad_.add(p);
    if (!virtual_pad_.connects_later()) {
      if (const std::string err = virtual_pad_.attach(); !err.empty()) {
        std::cerr << "tire-game: --pad: " << err << "\n";
        return 1;
      }
      SDL_PumpEvents();  // SDL takes in the pad at rest before the script moves it
    }
  }
  for (const std::string& problem : sound_.open(options_.sound)) warn(problem);
  if (!edit) after_level_change();
  levels_ = scan_levels(options_.levels_dir);

  // Room for every frame's times before the loop starts, so that recording them never allocates.
  frame_stats_.reserve(options_.frames
                           ? static_cast<std::size_t>(std::min<long long>(*options_.frames, kFrameSamples))
                           : kFrameSamplesInteractive);
  run_start_ = SDL_GetPerformanceCounter();
  return std::nullopt;
}

bool App::frame() {
  if (options_.frames && frame_ >= *options_.frames) return false;
  const Uint64 frame_start = SDL_GetPerformanceCounter();
  // A scripted pad moves before SDL reads its devices (in SDL_PollEvent), as a real one would.
  if (const std::string err = virtual_pad_.apply(frame_); !err.empty()) warn("--pad: " + err);
  // Scripted keys go through SDL's queue, exactly like real ones.
  for (const ScriptedKey& k : options_.keys.events_at(frame_)) {
    SDL_Event e{};
    SDL_SetModState(static_cast<SDL_Keymod>(k.down ? k.mod : Uint16{KMOD_NONE}));
    e.type = k.down ? SDL_KEYDOWN : SDL_KEYUP;
    e.key.state = k.down ? SDL_PRESSED : SDL_RELEASED;
    e.key.windowID = SDL_GetWindowID(window_);
    e.key.keysym.scancode = k.key;
    e.key.keysym.sym = SDL_GetKeyFromScancode(k.key);
    e.key.keysym.mod = k.mod;
    SDL_PushEvent(&e);
  }
  SDL_Event e;
  while (SDL_PollEvent(&e)) handle_event(e);
  imgui_->new_frame();
  if (editing_) {
    clicks_.clear();
    for (const SDL_Event& mouse : std::exchange(editor_mouse_, {}))
      editor_->handle_event(mouse, imgui_->wants_mouse(), imgui_->wants_keyboard());
  } else {
    take_clicks();
    session_.flush();  // spawns, grabs, tuning and loads apply now, between ticks
    if (session_.generation() != seen_generation_) after_level_change();
  }

  now_ = seconds_since(run_start_);
  const double wall = std::clamp(now_ - last_wall_, 0.0, 0.25);
  last_wall_ = now_;
  if (wall > 0.0) fps_ = fps_ == 0.0 ? 1.0 / wall : fps_ * 0.95 + 0.05 / wall;
  // --frames: every frame is exactly one tick, so automated runs are reproducible.
  const double frame_seconds =
      options_.frames ? (session_.loaded() ? session_.simulation().config().dt : 1.0 / 60.0) : wall;
  sound_.set_paused(editing_ || paused_ || menu_open_);
  if (!editing_) advance(frame_seconds);
  physics_ms_ = physics_ms_ * 0.9 + 0.1 * frame_physics_seconds_ * 1000.0;
  if (!editing_ && hot_reload_.poll(now_)) {
    if (load_level(session_.path())) warn("reloaded " + session_.path());
  }

  const Uint64 render_start = SDL_GetPerformanceCounter();
  draw_frame(frame_seconds);  // may set quit_ (the menu's Quit)
  const double render_seconds = seconds_since(render_start);
  const bool last_frame = quit_ || (options_.frames && frame_ + 1 >= *options_.frames);
  double screenshot_seconds = 0.0;
  if (last_frame && !options_.screenshot.empty()) {
    const Uint64 shot_start = SDL_GetPerformanceCounter();
    if (const std::string err = save_screenshot(renderer_, options_.screenshot); !err.empty()) {
      std::cerr << "tire-game: cannot save the screenshot " << options_.screenshot << ": " << err << "\n";
      output_failed_ = true;
    }
    screenshot_seconds = seconds_since(shot_start);
  }
  const Uint64 present_start = SDL_GetPerformanceCounter();
  SDL_RenderPresent(renderer_);
  const double present_seconds = seconds_since(present_start);
  // The screenshot is for tests, not part of what a player waits for.
  frame_stats_.add({static_cast<float>(frame_physics_seconds_ * 1000.0),
                    static_cast<float>((render_seconds + present_seconds) * 1000.0),
                    static_cast<float>(present_seconds * 1000.0),
                    static_cast<float>((seconds_since(frame_start) - screenshot_seconds) * 1000.0)});
  ++frame_;
  if (quit_) return false;
#ifndef __EMSCRIPTEN__
  // Without vsync (or when it is not honoured), do not spin faster than ~240 frames per second.
  // (In the browser, the page's animation frames pace the loop.)
  if (!options_.frames) {
    const double spent = seconds_since(run_start_) - now_;
    if (spent < 1.0 / 240.0) SDL_Delay(static_cast<Uint32>((1.0 / 240.0 - spent) * 1000.0));
  }
#endif
  return !(options_.frames && frame_ >= *options_.frames);
}

int App::finish() {
  if (const std::string err = sound_.close_log(); !err.empty()) {
    std::cerr << "tire-game: " << err << "\n";
    output_failed_ = true;
  }
  if (!options_.record.empty()) {
    if (const std::string err = recorder_.save(session_.simulation(), options_.record); !err.empty()) {
      std::cerr << "tire-game: cannot save the replay " << options_.record << ": " << err << "\n";
      return 2;
    }
  }
  summary_ = summary_json(frame_);
  std::cout << summary_ << std::endl;
  return output_failed_ ? 2 : 0;
}

std::string App::summary_json(long long frames) const {
  nlohmann::json out;
  out["frames"] = frames;
  if (editor_) {
    const editor::LevelDocument& doc = editor_->document();
    out["editor"] = {{"file", doc.file().string()},
                     {"editing", editing_},
                     {"modified", doc.modified()},
                     {"errors", doc.errors().size()},
                     {"undo_steps", doc.history_size()}};
  }
  if (!session_.loaded()) return out.dump();
  out["level"] = session_.level().name;
  out["ticks"] = session_.simulation().tick();
  out["status"] = tire::to_string(session_.simulation().status());
  out["hash"] = tire::to_hex(session_.simulation().state_hash());
  if (const std::optional<tire::TireView> p = player_view()) {
    const tire::Vec2 c = p->centroid;
    out["player"] = {c.x, c.y};
  } else {
    out["player"] = nullptr;
  }
  out["tires"] = session_.simulation().tire_count();
  out["gamepads"] = gamepads_.connected();
  out["progress"] = best_runs_.summary(session_.path());
  if (run_result_) {
    out["finished"] = {{"status", run_result_->won ? "won" : "lost"},
                       {"reason", tire::to_string(session_.simulation().end_reason())},
                       {"tick", run_result_->ticks},
                       {"time", run_result_->time}};
  }
  out["asleep"] = session_.simulation().asleep_count();
  out["sound"] = {{"device", sound_.device_open()},
                  {"events", sound_.events()},
                  {"max_voices", sound_.max_playing()},
                  {"muted", sound_.muted()}};
  // Wall time per frame in ms (median, p99, max over the frames sampled): the simulation
  // (Simulation::step), the rendering (drawing, ImGui, present) and the whole frame.
  const auto stats = [](const TimeStats& t) {
    return nlohmann::json{{"median", t.median}, {"p99", t.p99}, {"max", t.max}};
  };
  out["frame_ms"] = {{"samples", frame_stats_.size()},
                     {"sim", stats(frame_stats_.sim())},
                     {"sim_last_600", stats(frame_stats_.sim_last(600))},
                     {"render", stats(frame_stats_.render())},
                     {"present", stats(frame_stats_.present())},
                     {"frame", stats(frame_stats_.frame())}};
  return out.dump();
}

}  // namespace game
