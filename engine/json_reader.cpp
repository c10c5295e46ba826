#include "json_reader.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace tire {

namespace {

std::string format_number(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

// Levenshtein distance, for "did you mean".
std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = up;
    }
  }
  return row[b.size()];
}

std::string quoted_list(std::initializer_list<std::string_view> items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "\"" : ", \"") + std::string(item) + "\"";
  return out;
}

}  // namespace

bool Range::contains(double v) const {
  return (min_open ? v > min : v >= min) && (max_open ? v < max : v <= max);
}

std::string Range::text() const {
  return std::string(min_open ? "(" : "[") + format_number(min) + ", " + format_number(max) +
         (max_open ? ")" : "]");
}

std::string join_path(const std::string& path, std::string_view key) {
  std::string escaped;  // RFC 6901: ~ becomes ~0, / becomes ~1
  for (const char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return path + "/" + escaped;
}

std::string join_path(const std::string& path, std::size_t index) {
  return path + "/" + std::to_string(index);
}

std::string JsonReader::describe(const json& value) {
  std::string text = value.dump(-1, ' ', false, json::error_handler_t::replace);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  if (value.is_object()) return "an object";
  if (value.is_array() && text.size() > 40) return "an array of " + std::to_string(value.size());
  return text;
}

void JsonReader::fail(const std::string& path, std::string message) {
  issues_.push_back({path, std::move(message)});
}

bool JsonReader::object(const json& j, const std::string& path,
                        std::initializer_list<std::string_view> allowed) {
  if (!j.is_object()) {
    fail(path, "must be an object, got " + describe(j));
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string_view best;
    std::size_t best_distance = 3;  // suggest only close matches
    for (const auto& candidate : allowed) {
      const std::size_t d = edit_distance(key, candidate);
      if (d < best_distance) best_distance = d, best = candidate;
    }
    fail(join_path(path, key), best.empty()
                                   ? "unknown key; expected one of " + quoted_list(allowed)
                                   : "unknown key; did you mean \"" + std::string(best) + "\"?");
  }
  return true;
}

bool JsonReader::array(const json& j, const std::string& path, std::size_t max_size) {
  if (!j.is_array()) {
    fail(path, "must be an array, got " + describe(j));
    return false;
  }
  if (j.size() > max_size) {
    fail(path, "must have at most " + std::to_string(max_size) + " entries, got " + std::to_string(j.size()));
    return false;
  }
  return true;
}

double JsonReader::number(const json& obj, const std::string& path, const char* key,
                          double fallback, const Range& range, const char* unit, bool required) {
  const std::string p = join_path(path, key);
  const auto it = obj.find(key);
  if (it == obj.end()) {
    if (required) fail(p, "is required: a number in " + range.text() + (*unit ? " " : "") + unit);
    return fallback;
  }
  if (!it->is_number() || !range.contains(it->get<double>()) || !std::isfinite(it->get<double>())) {
    fail(p, "must be a number in " + range.text() + (*unit ? " " : "") + unit + ", got " + describe(*it));
    return fallback;
  }
  return it->get<double>();
}

int JsonReader::integer(const json& obj, const std::string& path, const char* key, int fallback,
                        const Range& range, bool required) {
  const std::string p = join_path(path, key);
  const auto it = obj.find(key);
  if (it == obj.end()) {
    if (required) fail(p, "is required: an integer in " + range.text());
    return fallback;
  }
  const bool integral = it->is_number_integer() ||
                        (it->is_number_float() && std::floor(it->get<double>()) == it->get<double>());
  if (!integral || !range.contains(it->get<double>())) {
    fail(p, "must be an integer in " + range.text() + ", got " + describe(*it));
    return fallback;
  }
  return static_cast<int>(it->get<double>());
}

bool JsonReader::boolean(const json& obj, const std::string& path, const char* key, bool fallback) {
  const auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  if (!it->is_boolean()) {
    fail(join_path(path, key), "must be true or false, got " + describe(*it));
    return fallback;
  }
  return it->get<bool>();
}

std::string JsonReader::string(const json& obj, const std::string& path, const char* key,
                               const std::string& fallback, std::size_t max_length, bool required) {
  const std::string p = join_path(path, key);
  const auto it = obj.find(key);
  if (it == obj.end()) {
    if (required) fail(p, "is required: a string");
    return fallback;
  }
  if (!it->is_string() || it->get_ref<const std::string&>().size() > max_length) {
    fail(p, "must be a string of at most " + std::to_string(max_length) + " characters, got " + describe(*it));
    return fallback;
  }
  return it->get<std::string>();
}

std::string JsonReader::choice(const json& obj, const std::string& path, const char* key,
                               const std::string& fallback, std::initializer_list<std::string_view> options) {
  const auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  if (!it->is_string() ||
      std::find(options.begin(), options.end(), it->get_ref<const std::string&>()) == options.end()) {
    fail(join_path(path, key), "must be one of " + quoted_list(options) + ", got " + describe(*it));
    return fallback;
  }
  return it->get<std::string>();
}

Vec2 JsonReader::vec2(const json& obj, const std::string& path, const char* key, Vec2 fallback,
                      const Range& component, const char* unit, bool required) {
  const std::string p = join_path(path, key);
  const auto it = obj.find(key);
  const std::string expected = "[x, y] with each in " + component.text() + " " + unit;
  if (it == obj.end()) {
    if (required) fail(p, "is required: " + expected);
    return fallback;
  }
  const bool ok = it->is_array() && it->size() == 2 && (*it)[0].is_number() && (*it)[1].is_number() &&
                  std::isfinite((*it)[0].get<double>()) && std::isfinite((*it)[1].get<double>()) &&
                  component.contains((*it)[0].get<double>()) && component.contains((*it)[1].get<double>());
  if (!ok) {
    fail(p, "must be " + expected + ", got " + describe(*it));
    return fallback;
  }
  return {(*it)[0].get<double>(), (*it)[1].get<double>()};
}

}  // namespace tire
