// Reads values out of an untrusted JSON document and records, instead of throwing, every problem
// it meets as "/json/pointer: what was expected, got what". One pass finds all of them.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/math/numbers.h"

namespace tire {

struct JsonIssue {
  std::string path;     // JSON pointer, "" for the document itself
  std::string message;  // what was expected, got what
};

class JsonReader {
 public:
  using json = nlohmann::json;

  explicit JsonReader(std::vector<JsonIssue>& issues) : issues_(issues) {}

  void fail(const std::string& path, std::string message);

  // True when `j` is an object; reports keys not in `allowed` (with a did-you-mean).
  bool object(const json& j, const std::string& path, std::initializer_list<std::string_view> allowed);
  bool object(const json& j, const std::string& path, std::span<const std::string_view> allowed);
  // True when `j` is an array of at most `max_size` elements.
  bool array(const json& j, const std::string& path, std::size_t max_size);

  // Field readers: a missing key yields `fallback`, or an error when `required`; a bad value is
  // reported and yields `fallback`.
  double number(const json& obj, const std::string& path, const char* key, double fallback,
                const Range& range, const char* unit, bool required = false);
  int integer(const json& obj, const std::string& path, const char* key, int fallback, const Range& range,
              bool required = false);
  bool boolean(const json& obj, const std::string& path, const char* key, bool fallback);
  std::string string(const json& obj, const std::string& path, const char* key, const std::string& fallback,
                     std::size_t max_length, bool required = false);
  std::string choice(const json& obj, const std::string& path, const char* key, const std::string& fallback,
                     std::initializer_list<std::string_view> options);
  std::string choice(const json& obj, const std::string& path, const char* key, const std::string& fallback,
                     std::span<const std::string> options);
  Vec2 vec2(const json& obj, const std::string& path, const char* key, Vec2 fallback, const Range& component,
            const char* unit, bool required = false);

  static std::string describe(const json& value);  // short rendering for "got ..."

 private:
  std::vector<JsonIssue>& issues_;
};

// Levenshtein distance, for "did you mean".
std::size_t edit_distance(std::string_view a, std::string_view b);

// What a document may hold, enforced while it is parsed, before a hostile file can build a large
// or deep tree: used by the level loader and the replay reader.
struct JsonBudget {
  int max_depth;
  std::size_t max_values;
  std::size_t max_string_bytes;
  const char* document;  // "a level", "a replay": for messages
};

// What reading a document cost, counted rather than timed: tests bound the work a hostile file
// causes with these, the same on any machine and in any build.
struct JsonWork {
  std::uintmax_t file_bytes = 0;  // read from disk (0: refused before reading, or given as text)
  std::size_t parsed_bytes = 0;   // characters the parser consumed before it finished or refused
  std::size_t values = 0;         // values built into the tree
  std::size_t string_bytes = 0;   // bytes of the strings and keys kept in the tree
};

struct JsonParse {
  std::optional<nlohmann::json> doc;  // empty when the text was refused
  std::string error;                  // why: "/json/pointer: what was wrong" or "invalid JSON: ..."
  // Each key given again in the same object, at the path of the repeat, "key given twice (first at
  // line N)". The tree keeps the last value; a reader refuses the document when any is here.
  std::vector<JsonIssue> duplicates;
  JsonWork work;
};

// Parses untrusted text within `budget`. Never throws.
JsonParse parse_json_bounded(const std::string& text, const JsonBudget& budget);

// Records the parse's duplicate keys as issues (first among a reader's, under its issue cap).
void report_duplicates(const JsonParse& parse, std::vector<JsonIssue>& issues);

std::string join_path(const std::string& path, std::string_view key);
std::string join_path(const std::string& path, std::size_t index);

}  // namespace tire
