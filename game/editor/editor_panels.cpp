// The editor's ImGui windows: the palette of tools, the property panel of the selection (every key
// the level reference lists for it, from the level key table), the level's errors and the question
// asked before quitting with unsaved changes.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstring>

#include "editor/editor_mode.h"
#include "editor/level_edits.h"
#include "tire/io/level_format.h"

namespace game {

namespace {

using editor::ItemKind;
using editor::Json;
using tire::KeyType;
using tire::LevelKey;
using tire::LevelObject;

struct ToolButton {
  EditTool tool;
  const char* label;
  const char* key;
  const char* help;
};
constexpr ToolButton kTools[] = {
    {EditTool::select, "Select", "V",
     "click selects, Shift adds, drag moves; drag on empty space box-selects"},
    {EditTool::obstacle, "Obstacle", "O", "drag a static box (a click makes a 4 x 0.5 m one)"},
    {EditTool::box, "Crate", "B", "drag a dynamic box prop"},
    {EditTool::circle, "Circle", "C", "click the centre, drag the radius"},
    {EditTool::polygon, "Polygon", "P", "click the corners (their convex hull), Enter or right click ends"},
    {EditTool::chain, "Chain", "L",
     "click terrain points left to right (solid below), Enter or right click ends"},
    {EditTool::tire, "Tire", "T", "click to place a tire; the first is the player"},
    {EditTool::vehicle, "Vehicle", "K",
     "click to place a car (its chassis' centre); in a level without a player it is the player.\n"
     "Selected: drag it whole, its square handles move each wheel's axle, the driver's head and a\n"
     "polygon chassis' points"},
    {EditTool::region, "Region", "R", "drag a named region for the script"},
    {EditTool::goal, "Goal", "X", "drag the region the player must reach to win"},
    {EditTool::waypoint, "Waypoint", "W", "with a prop selected, each click adds a waypoint to its path"},
};

LevelObject object_of(ItemKind kind) {
  switch (kind) {
    case ItemKind::obstacle: return LevelObject::obstacle;
    case ItemKind::region: return LevelObject::region;
    case ItemKind::prop: return LevelObject::prop;
    case ItemKind::tire: return LevelObject::tire;
    case ItemKind::vehicle: return LevelObject::vehicle;
  }
  return LevelObject::root;
}

// A key's label in the panel: its name and a short unit, "angular_velocity (rad/s)". A unit that is
// a phrase ("(times the rest area)", "segments per substep") is left to the tooltip's range line.
std::string label_of(const LevelKey& key) {
  const bool short_unit =
      !key.unit.empty() && key.unit.size() <= 8 && key.unit.find_first_of("( ") == std::string::npos;
  return key.key + (short_unit ? " (" + key.unit + ")" : "");
}

// `in_force`: the default as it stands for this object (a material preset's, a followed key's).
std::string tooltip(const LevelKey& key, const Json& in_force) {
  std::string text = key.description;
  switch (key.type) {
    case KeyType::number:
    case KeyType::integer:
    case KeyType::vec2:
    case KeyType::points:
      text += "\nrange " + tire::range_for_docs(key.range) + (key.unit.empty() ? "" : " " + key.unit);
      break;
    default: break;
  }
  if (key.required)
    text += "\nrequired";
  else if (!in_force.is_null())
    text += "\ndefault " + in_force.dump();
  return text;
}

std::string tooltip(const LevelKey& key) { return tooltip(key, key.default_value); }

// The property panel is a table: each key's label in the first column, wrapped to it rather than
// cut, and its field filling the second.
class PropertyTable {
 public:
  explicit PropertyTable(std::string id) : id_(std::move(id)) {}
  ~PropertyTable() { end(); }
  PropertyTable(const PropertyTable&) = delete;
  PropertyTable& operator=(const PropertyTable&) = delete;
  // Starts a row (and the table, when it is not open): the label's column is current.
  void row() {
    if (!open_) {
      open_ = ImGui::BeginTable(id_.c_str(), 2, ImGuiTableFlags_SizingStretchProp);
      if (open_) {
        ImGui::TableSetupColumn("key", ImGuiTableColumnFlags_WidthStretch, 0.45f);
        ImGui::TableSetupColumn("value", ImGuiTableColumnFlags_WidthStretch, 0.55f);
      }
    }
    if (!open_) return;
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
  }
  void value_column() {
    if (open_) ImGui::TableSetColumnIndex(1);
  }
  // Closes the table before something that spans the panel (a tree node).
  void end() {
    if (open_) ImGui::EndTable();
    open_ = false;
    ++part_;
    id_ += "+";
  }

 private:
  std::string id_;
  bool open_ = false;
  int part_ = 0;
};

// A level's first medals, from its time limit (60 s without one): gold within a third of it, silver
// within half, bronze within three quarters, in half seconds from 10 s up; the author tunes them.
Json starting_medals(const Json& level) {
  const auto it = level.find("time_limit");
  const double limit = it != level.end() && it->is_number() ? it->get<double>() : 60.0;
  const auto share = [limit](double s) {
    return limit >= 10.0 ? std::round(limit * s * 2.0) / 2.0 : limit * s;
  };
  return Json{{"gold", share(1.0 / 3.0)}, {"silver", share(0.5)}, {"bronze", share(0.75)}};
}

}  // namespace

// One key's field. Returns true when a value was entered (and committed or refused).
bool Editor::edit_property(const std::string& id, const std::string& pointer, const LevelKey& key) {
  const Json::json_pointer where(pointer);
  const Json& object = doc_.json().at(where);
  const auto it = object.find(key.key);
  const bool present = it != object.end();
  const Json in_force = computed_default(pointer, key);
  const Json current = present ? *it : in_force;
  const std::string label = "##" + id;
  std::optional<Json> entered;
  const auto pending = pending_.find(id);
  // The label, in the first column; a key the level does not give is greyed, field and all.
  if (!present) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  ImGui::TextWrapped("%s", label_of(key).c_str());
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(key, in_force).c_str());
  if (ImGui::TableGetColumnCount() > 1) ImGui::TableSetColumnIndex(1);  // none: the panel is collapsed
  const bool resettable = present && !key.required && key.type != KeyType::points;
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::SetNextItemWidth(
      resettable ? -(ImGui::CalcTextSize("x").x + 2.0f * style.FramePadding.x + style.ItemSpacing.x) : -1.0f);
  switch (key.type) {
    case KeyType::number:
    case KeyType::integer: {
      double v = (pending != pending_.end() ? pending->second : current).is_number()
                     ? (pending != pending_.end() ? pending->second : current).get<double>()
                     : 0.0;
      if (key.type == KeyType::integer) {
        int i = static_cast<int>(v);
        if (ImGui::InputInt(label.c_str(), &i)) pending_[id] = i;
      } else if (ImGui::InputDouble(label.c_str(), &v, 0.0, 0.0, "%.6g")) {
        pending_[id] = editor::number(v);
      }
      if (ImGui::IsItemDeactivatedAfterEdit() && pending_.contains(id)) entered = pending_[id];
      break;
    }
    case KeyType::vec2: {
      const Json& shown = pending != pending_.end() ? pending->second : current;
      double v[2] = {
          shown.is_array() && shown.size() == 2 && shown[0].is_number() ? shown[0].get<double>() : 0.0,
          shown.is_array() && shown.size() == 2 && shown[1].is_number() ? shown[1].get<double>() : 0.0};
      if (ImGui::InputScalarN(label.c_str(), ImGuiDataType_Double, v, 2, nullptr, nullptr, "%.6g")) {
        // "inf" (a computed bound's open top, as shown) or a typed "nan" becomes the range's end.
        for (double& c : v)
          if (!std::isfinite(c)) c = c < 0.0 ? key.range.min : key.range.max;
        pending_[id] = editor::vec2({v[0], v[1]});
      }
      if (ImGui::IsItemDeactivatedAfterEdit() && pending_.contains(id)) entered = pending_[id];
      break;
    }
    case KeyType::boolean: {
      bool b = current.is_boolean() && current.get<bool>();
      if (ImGui::Checkbox(label.c_str(), &b)) entered = b;
      break;
    }
    case KeyType::choice: {
      const std::string now = current.is_string() ? current.get<std::string>() : "";
      if (ImGui::BeginCombo(label.c_str(), now.c_str())) {
        for (const std::string& c : key.choices)
          if (ImGui::Selectable(c.c_str(), c == now)) entered = c;
        ImGui::EndCombo();
      }
      break;
    }
    case KeyType::string: {
      std::string text = pending != pending_.end() && pending->second.is_string()
                             ? pending->second.get<std::string>()
                         : current.is_string() ? current.get<std::string>()
                                               : "";
      char buffer[2048];
      std::snprintf(buffer, sizeof buffer, "%s", text.c_str());
      if (ImGui::InputText(label.c_str(), buffer, sizeof buffer)) pending_[id] = std::string(buffer);
      if (ImGui::IsItemDeactivatedAfterEdit() && pending_.contains(id)) entered = pending_[id];
      break;
    }
    case KeyType::points:
      ImGui::TextWrapped("%zu points (drag them in the view)", present && it->is_array() ? it->size() : 0);
      break;
    case KeyType::object:
    case KeyType::array: break;
  }
  if (!present) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(key, in_force).c_str());
  if (resettable) {
    ImGui::SameLine();
    if (ImGui::SmallButton(("x##reset" + id).c_str())) {
      Json next = doc_.json();
      next.at(where).erase(key.key);
      apply(std::move(next), "removing the key was");
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("back to the default");
  }
  if (!entered) return false;
  pending_.erase(id);
  Json next = doc_.json();
  next.at(where)[key.key] = *entered;
  if (std::string e = doc_.change(std::move(next)); !e.empty()) {
    // "FILE: /props/0/density: must be ...": the panel's field says which file and key.
    const std::string file = doc_.file().string() + ": ";
    if (e.starts_with(file)) e.erase(0, file.size());
    refused_[id] = std::move(e);
  } else
    refused_.erase(id);
  return true;
}

void Editor::draw_keys(const std::string& id, const std::string& pointer, LevelObject object,
                       const std::string& shape) {
  const Json::json_pointer where(pointer);
  PropertyTable table("##keys" + id);
  for (const LevelKey& key : tire::level_keys(object)) {
    if ((object == LevelObject::prop || object == LevelObject::chassis) && !shape.empty() &&
        !tire::applies_to_shape(key, shape))
      continue;
    if (key.key == "$schema") continue;
    const std::string field = id + "/" + key.key;
    if (key.type == KeyType::object && key.nested) {
      table.end();  // a nested object spans the panel, its keys in a table of their own
      const Json& parent = doc_.json().at(where);
      const bool present = parent.contains(key.key) && parent[key.key].is_object();
      if (object == LevelObject::prop && key.key == "path" && !present)
        continue;  // the Waypoint tool adds one
      if (ImGui::TreeNode((key.key + "##" + field).c_str())) {
        if (!present) {
          if (ImGui::SmallButton(("set##" + field).c_str())) {
            Json next = doc_.json();
            next.at(where)[key.key] = *key.nested == LevelObject::medals ? starting_medals(doc_.json())
                                      : *key.nested == LevelObject::head
                                          ? editor::default_vehicle({}, false)["head"]  // it needs both keys
                                          : Json::object();
            apply(std::move(next), "adding it was");
          }
          ImGui::SameLine();
          ImGui::TextDisabled(*key.nested == LevelObject::bounds ? "(computed from the level)"
                                                                 : "(defaults)");
        } else {
          // A chassis shows the keys of its shape, as a prop does.
          const std::string nested_shape =
              *key.nested == LevelObject::chassis ? editor::string_at(parent[key.key], "shape", "box") : "";
          draw_keys(field, pointer + "/" + key.key, *key.nested, nested_shape);
        }
        ImGui::TreePop();
      }
      continue;
    }
    if (key.type == KeyType::array && key.nested && object != LevelObject::root) {
      // A vehicle's wheels: one node each, with its keys, and a button to add one like the last.
      table.end();
      draw_array(field, pointer, key);
      continue;
    }
    if (key.type == KeyType::array || key.type == KeyType::object) continue;  // counters: kept as written
    if (key.key == "goal" && object == LevelObject::root) {
      // The goal names a region: chosen from them.
      const std::string now = editor::string_at(doc_.json(), "goal", "");
      table.row();
      ImGui::TextWrapped("goal");
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(key).c_str());
      table.value_column();
      ImGui::SetNextItemWidth(-1.0f);
      if (ImGui::BeginCombo("##goal/root", now.empty() ? "(none)" : now.c_str())) {
        Json next = doc_.json();
        bool chosen = false;
        if (ImGui::Selectable("(none)", now.empty())) next.erase("goal"), chosen = true;
        for (std::size_t i = 0; i < editor::count(doc_.json(), ItemKind::region); ++i) {
          const std::string name = editor::string_at(doc_.json()["regions"][i], "name", "");
          if (!name.empty() && ImGui::Selectable(name.c_str(), name == now))
            next["goal"] = name, chosen = true;
        }
        if (chosen) apply(std::move(next), "the goal was");
        ImGui::EndCombo();
      }
      continue;
    }
    table.row();
    edit_property(field, pointer, key);
    if (const auto r = refused_.find(field); r != refused_.end()) {
      table.end();  // the refusal spans the panel, under its field
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.45f, 0.4f, 1.0f});
      ImGui::TextWrapped("%s", r->second.c_str());
      ImGui::PopStyleColor();
    }
  }
}

void Editor::draw_array(const std::string& id, const std::string& pointer, const LevelKey& key) {
  const Json& parent = doc_.json().at(Json::json_pointer(pointer));
  const auto it = parent.find(key.key);
  const std::size_t n = it != parent.end() && it->is_array() ? it->size() : 0;
  const std::string singular = key.key.ends_with("s") ? key.key.substr(0, key.key.size() - 1) : key.key;
  for (std::size_t i = 0; i < n; ++i) {
    const std::string field = id + "/" + std::to_string(i);
    const std::string where = pointer + "/" + key.key + "/" + std::to_string(i);
    if (ImGui::TreeNode((singular + " " + std::to_string(i) + "##" + field).c_str())) {
      draw_keys(field, where, *key.nested, "");
      if (ImGui::SmallButton(("remove##" + field).c_str())) {
        Json next = doc_.json();
        next.at(Json::json_pointer(pointer + "/" + key.key)).erase(i);
        if (apply(std::move(next), "removing it was")) selection_ = {selection_.front().item()};
      }
      ImGui::TreePop();
    }
  }
  if (n > 0 && ImGui::SmallButton(("add a " + singular + "##" + id).c_str())) {
    // A copy of the last, its axle (a wheel's) a little behind it.
    Json next = doc_.json();
    Json& items = next.at(Json::json_pointer(pointer + "/" + key.key));
    Json copy = items.back();
    if (copy.is_object() && copy.contains("axle"))
      copy["axle"] = editor::vec2(editor::vec2_at(copy, "axle", {}) + tire::Vec2{-0.5, 0.0});
    items.push_back(std::move(copy));
    apply(std::move(next), "adding it was");
  }
}

void Editor::draw_level_properties() {
  ImGui::TextUnformatted("Level");
  draw_keys("root", "", LevelObject::root, "");
  const Json& doc = doc_.json();
  ImGui::Separator();
  for (const char* key : {"tires", "vehicles", "obstacles", "props", "regions", "counters", "triggers"}) {
    const auto it = doc.find(key);
    ImGui::TextDisabled(
        "%s: %zu%s", key, it != doc.end() && it->is_array() ? it->size() : 0,
        std::strcmp(key, "counters") == 0 || std::strcmp(key, "triggers") == 0 ? " (kept as written)" : "");
  }
}

void Editor::draw_item_properties(const editor::Pick& item) {
  const Json& doc = doc_.json();
  ImGui::TextWrapped("%s", editor::describe(doc, item.kind, item.index).c_str());
  const std::string pointer =
      std::string("/") + editor::array_key(item.kind) + "/" + std::to_string(item.index);
  const std::string shape =
      item.kind == ItemKind::prop
          ? editor::string_at(doc[editor::array_key(item.kind)][item.index], "shape", "box")
          : "";
  if (item.kind == ItemKind::vehicle) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextWrapped(
        "drag it whole; its square handles: each wheel's axle, the driver's head, a polygon chassis' points");
    ImGui::PopStyleColor();
  }
  draw_keys(pointer, pointer, object_of(item.kind), shape);
}

Json Editor::computed_default(const std::string& pointer, const LevelKey& key) const {
  // A bounds corner the level does not give: the one in force, computed from the level.
  if (pointer == "/bounds" && (key.key == "min" || key.key == "max") && doc_.level()) {
    const tire::Aabb& box = doc_.info().bounds;
    const tire::Vec2 v = key.key == "min" ? box.min : box.max;
    return Json::array({v.x, v.y});
  }
  const tire::TunableParameter* row = tire::find_tunable_parameter(key.parameter);
  if (!row) return key.default_value;
  // A default that follows another key (a tire's kinetic_friction: its friction) shows that key's,
  // when the object gives it.
  const std::string_view follows = row->default_follows;
  if (!follows.empty() && doc_.json().contains(Json::json_pointer(pointer))) {
    const std::string field(follows.substr(follows.rfind('.') + 1));
    const Json& object = doc_.json().at(Json::json_pointer(pointer));
    if (const auto it = object.find(field); it != object.end()) return *it;
  }
  // A tire that names a material preset: the preset's value, where it sets the key (as the level
  // reader applies it: tire/io/level_format.h).
  // A vehicle's wheel likewise ("/vehicles/0/wheels/1", or its compliance below it).
  std::optional<Json::json_pointer> tire_pointer;
  if (pointer.starts_with("/tires/"))
    tire_pointer =
        Json::json_pointer(pointer.substr(0, pointer.find('/', std::string_view("/tires/").size())));
  else if (const std::size_t w = pointer.find("/wheels/");
           pointer.starts_with("/vehicles/") && w != std::string::npos)
    tire_pointer =
        Json::json_pointer(pointer.substr(0, pointer.find('/', w + std::string_view("/wheels/").size())));
  if (tire_pointer) {
    if (doc_.json().contains(*tire_pointer))
      if (const tire::MaterialPreset* m =
              tire::find_material_preset(editor::string_at(doc_.json().at(*tire_pointer), "material", "")))
        if (const std::optional<double> v = m->value(row->key)) return *v;
  }
  if (!follows.empty())
    if (const tire::TunableParameter* p = tire::find_tunable_parameter(follows)) return p->default_value;
  return key.default_value;
}

void Editor::draw_properties() {
  std::optional<editor::Pick> item;
  if (!selection_.empty()) {
    item = selection_.front().item();
    for (const editor::Pick& p : selection_)
      if (p.item() != *item) item.reset();
  }
  // 28 % of the window: at 1280 px wide, 360 px, which holds a label and a field side by side.
  properties_width_ = std::clamp(0.28f * static_cast<float>(width_), 340.0f, 480.0f);
  ImGui::SetNextWindowPos({static_cast<float>(width_) - properties_width_ - 10.0f, 10.0f}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({properties_width_, static_cast<float>(height_) - 20.0f}, ImGuiCond_Always);
  ImGui::Begin("Properties", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  if (selection_.empty())
    draw_level_properties();
  else if (item && editor::shape_of(doc_.json(), item->kind, item->index))
    draw_item_properties(*item);
  else
    ImGui::Text("%zu selected", selection_.size());
  ImGui::End();
}

void Editor::draw_ui() {
  ImGui::SetNextWindowPos({10.0f, 10.0f}, ImGuiCond_Always);
  ImGui::Begin("Editor", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize);
  for (const ToolButton& t : kTools) {
    const bool on = tool_ == t.tool;
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button((std::string(t.label) + "  " + t.key).c_str(), {170.0f, 0.0f})) set_tool(t.tool);
    if (on) ImGui::PopStyleColor();
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", t.help);
  }
  ImGui::Separator();
  ImGui::Checkbox("snap to grid (G)", &snap_);
  ImGui::PushItemWidth(80.0f);
  double g = grid_;
  if (ImGui::InputDouble("step (m)", &g, 0.0, 0.0, "%.3g") && g >= 0.01 && g <= 10.0) grid_ = g;
  ImGui::PopItemWidth();
  ImGui::Separator();
  if (ImGui::Button("Undo", {82.0f, 0.0f})) undo();
  ImGui::SameLine();
  if (ImGui::Button("Redo", {82.0f, 0.0f})) redo();
  if (ImGui::Button("Save  Ctrl+S", {170.0f, 0.0f})) save();
  if (ImGui::Button("Play  E", {170.0f, 0.0f})) request_ = EditorRequest::play;
  ImGui::TextDisabled(
      "wheel: zoom at the cursor\nmiddle or Space+drag: pan\nF: frame the level\nDel: delete, Ctrl+D: copy\n"
      "arrows: nudge a grid step\nCtrl+Z / Ctrl+Y: undo / redo");
  palette_width_ = ImGui::GetWindowWidth();
  ImGui::End();

  draw_properties();

  if (!doc_.errors().empty()) {
    // Between the palette and the property panel, each error wrapped to the window's width.
    const float left = palette_width_ + 20.0f;
    const float width = std::max(200.0f, static_cast<float>(width_) - left - properties_width_ - 30.0f);
    ImGui::SetNextWindowPos({left, static_cast<float>(height_) - 10.0f}, ImGuiCond_Always, {0.0f, 1.0f});
    ImGui::SetNextWindowSize({width, 0.0f}, ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints({width, 0.0f}, {width, 0.5f * static_cast<float>(height_)});
    ImGui::Begin("Not valid: it cannot be saved or played until fixed", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.5f, 0.45f, 1.0f});
    for (const std::string& e : doc_.errors()) ImGui::TextWrapped("%s", e.c_str());
    ImGui::PopStyleColor();
    ImGui::End();
  }

  if (confirm_quit_) ImGui::OpenPopup("Unsaved changes");
  if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
    ImGui::Text("%s has changes that are not saved.", doc_.file().filename().string().c_str());
    if (ImGui::Button("Save and quit")) {
      save();
      if (!doc_.modified()) request_ = EditorRequest::quit;
      confirm_quit_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Quit without saving")) {
      request_ = EditorRequest::quit;
      confirm_quit_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) {
      confirm_quit_ = false;
      ImGui::CloseCurrentPopup();
    }
    ImGui::EndPopup();
  }
}

}  // namespace game
