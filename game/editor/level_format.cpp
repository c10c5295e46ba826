#include "level_format.h"

#include "tire/io/level_format.h"

namespace editor {

namespace {

using tire::LevelObject;

// `j`'s keys in the order `object` lists them, then the others as they came; nested level objects
// likewise.
Json ordered(const Json& j, LevelObject object) {
  if (!j.is_object()) return j;
  Json out = Json::object();
  for (const tire::LevelKey& key : tire::level_keys(object)) {
    const auto it = j.find(key.key);
    if (it == j.end()) continue;
    if (key.nested && it->is_object()) {
      out[key.key] = ordered(*it, *key.nested);
    } else if (key.nested && it->is_array()) {
      Json items = Json::array();
      for (const Json& item : *it) items.push_back(ordered(item, *key.nested));
      out[key.key] = std::move(items);
    } else {
      out[key.key] = *it;
    }
  }
  for (auto it = j.begin(); it != j.end(); ++it)
    if (!out.contains(it.key())) out[it.key()] = it.value();
  return out;
}

}  // namespace

Json in_reference_order(const Json& doc) { return ordered(doc, LevelObject::root); }

std::string level_text(const Json& doc) {
  const Json ordered_doc = in_reference_order(doc);
  std::string text = tire::format_json(ordered_doc);
  if (ordered_doc.empty() || text.find('\n') + 1 != text.size()) return text;
  // A small level fits on one line; a file reads better with one root key a line.
  text = "{\n";
  std::size_t i = 0;
  for (auto it = ordered_doc.begin(); it != ordered_doc.end(); ++it) {
    std::string value = tire::format_json(it.value());
    value.pop_back();  // its newline
    text += "  " + Json(it.key()).dump() + ": " + value + (++i < ordered_doc.size() ? ",\n" : "\n");
  }
  return text + "}\n";
}

Json new_level(const std::filesystem::path& file) {
  Json doc = Json::object();
  std::error_code ec;
  if (std::filesystem::exists(file.parent_path() / "schema.json", ec)) doc["$schema"] = "schema.json";
  doc["name"] = file.stem().string().empty() ? std::string("New level") : file.stem().string();
  return doc;
}

}  // namespace editor
