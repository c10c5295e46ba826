// The level editor inside the game (tire-game --edit FILE, or E while playing): the level drawn as
// it will start, with its items' outlines and handles over it; the mouse selects, moves, resizes,
// rotates and adds; an ImGui palette and property panel; undo and redo; save. The document model
// (editor/level_document.h) holds the JSON and its history; this class is its window.
#pragma once

#include <SDL.h>

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "editor/level_document.h"
#include "play/game_session.h"
#include "render/camera.h"
#include "render/draw.h"
#include "render/renderer.h"
#include "tire/io/level_format.h"

namespace game {

// What a click with the mouse does in the editor.
enum class EditTool { select, obstacle, box, circle, polygon, chain, tire, vehicle, region, goal, waypoint };

// What the editor asks of the app.
enum class EditorRequest { none, play, quit };

class Editor {
 public:
  // Opens `file` (a new level when it does not exist). Returns "" or why it cannot.
  std::string open(const std::filesystem::path& file);

  editor::LevelDocument& document() { return doc_; }
  const editor::LevelDocument& document() const { return doc_; }
  const editor::Selection& selection() const { return selection_; }
  EditTool tool() const { return tool_; }

  // Window points to output pixels (high-DPI), for mouse positions.
  void set_window_scale(double sx, double sy) {
    window_scale_x_ = sx;
    window_scale_y_ = sy;
  }
  // An SDL event ImGui did not take (`imgui_mouse`/`imgui_keyboard`: ImGui wants that device).
  void handle_event(const SDL_Event& e, bool imgui_mouse, bool imgui_keyboard);
  // Draws the level and the editor's overlay into `draw` (width × height output pixels).
  void draw(Draw& draw, WorldRenderer& renderer, int width, int height);
  // The palette, the property panel and the level's errors (ImGui).
  void draw_ui();
  // Ready to quit: asks about unsaved changes first (the answer comes as EditorRequest::quit).
  void request_quit();

  EditorRequest take_request();
  // Messages for the player's warning list (saved, refused changes, ...), taken once.
  std::vector<std::string> take_messages();
  // "Soft tire editor - 04-crates.json *" (the star: unsaved changes).
  std::string title() const;
  // Frames the whole level in the view.
  void frame_all();

 private:
  enum class Drag { none, move, box_select, pan, corner, radius, angle, point, create_box, create_circle };

  tire::Vec2 to_world(int x, int y) const;
  tire::Vec2 snapped(tire::Vec2 p) const;
  double pick_tolerance() const { return 8.0 / scale_; }  // m: eight pixels

  void key_down(const SDL_Keysym& key);
  void mouse_down(int x, int y, Uint8 button, bool shift);
  void mouse_move(int x, int y);
  void mouse_up(Uint8 button);
  void wheel(int x, int y, float amount);

  bool press_handle(tire::Vec2 p);
  void press_select(tire::Vec2 p, bool shift);
  void finish_drawing();  // a polygon or chain being clicked in
  void add_item(editor::ItemKind kind, editor::Json item);
  // One change, its refusal reported; true when the document took it as a step of its history.
  bool apply(editor::Json next, const char* what);
  void end_drag();
  void undo();
  void redo();
  void save();
  void delete_selection();
  void duplicate_selection();
  void nudge(tire::Vec2 delta);
  void set_tool(EditTool tool);

  void update_preview();
  void draw_overlay(Draw& d);
  void draw_bounds(Draw& d);
  void draw_grid(Draw& d);
  void draw_properties();
  void draw_level_properties();
  void draw_item_properties(const editor::Pick& item);

  editor::LevelDocument doc_;
  GameSession preview_;  // the level as it starts, never stepped
  std::uint64_t preview_version_ = ~0ull;
  Camera camera_;
  tire::Vec2 center_;
  double scale_ = 60.0;  // px per m
  double window_scale_x_ = 1.0, window_scale_y_ = 1.0;
  int width_ = 1280, height_ = 720;
  bool framed_ = false;

  editor::Selection selection_;
  EditTool tool_ = EditTool::select;
  bool snap_ = true;
  double grid_ = 0.25;  // m
  bool space_held_ = false;

  Drag drag_ = Drag::none;
  editor::Json drag_base_;  // the document when the drag began
  editor::Pick drag_item_;  // the item or point a handle drag changes
  int drag_corner_ = 0;
  tire::Vec2 press_world_, mouse_world_, drag_anchor_;
  int press_x_ = 0, press_y_ = 0;
  std::vector<tire::Vec2> drawing_;  // the points of a polygon or chain being clicked in

  // A property being typed into: its text or value until the field is left (ImGui keeps only its
  // own buffer), and the validator's refusal of the last value entered, by field id.
  std::map<std::string, editor::Json> pending_;
  std::map<std::string, std::string> refused_;
  bool edit_property(const std::string& id, const std::string& pointer, const tire::LevelKey& key);
  // The value a missing key shows: its default, or what the engine computes for it (a bounds corner).
  editor::Json computed_default(const std::string& pointer, const tire::LevelKey& key) const;
  float properties_width_ = 340.0f;  // as last drawn
  float palette_width_ = 180.0f;     // as last drawn
  void draw_keys(const std::string& id, const std::string& pointer, tire::LevelObject object,
                 const std::string& shape);
  // An array of level objects (a vehicle's wheels), each a tree node of its keys.
  void draw_array(const std::string& id, const std::string& pointer, const tire::LevelKey& key);

  bool confirm_quit_ = false;
  EditorRequest request_ = EditorRequest::none;
  std::vector<std::string> messages_;
};

}  // namespace game
