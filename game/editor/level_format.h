// A level as the editor writes it: keys in the order of the level reference (tire/io/level_format.h,
// the order levels/README.md lists them), keys the table does not know (scripts' triggers and
// counters, inside and out) in the order they came, two-space indents, an object or array on one
// line when it fits in 100 columns, numbers as short as they read back exactly (format_json).
#pragma once

#include <filesystem>
#include <string>

#include "level_items.h"

namespace editor {

// The document with the keys of its level objects in reference order.
Json in_reference_order(const Json& doc);
// The text a save writes.
std::string level_text(const Json& doc);
// What a new level file starts as: a name taken from the file's, and the schema when one sits
// beside it.
Json new_level(const std::filesystem::path& file);

}  // namespace editor
