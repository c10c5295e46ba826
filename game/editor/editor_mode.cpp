#include "editor/editor_mode.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "editor/level_edits.h"
#include "editor/level_format.h"

namespace game {

namespace {

using editor::ItemKind;
using editor::ItemShape;
using editor::Json;
using editor::Pick;
using editor::PointSet;
using tire::Vec2;

constexpr double kHandlePixels = 7.0;                  // a handle's half size and how near counts as on it
constexpr double kRotatePixels = 36.0;                 // the rotate handle's distance beyond the item
constexpr double kMinScale = 2.0, kMaxScale = 2000.0;  // px per m

struct Handle {
  enum class Kind { corner, radius, angle, point, midpoint };
  Kind kind;
  Vec2 at;
  Pick pick;       // the item, or for point and midpoint the point (midpoint: where it is inserted)
  int corner = 0;  // Kind::corner
};

// The one item a selection is about (an item, or points of one item), if it is about one.
std::optional<Pick> single_item(const editor::Selection& s) {
  if (s.empty()) return std::nullopt;
  const Pick first = s.front().item();
  for (const Pick& p : s)
    if (p.item() != first) return std::nullopt;
  return first;
}

std::vector<Handle> handles_of(const Json& doc, const editor::Selection& selection, double scale) {
  std::vector<Handle> out;
  const auto item = single_item(selection);
  if (!item) return out;
  const auto s = editor::shape_of(doc, item->kind, item->index);
  if (!s) return out;
  using Form = ItemShape::Form;
  if (s->form == Form::box && s->outline.size() == 4)
    for (int c = 0; c < 4; ++c)
      out.push_back({Handle::Kind::corner, s->outline[static_cast<std::size_t>(c)], *item, c});
  if (s->form == Form::circle)
    out.push_back({Handle::Kind::radius, editor::to_world(*s, {s->radius, 0.0}), *item});
  if ((item->kind == ItemKind::prop || item->kind == ItemKind::vehicle) && s->form != Form::chain) {
    double extent = 0.0;
    for (const Vec2 p : s->outline) extent = std::max(extent, tire::length(p - s->position));
    out.push_back({Handle::Kind::angle, editor::to_world(*s, {0.0, extent + kRotatePixels / scale}), *item});
  }
  const auto add_points = [&](const std::vector<Vec2>& points, PointSet set, bool closed) {
    for (std::size_t i = 0; i < points.size(); ++i)
      out.push_back({Handle::Kind::point, points[i], {item->kind, item->index, set, i}});
    for (std::size_t i = 0; i + 1 < points.size() + (closed ? 1 : 0); ++i)
      out.push_back({Handle::Kind::midpoint,
                     (points[i] + points[(i + 1) % points.size()]) * 0.5,
                     {item->kind, item->index, set, i + 1}});
  };
  // A vehicle's handles are its polygon chassis' points, its wheels' axle points and its driver's
  // head, all dragged in the chassis' frame.
  if (s->form == Form::polygon || s->form == Form::chain)
    add_points(s->outline, PointSet::points, s->form == Form::polygon || s->loop);
  for (std::size_t w = 0; w < s->axles.size(); ++w)
    out.push_back({Handle::Kind::point, s->axles[w], {item->kind, item->index, PointSet::axles, w}});
  if (s->head) out.push_back({Handle::Kind::point, *s->head, {item->kind, item->index, PointSet::head, 0}});
  if (!s->waypoints.empty()) add_points(s->waypoints, PointSet::waypoints, false);
  return out;
}

// The convex hull of `points`, counter-clockwise (Andrew's monotone chain).
std::vector<Vec2> convex_hull(std::vector<Vec2> points) {
  std::sort(points.begin(), points.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  points.erase(std::unique(points.begin(), points.end()), points.end());
  if (points.size() < 3) return points;
  std::vector<Vec2> hull(2 * points.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    while (k >= 2 && tire::cross(hull[k - 1] - hull[k - 2], points[i] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i];
  }
  for (std::size_t i = points.size() - 1, t = k + 1; i > 0; --i) {
    while (k >= t && tire::cross(hull[k - 1] - hull[k - 2], points[i - 1] - hull[k - 2]) <= 0) --k;
    hull[k++] = points[i - 1];
  }
  hull.resize(k - 1);
  return hull;
}

Vec2 mean(const std::vector<Vec2>& points) {
  Vec2 sum;
  for (const Vec2 p : points) sum += p;
  return sum / static_cast<double>(std::max<std::size_t>(points.size(), 1));
}

ScreenPoint offset(ScreenPoint p, float dx, float dy) { return {p.x + dx, p.y + dy}; }

}  // namespace

std::string Editor::open(const std::filesystem::path& file) {
  if (std::string e = doc_.open(file); !e.empty()) return e;
  selection_.clear();
  drag_ = Drag::none;
  drawing_.clear();
  framed_ = false;
  preview_version_ = ~0ull;
  return "";
}

std::string Editor::title() const {
  return "Soft tire editor - " + doc_.file().filename().string() + (doc_.modified() ? " *" : "");
}

EditorRequest Editor::take_request() { return std::exchange(request_, EditorRequest::none); }

std::vector<std::string> Editor::take_messages() { return std::exchange(messages_, {}); }

void Editor::request_quit() {
  if (doc_.modified())
    confirm_quit_ = true;
  else
    request_ = EditorRequest::quit;
}

void Editor::frame_all() {
  const auto extent = editor::level_extent(doc_.json());
  const tire::Aabb box = extent ? extent->expanded(1.0) : tire::Aabb{{-6, -2}, {6, 5}};
  center_ = (box.min + box.max) * 0.5;
  // Leave room for the palette on the left and the property panel on the right.
  const double usable = std::max(width_ - 560.0, width_ * 0.5);
  scale_ = std::clamp(std::min(usable / (box.max.x - box.min.x), (height_ - 60.0) / (box.max.y - box.min.y)),
                      kMinScale, kMaxScale);
  center_.x -= (140.0 - 280.0) * 0.5 / scale_;  // the palette is narrower than the panel
}

Vec2 Editor::to_world(int x, int y) const {
  return camera_.to_world(x * window_scale_x_, y * window_scale_y_);
}

Vec2 Editor::snapped(Vec2 p) const {
  if (!snap_) return {std::round(p.x * 1000.0) / 1000.0, std::round(p.y * 1000.0) / 1000.0};
  return {std::round(p.x / grid_) * grid_, std::round(p.y / grid_) * grid_};
}

void Editor::set_tool(EditTool tool) {
  tool_ = tool;
  drawing_.clear();
  if (tool == EditTool::waypoint && !single_item(selection_))
    messages_.push_back("waypoints: select the prop whose path they make, then click where it should go");
}

// ---- Changes -------------------------------------------------------------------------------------

bool Editor::apply(Json next, const char* what) {
  const std::size_t before = doc_.history_size();
  if (const std::string e = doc_.change(std::move(next)); !e.empty())
    messages_.push_back(std::string(what) + " refused: " + e);
  return doc_.history_size() != before;  // a change to what it already is makes no step either
}

void Editor::add_item(ItemKind kind, Json item) {
  Pick added;
  const Json next = editor::with_item(doc_.json(), kind, std::move(item), added);
  if (apply(next, "adding it was")) selection_ = {added};
}

void Editor::undo() {
  if (!doc_.undo()) messages_.push_back("nothing to undo");
  selection_.clear();
}

void Editor::redo() {
  if (!doc_.redo()) messages_.push_back("nothing to redo");
  selection_.clear();
}

void Editor::save() {
  if (const std::string e = doc_.save(); !e.empty())
    messages_.push_back(e);
  else
    messages_.push_back("saved " + doc_.file().string());
}

void Editor::delete_selection() {
  if (selection_.empty()) return;
  if (apply(editor::removed(doc_.json(), selection_), "deleting it was")) selection_.clear();
}

void Editor::duplicate_selection() {
  editor::Selection copies;
  const Json next = editor::duplicated(doc_.json(), selection_, {grid_ * 2.0, grid_ * 2.0}, copies);
  if (apply(next, "duplicating was")) selection_ = copies;
}

void Editor::nudge(Vec2 delta) {
  if (!selection_.empty()) apply(editor::moved(doc_.json(), selection_, delta), "moving it was");
}

void Editor::finish_drawing() {
  const std::vector<Vec2> points = std::exchange(drawing_, {});
  if (tool_ == EditTool::polygon) {
    const std::vector<Vec2> hull = convex_hull(points);
    if (hull.size() < 3 || hull.size() > 8) {
      messages_.push_back("a polygon needs 3 to 8 corners around an area; got " +
                          std::to_string(hull.size()));
      return;
    }
    const Vec2 origin = snapped(mean(hull));
    Json local = Json::array();
    for (const Vec2 p : hull) local.push_back(editor::vec2(p - origin));
    add_item(ItemKind::prop, {{"shape", "polygon"},
                              {"type", "static"},
                              {"position", editor::vec2(origin)},
                              {"points", std::move(local)}});
  } else if (tool_ == EditTool::chain) {
    if (points.size() < 2) {
      messages_.push_back("a chain needs at least 2 points");
      return;
    }
    Json local = Json::array();
    for (const Vec2 p : points) local.push_back(editor::vec2(p - points.front()));
    add_item(ItemKind::prop,
             {{"shape", "chain"}, {"position", editor::vec2(points.front())}, {"points", std::move(local)}});
  }
  tool_ = EditTool::select;
}

// ---- Input ---------------------------------------------------------------------------------------

void Editor::handle_event(const SDL_Event& e, bool imgui_mouse, bool imgui_keyboard) {
  switch (e.type) {
    case SDL_KEYDOWN:
      if (e.key.keysym.scancode == SDL_SCANCODE_SPACE) space_held_ = true;
      if (!imgui_keyboard && !e.key.repeat) key_down(e.key.keysym);
      // Arrow keys repeat: holding one keeps nudging.
      else if (!imgui_keyboard && e.key.repeat && !selection_.empty()) {
        const double s = snap_ ? grid_ : 0.01;
        switch (e.key.keysym.scancode) {
          case SDL_SCANCODE_LEFT: nudge({-s, 0}); break;
          case SDL_SCANCODE_RIGHT: nudge({s, 0}); break;
          case SDL_SCANCODE_UP: nudge({0, s}); break;
          case SDL_SCANCODE_DOWN: nudge({0, -s}); break;
          default: break;
        }
      }
      break;
    case SDL_KEYUP:
      if (e.key.keysym.scancode == SDL_SCANCODE_SPACE) space_held_ = false;
      break;
    case SDL_MOUSEBUTTONDOWN:
      if (!imgui_mouse)
        mouse_down(e.button.x, e.button.y, e.button.button, (SDL_GetModState() & KMOD_SHIFT) != 0);
      break;
    case SDL_MOUSEMOTION: mouse_move(e.motion.x, e.motion.y); break;
    case SDL_MOUSEBUTTONUP: mouse_up(e.button.button); break;
    case SDL_MOUSEWHEEL:
      if (!imgui_mouse) {
        int x = 0, y = 0;
        SDL_GetMouseState(&x, &y);
        wheel(x, y, e.wheel.preciseY != 0.0f ? e.wheel.preciseY : static_cast<float>(e.wheel.y));
      }
      break;
    default: break;
  }
}

void Editor::key_down(const SDL_Keysym& key) {
  const bool ctrl = (key.mod & KMOD_CTRL) != 0, shift = (key.mod & KMOD_SHIFT) != 0;
  const double step = snap_ ? grid_ : 0.01;
  if (ctrl) {
    switch (key.scancode) {
      case SDL_SCANCODE_Z: shift ? redo() : undo(); break;
      case SDL_SCANCODE_Y: redo(); break;
      case SDL_SCANCODE_S: save(); break;
      case SDL_SCANCODE_D: duplicate_selection(); break;
      case SDL_SCANCODE_A: selection_ = editor::items_inside(doc_.json(), {{-1e9, -1e9}, {1e9, 1e9}}); break;
      default: break;
    }
    return;
  }
  switch (key.scancode) {
    case SDL_SCANCODE_ESCAPE:
      if (drag_ != Drag::none) {
        doc_.cancel_gesture();
        drag_ = Drag::none;
      } else if (!drawing_.empty()) {
        drawing_.clear();
      } else if (tool_ != EditTool::select) {
        tool_ = EditTool::select;
      } else {
        selection_.clear();
      }
      break;
    case SDL_SCANCODE_RETURN:
    case SDL_SCANCODE_KP_ENTER: finish_drawing(); break;
    case SDL_SCANCODE_DELETE:
    case SDL_SCANCODE_BACKSPACE: delete_selection(); break;
    case SDL_SCANCODE_LEFT: nudge({-step, 0}); break;
    case SDL_SCANCODE_RIGHT: nudge({step, 0}); break;
    case SDL_SCANCODE_UP: nudge({0, step}); break;
    case SDL_SCANCODE_DOWN: nudge({0, -step}); break;
    case SDL_SCANCODE_G: snap_ = !snap_; break;
    case SDL_SCANCODE_F: frame_all(); break;
    case SDL_SCANCODE_E:
    case SDL_SCANCODE_F6: request_ = EditorRequest::play; break;
    case SDL_SCANCODE_V: set_tool(EditTool::select); break;
    case SDL_SCANCODE_O: set_tool(EditTool::obstacle); break;
    case SDL_SCANCODE_B: set_tool(EditTool::box); break;
    case SDL_SCANCODE_C: set_tool(EditTool::circle); break;
    case SDL_SCANCODE_P: set_tool(EditTool::polygon); break;
    case SDL_SCANCODE_L: set_tool(EditTool::chain); break;
    case SDL_SCANCODE_T: set_tool(EditTool::tire); break;
    case SDL_SCANCODE_K: set_tool(EditTool::vehicle); break;
    case SDL_SCANCODE_R: set_tool(EditTool::region); break;
    case SDL_SCANCODE_X: set_tool(EditTool::goal); break;
    case SDL_SCANCODE_W: set_tool(EditTool::waypoint); break;
    default: break;
  }
}

void Editor::wheel(int x, int y, float amount) {
  // Zoom about the cursor: the point under it stays under it.
  const Vec2 before = to_world(x, y);
  scale_ = std::clamp(scale_ * std::pow(1.15, static_cast<double>(amount)), kMinScale, kMaxScale);
  camera_.set_view(center_, scale_);
  const Vec2 after = to_world(x, y);
  center_ += before - after;
}

void Editor::mouse_down(int x, int y, Uint8 button, bool shift) {
  const Vec2 p = to_world(x, y);
  press_world_ = mouse_world_ = p;
  press_x_ = x;
  press_y_ = y;
  if (button == SDL_BUTTON_MIDDLE || (button == SDL_BUTTON_LEFT && space_held_)) {
    drag_ = Drag::pan;
    return;
  }
  if (button == SDL_BUTTON_RIGHT) {
    if (!drawing_.empty()) finish_drawing();
    return;
  }
  if (button != SDL_BUTTON_LEFT) return;
  const Vec2 at = snapped(p);
  switch (tool_) {
    case EditTool::select:
      if (!press_handle(p)) press_select(p, shift);
      return;
    case EditTool::obstacle:
    case EditTool::box:
    case EditTool::region:
    case EditTool::goal:
      drag_ = Drag::create_box;
      drag_anchor_ = at;
      return;
    case EditTool::circle:
      drag_ = Drag::create_circle;
      drag_anchor_ = at;
      return;
    case EditTool::polygon:
    case EditTool::chain: drawing_.push_back(at); return;
    case EditTool::tire:
      add_item(ItemKind::tire, {{"position", editor::vec2(at)}});
      tool_ = EditTool::select;
      return;
    case EditTool::vehicle:
      // The player's, in a level that has no player yet (no tire, none marked).
      add_item(ItemKind::vehicle,
               editor::default_vehicle(at, editor::count(doc_.json(), ItemKind::tire) == 0 &&
                                               !editor::names_a_player(doc_.json())));
      tool_ = EditTool::select;
      return;
    case EditTool::waypoint: {
      const auto item = single_item(selection_);
      if (!item || item->kind != ItemKind::prop) {
        messages_.push_back("waypoints: select the prop whose path they make first");
        return;
      }
      Pick added;
      apply(editor::with_waypoint(doc_.json(), *item, at, added), "the waypoint was");
      return;
    }
  }
}

bool Editor::press_handle(Vec2 p) {
  const double reach = kHandlePixels / scale_ * 1.5;
  for (const Handle& h : handles_of(doc_.json(), selection_, scale_)) {
    if (tire::length(h.at - p) > reach) continue;
    drag_base_ = doc_.json();
    drag_item_ = h.pick;
    doc_.begin_gesture();
    switch (h.kind) {
      case Handle::Kind::corner:
        drag_ = Drag::corner;
        drag_corner_ = h.corner;
        break;
      case Handle::Kind::radius: drag_ = Drag::radius; break;
      case Handle::Kind::angle: drag_ = Drag::angle; break;
      case Handle::Kind::point:
        drag_ = Drag::point;
        if (!(SDL_GetModState() & KMOD_SHIFT)) selection_ = {h.pick};
        editor::select(selection_, h.pick);
        break;
      case Handle::Kind::midpoint:
        // Pressing a segment's middle inserts a point there, then drags it.
        drag_base_ = editor::with_point_inserted(drag_base_, h.pick, h.at);
        doc_.preview(drag_base_);
        drag_ = Drag::point;
        selection_ = {h.pick};
        break;
    }
    return true;
  }
  return false;
}

void Editor::press_select(Vec2 p, bool shift) {
  // A chain's or polygon's point, or a waypoint, is picked on its own and dragged by itself.
  if (const auto point = editor::pick_point(doc_.json(), p, kHandlePixels * 1.5 / scale_)) {
    if (!shift) selection_.clear();
    editor::select(selection_, *point);
    drag_base_ = doc_.json();
    drag_item_ = *point;
    doc_.begin_gesture();
    drag_ = Drag::point;
    return;
  }
  const auto hit = editor::pick_item(doc_.json(), p, pick_tolerance());
  if (!hit) {
    if (!shift) selection_.clear();
    drag_ = Drag::box_select;
    return;
  }
  if (shift && editor::is_selected(selection_, *hit)) {
    selection_.erase(std::find(selection_.begin(), selection_.end(), *hit));
    return;
  }
  if (!editor::is_selected(selection_, *hit)) {
    if (!shift) selection_.clear();
    editor::select(selection_, *hit);
  }
  // Moving snaps the item's reference point (its origin, hub or lower-left corner) to the grid: a
  // vehicle's is its chassis' origin.
  const auto shape = editor::shape_of(doc_.json(), hit->kind, hit->index);
  const bool corner = hit->kind == ItemKind::obstacle || hit->kind == ItemKind::region;
  drag_anchor_ = shape ? (corner && !shape->outline.empty() ? shape->outline[0] : shape->position) : p;
  drag_base_ = doc_.json();
  doc_.begin_gesture();
  drag_ = Drag::move;
}

void Editor::mouse_move(int x, int y) {
  const Vec2 p = to_world(x, y);
  const Vec2 last = mouse_world_;
  mouse_world_ = p;
  switch (drag_) {
    case Drag::pan:
      center_ -= p - last;
      camera_.set_view(center_, scale_);
      mouse_world_ = to_world(x, y);
      break;
    case Drag::move: {
      const Vec2 delta = snapped(drag_anchor_ + (p - press_world_)) - drag_anchor_;
      doc_.preview(editor::moved(drag_base_, selection_, snap_ ? delta : p - press_world_));
      break;
    }
    case Drag::corner:
      doc_.preview(editor::with_corner(drag_base_, drag_item_, drag_corner_, snapped(p)));
      break;
    case Drag::radius: {
      const auto s = editor::shape_of(drag_base_, drag_item_.kind, drag_item_.index);
      if (!s) break;
      double r = tire::length(p - s->position);
      r = snap_ ? std::max(grid_ * 0.5, std::round(r / (grid_ * 0.5)) * grid_ * 0.5) : r;
      doc_.preview(editor::with_radius(drag_base_, drag_item_, r));
      break;
    }
    case Drag::angle: {
      const auto s = editor::shape_of(drag_base_, drag_item_.kind, drag_item_.index);
      if (!s) break;
      const Vec2 d = p - s->position;
      double a = std::atan2(d.y, d.x) - std::numbers::pi / 2.0;
      // With the grid on, angles snap to 15 degrees.
      if (snap_) a = std::round(a / (std::numbers::pi / 12.0)) * (std::numbers::pi / 12.0);
      doc_.preview(editor::with_angle(drag_base_, drag_item_, a));
      break;
    }
    case Drag::point: {
      const auto s = editor::shape_of(drag_base_, drag_item_.kind, drag_item_.index);
      if (s && snap_ && drag_item_.kind == ItemKind::vehicle) {
        // A vehicle's axle point, head or polygon chassis' point moves by whole grid steps along the
        // chassis' own axes, so that [0.6, -0.3] dragged sideways stays at -0.3 and a symmetric car
        // stays symmetric.
        const Vec2 start = drag_item_.set == PointSet::head    ? s->head.value_or(s->position)
                           : drag_item_.set == PointSet::axles ? s->axles.at(drag_item_.point)
                                                               : s->outline.at(drag_item_.point);
        const Vec2 local = editor::to_local(*s, p) - editor::to_local(*s, press_world_);
        const Vec2 steps{std::round(local.x / grid_) * grid_, std::round(local.y / grid_) * grid_};
        doc_.preview(editor::with_point(drag_base_, drag_item_,
                                        editor::to_world(*s, editor::to_local(*s, start) + steps)));
        break;
      }
      doc_.preview(editor::with_point(drag_base_, drag_item_, snapped(p)));
      break;
    }
    default: break;
  }
}

void Editor::end_drag() {
  if (const std::string e = doc_.end_gesture(); !e.empty()) messages_.push_back("change refused: " + e);
}

void Editor::mouse_up(Uint8 button) {
  const Drag drag = std::exchange(drag_, Drag::none);
  if (button == SDL_BUTTON_MIDDLE || drag == Drag::pan) return;
  if (button != SDL_BUTTON_LEFT) return;
  const Vec2 end = snapped(mouse_world_);
  switch (drag) {
    case Drag::move:
    case Drag::corner:
    case Drag::radius:
    case Drag::angle:
    case Drag::point: end_drag(); break;
    case Drag::box_select: {
      const tire::Aabb box{
          {std::min(press_world_.x, mouse_world_.x), std::min(press_world_.y, mouse_world_.y)},
          {std::max(press_world_.x, mouse_world_.x), std::max(press_world_.y, mouse_world_.y)}};
      for (const Pick& p : editor::items_inside(doc_.json(), box)) editor::select(selection_, p);
      break;
    }
    case Drag::create_box: {
      Vec2 lo{std::min(drag_anchor_.x, end.x), std::min(drag_anchor_.y, end.y)};
      Vec2 hi{std::max(drag_anchor_.x, end.x), std::max(drag_anchor_.y, end.y)};
      // A click without a drag makes an item of a size that suits its kind.
      const bool clicked = hi.x - lo.x < 0.05 || hi.y - lo.y < 0.05;
      if (tool_ == EditTool::obstacle) {
        if (clicked) hi = lo + Vec2{4.0, 0.5};
        add_item(ItemKind::obstacle, {{"min", editor::vec2(lo)}, {"max", editor::vec2(hi)}});
      } else if (tool_ == EditTool::box) {
        if (clicked) lo -= Vec2{0.5, 0.5}, hi = lo + Vec2{1.0, 1.0};
        add_item(ItemKind::prop, {{"name", editor::unique_name(doc_.json(), ItemKind::prop, "crate")},
                                  {"shape", "box"},
                                  {"type", "dynamic"},
                                  {"position", editor::vec2((lo + hi) * 0.5)},
                                  {"size", editor::vec2(hi - lo)}});
      } else {
        if (clicked) hi = lo + Vec2{2.0, 2.0};
        const bool goal = tool_ == EditTool::goal;
        const std::string name = editor::unique_name(doc_.json(), ItemKind::region, goal ? "goal" : "region");
        Pick added;
        Json next =
            editor::with_item(doc_.json(), ItemKind::region,
                              {{"name", name}, {"min", editor::vec2(lo)}, {"max", editor::vec2(hi)}}, added);
        if (goal) next["goal"] = name;
        if (apply(std::move(next), "the region was")) selection_ = {added};
      }
      tool_ = EditTool::select;
      break;
    }
    case Drag::create_circle: {
      const double r = tire::length(end - drag_anchor_);
      add_item(ItemKind::prop, {{"shape", "circle"},
                                {"type", "dynamic"},
                                {"position", editor::vec2(drag_anchor_)},
                                {"radius", editor::number(r < 0.05 ? 0.5 : r)}});
      tool_ = EditTool::select;
      break;
    }
    default: break;
  }
}

// ---- Drawing -------------------------------------------------------------------------------------

void Editor::update_preview() {
  if (preview_version_ == doc_.version()) return;
  preview_version_ = doc_.version();
  // The last level that validated stays on screen while the document does not.
  if (doc_.level()) preview_.start(doc_.file().string(), doc_.level());
}

void Editor::draw(Draw& d, WorldRenderer& renderer, int width, int height) {
  width_ = width;
  height_ = height;
  if (!framed_) {
    frame_all();
    framed_ = true;
  }
  camera_.resize(width, height);
  camera_.set_view(center_, scale_);
  update_preview();
  if (preview_.loaded()) {
    renderer.set_underground(underground(preview_.simulation()));
    DebugOptions plain;
    renderer.draw(d, camera_, preview_, 1.0, plain);
  } else {
    d.vertical_gradient(width, height, rgba(92, 148, 206), rgba(196, 222, 240));
  }
  draw_grid(d);
  draw_overlay(d);
  d.flush();
}

void Editor::draw_grid(Draw& d) {
  if (!snap_) return;
  // A line every grid step, or every fifth, tenth, ... when the steps would crowd the screen.
  double step = grid_;
  while (step * scale_ < 12.0) step *= 5.0;
  const tire::Aabb view = camera_.view();
  const SDL_Color minor = rgba(255, 255, 255, 28), major = rgba(255, 255, 255, 60);
  for (double x = std::floor(view.min.x / step) * step; x <= view.max.x; x += step) {
    const bool axis = std::fabs(std::remainder(x, step * 4.0)) < step * 0.5;
    d.line(camera_.to_screen({x, view.min.y}), camera_.to_screen({x, view.max.y}), 1.0f,
           axis ? major : minor);
  }
  for (double y = std::floor(view.min.y / step) * step; y <= view.max.y; y += step) {
    const bool axis = std::fabs(std::remainder(y, step * 4.0)) < step * 0.5;
    d.line(camera_.to_screen({view.min.x, y}), camera_.to_screen({view.max.x, y}), 1.0f,
           axis ? major : minor);
  }
}

// The level's bounds (levels/README.md "bounds"), as the last level that validated has them: the
// world outside them tinted, their edge drawn, and a label saying whether they are the level's own
// or computed. A computed top is open: the tint and the sides go up out of the view.
void Editor::draw_bounds(Draw& d) {
  if (!doc_.level()) return;
  const tire::LevelInfo& info = doc_.info();
  const tire::Aabb& box = info.bounds;
  const tire::Aabb view = camera_.view();
  const tire::Vec2 lo{std::max(box.min.x, view.min.x - 1.0), std::max(box.min.y, view.min.y - 1.0)};
  const tire::Vec2 hi{std::min(box.max.x, view.max.x + 1.0), std::min(box.max.y, view.max.y + 1.0)};
  const SDL_Color outside = rgba(120, 0, 0, 60), edge = rgba(230, 60, 50, 220);
  const auto rect = [&](tire::Vec2 a, tire::Vec2 b) {
    if (a.x < b.x && a.y < b.y) d.rect(camera_.to_screen(a), camera_.to_screen(b), outside);
  };
  const tire::Vec2 vlo = view.min - tire::Vec2{1, 1}, vhi = view.max + tire::Vec2{1, 1};
  rect(vlo, {vhi.x, std::min(lo.y, vhi.y)});           // below
  rect({vlo.x, std::max(hi.y, vlo.y)}, vhi);           // above
  rect({vlo.x, lo.y}, {std::min(lo.x, vhi.x), hi.y});  // left
  rect({std::max(hi.x, vlo.x), lo.y}, {vhi.x, hi.y});  // right
  if (lo.x >= hi.x || lo.y >= hi.y) return;
  const ScreenPoint a = camera_.to_screen(lo), b = camera_.to_screen(hi);
  if (box.min.y >= view.min.y) d.line(a, {b.x, a.y}, 2.0f, edge);
  if (box.max.y <= view.max.y) d.line({a.x, b.y}, b, 2.0f, edge);
  if (box.min.x >= view.min.x) d.line(a, {a.x, b.y}, 2.0f, edge);
  if (box.max.x <= view.max.x) d.line({b.x, a.y}, b, 2.0f, edge);
  char label[96];
  std::snprintf(label, sizeof label, "bounds (%s)",
                info.bounds_min_given && info.bounds_max_given ? "the level's"
                : info.bounds_min_given || info.bounds_max_given
                    ? "partly computed"
                    : "computed: margin below and beside the level");
  ImGui::GetBackgroundDrawList()->AddText(
      {std::max(a.x, palette_width_ + 10.0f) + 6, std::min(a.y, static_cast<float>(height_) - 30.0f) - 20},
      IM_COL32(255, 120, 110, 255), label);
}

void Editor::draw_overlay(Draw& d) {
  const Json& doc = doc_.json();
  const SDL_Color outline = rgba(255, 255, 255, 110), chosen = rgba(255, 170, 40),
                  region = rgba(90, 200, 255, 60), goal = rgba(90, 255, 120, 70),
                  path = rgba(255, 230, 120, 200);
  const std::string goal_name = editor::string_at(doc, "goal", "");
  ImDrawList* labels = ImGui::GetBackgroundDrawList();  // under the panels
  const auto screen = [this](const std::vector<Vec2>& points) {
    std::vector<ScreenPoint> out;
    for (const Vec2 p : points) out.push_back(camera_.to_screen(p));
    return out;
  };
  for (const ItemKind kind :
       {ItemKind::obstacle, ItemKind::region, ItemKind::prop, ItemKind::tire, ItemKind::vehicle}) {
    for (std::size_t i = 0; i < editor::count(doc, kind); ++i) {
      const auto s = editor::shape_of(doc, kind, i);
      if (!s || s->outline.empty()) continue;
      const bool selected = editor::is_selected(selection_, {kind, i});
      const std::vector<ScreenPoint> pts = screen(s->outline);
      if (kind == ItemKind::region) {
        const std::string name = editor::string_at(doc[editor::array_key(kind)][i], "name", "");
        d.rect(pts[0], pts[2], name == goal_name && !name.empty() ? goal : region);
        labels->AddText({pts[3].x + 4, pts[3].y + 2}, IM_COL32(255, 255, 255, 220),
                        (name == goal_name && !name.empty() ? name + " (goal)" : name).c_str());
      }
      const bool open = s->form == ItemShape::Form::chain && !s->loop;
      d.polyline(pts, !open, selected ? 3.0f : 1.0f, selected ? chosen : outline);
      // A vehicle's wheels and head, each joined to the chassis' origin by a thin line.
      const auto ring = [&](Vec2 c, double r) {
        std::vector<ScreenPoint> circle;
        for (int k = 0; k < 32; ++k) {
          const double a = 2.0 * std::numbers::pi * k / 32;
          circle.push_back(camera_.to_screen(c + Vec2{std::cos(a), std::sin(a)} * r));
        }
        d.polyline(circle, true, selected ? 2.0f : 1.0f, selected ? chosen : outline);
        d.line(camera_.to_screen(s->position), camera_.to_screen(c), 1.0f, selected ? chosen : outline);
      };
      for (std::size_t w = 0; w < s->axles.size() && w < s->wheel_radii.size(); ++w)
        ring(s->axles[w], s->wheel_radii[w]);
      if (s->head) ring(*s->head, s->head_radius);
      if (!s->waypoints.empty()) {
        std::vector<Vec2> route{s->position};
        route.insert(route.end(), s->waypoints.begin(), s->waypoints.end());
        d.polyline(screen(route), false, 1.5f, path);
      }
    }
  }
  draw_bounds(d);
  // Handles of the one selected item.
  const float h = static_cast<float>(kHandlePixels) * 0.5f;
  for (const Handle& handle : handles_of(doc, selection_, scale_)) {
    const ScreenPoint c = camera_.to_screen(handle.at);
    const bool on = editor::is_selected(selection_, handle.pick) && handle.pick.is_point();
    switch (handle.kind) {
      case Handle::Kind::midpoint: d.circle(c, h * 0.8f, rgba(255, 255, 255, 150), 12); break;
      case Handle::Kind::angle: {
        const auto item = single_item(selection_);
        const auto s = editor::shape_of(doc, item->kind, item->index);
        d.line(camera_.to_screen(s->position), c, 1.0f, chosen);
        d.circle(c, h + 1.0f, chosen, 16);
        break;
      }
      default:
        d.rect(offset(c, -h - 1, -h - 1), offset(c, h + 1, h + 1), rgba(30, 30, 30));
        d.rect(offset(c, -h, -h), offset(c, h, h), on ? rgba(255, 60, 60) : chosen);
        break;
    }
  }
  // What a drag is making.
  const Vec2 end = snapped(mouse_world_);
  if (drag_ == Drag::box_select)
    d.rect_outline(camera_.to_screen(press_world_), camera_.to_screen(mouse_world_), 1.0f,
                   rgba(255, 255, 255, 200));
  if (drag_ == Drag::create_box)
    d.rect_outline(camera_.to_screen(drag_anchor_), camera_.to_screen(end), 2.0f, chosen);
  if (drag_ == Drag::create_circle)
    d.circle(camera_.to_screen(drag_anchor_), camera_.pixels(tire::length(end - drag_anchor_)),
             rgba(255, 170, 40, 90), 32);
  if (!drawing_.empty()) {
    std::vector<Vec2> points = drawing_;
    points.push_back(end);
    if (tool_ == EditTool::polygon) points = convex_hull(points);
    d.polyline(screen(points), tool_ == EditTool::polygon, 2.0f, chosen);
  }
}

}  // namespace game
