// The editor's ImGui windows: the palette of tools, the property panel of the selection (every key
// the level reference lists for it, from the level key table), the level's errors and the question
// asked before quitting with unsaved changes.
#include <imgui.h>

#include <cstring>

#include "editor/level_edits.h"
#include "editor_mode.h"
#include "tire/io/level_schema.h"

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
  }
  return LevelObject::root;
}

std::string tooltip(const LevelKey& key) {
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
  else if (!key.default_value.is_null())
    text += "\ndefault " + key.default_value.dump();
  return text;
}

}  // namespace

// One key's field. Returns true when a value was entered (and committed or refused).
bool Editor::edit_property(const std::string& id, const std::string& pointer, const LevelKey& key) {
  const Json::json_pointer where(pointer);
  const Json& object = doc_.json().at(where);
  const auto it = object.find(key.key);
  const bool present = it != object.end();
  const Json current = present ? *it : Json(key.default_value);
  const std::string label = key.key + (key.unit.empty() ? "" : " (" + key.unit + ")") + "##" + id;
  std::optional<Json> entered;
  const auto pending = pending_.find(id);
  if (!present) ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
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
      if (ImGui::InputScalarN(label.c_str(), ImGuiDataType_Double, v, 2, nullptr, nullptr, "%.6g"))
        pending_[id] = editor::vec2({v[0], v[1]});
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
      ImGui::Text("%s: %zu points (drag them in the view)", key.key.c_str(),
                  present && it->is_array() ? it->size() : 0);
      break;
    case KeyType::object:
    case KeyType::array: break;
  }
  if (!present) ImGui::PopStyleColor();
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip(key).c_str());
  if (present && !key.required && key.type != KeyType::points) {
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
  if (const std::string e = doc_.change(std::move(next)); !e.empty())
    refused_[id] = e;
  else
    refused_.erase(id);
  return true;
}

void Editor::draw_keys(const std::string& id, const std::string& pointer, LevelObject object,
                       const std::string& shape) {
  const Json::json_pointer where(pointer);
  for (const LevelKey& key : tire::level_keys(object)) {
    if (object == LevelObject::prop && !shape.empty() && !tire::applies_to_shape(key, shape)) continue;
    if (key.key == "$schema") continue;
    const std::string field = id + "/" + key.key;
    if (key.type == KeyType::object && key.nested) {
      const Json& parent = doc_.json().at(where);
      const bool present = parent.contains(key.key) && parent[key.key].is_object();
      if (object == LevelObject::prop && key.key == "path" && !present)
        continue;  // the Waypoint tool adds one
      if (ImGui::TreeNode((key.key + "##" + field).c_str())) {
        if (!present) {
          if (ImGui::SmallButton(("set##" + field).c_str())) {
            Json next = doc_.json();
            next.at(where)[key.key] = Json::object();
            apply(std::move(next), "adding it was");
          }
          ImGui::SameLine();
          ImGui::TextDisabled("(defaults)");
        } else {
          draw_keys(field, pointer + "/" + key.key, *key.nested, "");
        }
        ImGui::TreePop();
      }
      continue;
    }
    if (key.type == KeyType::array || key.type == KeyType::object) continue;  // counters: kept as written
    if (key.key == "goal" && object == LevelObject::root) {
      // The goal names a region: chosen from them.
      const std::string now = editor::string_at(doc_.json(), "goal", "");
      if (ImGui::BeginCombo("goal##root", now.empty() ? "(none)" : now.c_str())) {
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
    edit_property(field, pointer, key);
    if (const auto r = refused_.find(field); r != refused_.end())
      ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s", r->second.c_str());
  }
}

void Editor::draw_level_properties() {
  ImGui::TextUnformatted("Level");
  draw_keys("root", "", LevelObject::root, "");
  const Json& doc = doc_.json();
  ImGui::Separator();
  for (const char* key : {"tires", "obstacles", "props", "regions", "counters", "triggers"}) {
    const auto it = doc.find(key);
    ImGui::TextDisabled(
        "%s: %zu%s", key, it != doc.end() && it->is_array() ? it->size() : 0,
        std::strcmp(key, "counters") == 0 || std::strcmp(key, "triggers") == 0 ? " (kept as written)" : "");
  }
}

void Editor::draw_item_properties(const editor::Pick& item) {
  const Json& doc = doc_.json();
  ImGui::TextUnformatted(editor::describe(doc, item.kind, item.index).c_str());
  const std::string pointer =
      std::string("/") + editor::array_key(item.kind) + "/" + std::to_string(item.index);
  const std::string shape =
      item.kind == ItemKind::prop
          ? editor::string_at(doc[editor::array_key(item.kind)][item.index], "shape", "box")
          : "";
  draw_keys(pointer, pointer, object_of(item.kind), shape);
}

void Editor::draw_properties() {
  ImGui::SetNextWindowPos({static_cast<float>(width_) - 300.0f, 10.0f}, ImGuiCond_Always);
  ImGui::SetNextWindowSize({290.0f, static_cast<float>(height_) - 20.0f}, ImGuiCond_Always);
  ImGui::Begin("Properties", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
  ImGui::PushItemWidth(140.0f);
  std::optional<editor::Pick> item;
  if (!selection_.empty()) {
    item = selection_.front().item();
    for (const editor::Pick& p : selection_)
      if (p.item() != *item) item.reset();
  }
  if (selection_.empty())
    draw_level_properties();
  else if (item && editor::shape_of(doc_.json(), item->kind, item->index))
    draw_item_properties(*item);
  else
    ImGui::Text("%zu selected", selection_.size());
  ImGui::PopItemWidth();
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
  ImGui::End();

  draw_properties();

  if (!doc_.errors().empty()) {
    ImGui::SetNextWindowPos({190.0f, static_cast<float>(height_) - 10.0f}, ImGuiCond_Always, {0.0f, 1.0f});
    ImGui::SetNextWindowSize({static_cast<float>(width_) - 500.0f, 0.0f}, ImGuiCond_Always);
    ImGui::Begin("Not valid: it cannot be saved or played until fixed", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize);
    for (const std::string& e : doc_.errors()) ImGui::TextColored({1.0f, 0.5f, 0.45f, 1.0f}, "%s", e.c_str());
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
