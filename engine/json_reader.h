// Reads values out of an untrusted JSON document and records, instead of throwing, every problem
// it meets as "/json/pointer: what was expected, got what". One pass finds all of them.
#pragma once

#include <initializer_list>
#include <optional>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "vec2.h"

namespace tire {

struct JsonIssue {
  std::string path;     // JSON pointer, "" for the document itself
  std::string message;  // what was expected, got what
};

// An inclusive or exclusive numeric interval, printed as in the reference page: [6, 256], (0, 0.1].
struct Range {
  double min;
  double max;
  bool min_open = false;
  bool max_open = false;
  bool contains(double v) const;
  std::string text() const;
};

class JsonReader {
 public:
  using json = nlohmann::json;

  explicit JsonReader(std::vector<JsonIssue>& issues) : issues_(issues) {}

  void fail(const std::string& path, std::string message);

  // True when `j` is an object; reports keys not in `allowed` (with a did-you-mean).
  bool object(const json& j, const std::string& path, std::initializer_list<std::string_view> allowed);
  // True when `j` is an array of at most `max_size` elements.
  bool array(const json& j, const std::string& path, std::size_t max_size);

  // Field readers: a missing key yields `fallback`, or an error when `required`; a bad value is
  // reported and yields `fallback`.
  double number(const json& obj, const std::string& path, const char* key, double fallback,
                const Range& range, const char* unit, bool required = false);
  int integer(const json& obj, const std::string& path, const char* key, int fallback,
              const Range& range, bool required = false);
  bool boolean(const json& obj, const std::string& path, const char* key, bool fallback);
  std::string string(const json& obj, const std::string& path, const char* key,
                     const std::string& fallback, std::size_t max_length, bool required = false);
  std::string choice(const json& obj, const std::string& path, const char* key,
                     const std::string& fallback, std::initializer_list<std::string_view> options);
  Vec2 vec2(const json& obj, const std::string& path, const char* key, Vec2 fallback,
            const Range& component, const char* unit, bool required = false);

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
std::optional<nlohmann::json> parse_json_bounded(const std::string& text, const JsonBudget& budget, std::string& error);

std::string join_path(const std::string& path, std::string_view key);
std::string join_path(const std::string& path, std::size_t index);

}  // namespace tire
