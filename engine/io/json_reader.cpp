#include "tire/io/json_reader.h"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <map>
#include <optional>

#include "tire/io/file_io.h"

namespace tire {

namespace {

// Issues recorded per document; past it, one line says more follow.
constexpr std::size_t kMaxIssues = 200;

template <typename Names>
std::string quoted_list(const Names& items) {
  std::string out;
  for (const auto& item : items) out += (out.empty() ? "\"" : ", \"") + std::string(item) + "\"";
  return out;
}

// A key from the file as it appears in a message: a hostile key of megabytes is cut short, and a
// control character in it is escaped (printable), so that it cannot end the message's line.
std::string shorten_key(const std::string& key) {
  constexpr std::size_t kShown = 80;
  return key.size() <= kShown
             ? printable(key)
             : printable(key.substr(0, kShown)) + "...(" + std::to_string(key.size()) + " bytes)";
}

}  // namespace

// Exact up to kMaxEditDistance; past it, some number above kMaxEditDistance. "Did you mean" only
// wants small distances, and a hostile 4 KiB name compared with every candidate would otherwise cost
// millions of steps per name (seconds for a level full of them).
constexpr std::size_t kMaxEditDistance = 16;

std::size_t edit_distance(std::string_view a, std::string_view b) {
  const std::size_t gap = a.size() > b.size() ? a.size() - b.size() : b.size() - a.size();
  if (gap > kMaxEditDistance) return kMaxEditDistance + 1;  // the distance is at least the gap
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

std::string join_path(const std::string& path, std::string_view key) {
  std::string escaped;  // RFC 6901: ~ becomes ~0, / becomes ~1
  for (const char c : key) escaped += c == '~' ? "~0" : c == '/' ? "~1" : std::string(1, c);
  return path + "/" + escaped;
}

std::string join_path(const std::string& path, std::size_t index) {
  return path + "/" + std::to_string(index);
}

namespace {

using json = nlohmann::json;

// Appends value.dump() to `out`, but stops soon after `out` passes `limit` characters: describing
// a hostile value (a huge array, a string of megabytes) costs no more than describing a small one.
void dump_bounded(const json& value, std::string& out, std::size_t limit) {
  if (out.size() > limit) return;
  if (value.is_string()) {
    const std::string& s = value.get_ref<const std::string&>();
    const json head = s.size() > limit ? json(s.substr(0, limit)) : value;
    std::string text = head.dump(-1, ' ', false, json::error_handler_t::replace);
    if (s.size() > limit) text.pop_back();  // the cut string has no closing quote
    out += text;
  } else if (value.is_array()) {
    out += '[';
    for (std::size_t i = 0; i < value.size() && out.size() <= limit; ++i) {
      if (i > 0) out += ',';
      dump_bounded(value[i], out, limit);
    }
    out += ']';
  } else if (value.is_object()) {
    out += '{';
    bool first = true;
    for (auto it = value.begin(); it != value.end() && out.size() <= limit; ++it) {
      if (!first) out += ',';
      first = false;
      dump_bounded(json(it.key()), out, limit);
      out += ':';
      dump_bounded(it.value(), out, limit);
    }
    out += '}';
  } else {
    out += value.dump();
  }
}

}  // namespace

std::string JsonReader::describe(const json& value) {
  if (value.is_object()) return "an object";
  // An array of more than 20 entries dumps to more than 40 characters.
  if (value.is_array() && value.size() > 20) return "an array of " + std::to_string(value.size());
  std::string text;
  dump_bounded(value, text, 61);
  if (text.size() > 60) text = text.substr(0, 57) + "...";
  if (value.is_array() && text.size() > 40) return "an array of " + std::to_string(value.size());
  return text;
}

void JsonReader::fail(const std::string& path, std::string message) {
  // A hostile file can hold a million mistakes; the first ones tell the story.
  if (issues_.size() > kMaxIssues) return;
  if (issues_.size() == kMaxIssues) {
    issues_.push_back(
        {"", "more problems follow; only the first " + std::to_string(kMaxIssues) + " are reported"});
    return;
  }
  issues_.push_back({path, std::move(message)});
}

bool JsonReader::object(const json& j, const std::string& path,
                        std::initializer_list<std::string_view> allowed) {
  return object(j, path, std::span<const std::string_view>(allowed.begin(), allowed.size()));
}

bool JsonReader::object(const json& j, const std::string& path, std::span<const std::string_view> allowed) {
  if (!j.is_object()) {
    fail(path, "must be an object, got " + describe(j));
    return false;
  }
  for (const auto& [key, value] : j.items()) {
    if (std::find(allowed.begin(), allowed.end(), key) != allowed.end()) continue;
    std::string_view best;
    std::size_t best_distance = 3;  // suggest only close matches
    for (const auto& candidate : allowed) {
      // The distance is at least the difference in length: a long hostile key costs nothing.
      const std::size_t gap =
          key.size() > candidate.size() ? key.size() - candidate.size() : candidate.size() - key.size();
      if (gap >= best_distance) continue;
      const std::size_t d = edit_distance(key, candidate);
      if (d < best_distance) best_distance = d, best = candidate;
    }
    fail(join_path(path, shorten_key(key)), best.empty()
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

double JsonReader::number(const json& obj, const std::string& path, const char* key, double fallback,
                          const Range& range, const char* unit, bool required) {
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
    fail(p,
         "must be a string of at most " + std::to_string(max_length) + " characters, got " + describe(*it));
    return fallback;
  }
  return it->get<std::string>();
}

namespace {

template <typename Names>
std::string read_choice(JsonReader& r, const nlohmann::json& obj, const std::string& path, const char* key,
                        const std::string& fallback, const Names& options) {
  const auto it = obj.find(key);
  if (it == obj.end()) return fallback;
  if (!it->is_string() ||
      std::find(options.begin(), options.end(), it->get_ref<const std::string&>()) == options.end()) {
    r.fail(join_path(path, key),
           "must be one of " + quoted_list(options) + ", got " + JsonReader::describe(*it));
    return fallback;
  }
  return it->get<std::string>();
}

}  // namespace

std::string JsonReader::choice(const json& obj, const std::string& path, const char* key,
                               const std::string& fallback, std::initializer_list<std::string_view> options) {
  return read_choice(*this, obj, path, key, fallback, options);
}

std::string JsonReader::choice(const json& obj, const std::string& path, const char* key,
                               const std::string& fallback, std::span<const std::string> options) {
  return read_choice(*this, obj, path, key, fallback, options);
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

// ---- Bounded parsing ---------------------------------------------------------------------------

namespace {

struct OverBudget {
  std::string what;
};

// Where the parser is in the text. nlohmann's SAX events carry no position, so the parser reads
// the text through a CountingIterator, which moves this forward one character at a time.
struct Cursor {
  std::size_t bytes = 0;  // characters consumed
  std::size_t line = 1;   // of the next character
};

class CountingIterator {
 public:
  using iterator_category = std::input_iterator_tag;
  using value_type = char;
  using difference_type = std::ptrdiff_t;
  using pointer = const char*;
  using reference = const char&;

  CountingIterator(const char* at, Cursor* cursor) : at_(at), cursor_(cursor) {}
  reference operator*() const { return *at_; }
  CountingIterator& operator++() {
    if (*at_ == '\n') ++cursor_->line;
    ++at_;
    ++cursor_->bytes;
    return *this;
  }
  CountingIterator operator++(int) {
    CountingIterator before = *this;
    ++*this;
    return before;
  }
  bool operator==(const CountingIterator& other) const { return at_ == other.at_; }
  bool operator!=(const CountingIterator& other) const { return at_ != other.at_; }

 private:
  const char* at_;
  Cursor* cursor_;
};

// Builds the document from nlohmann's SAX events, refusing it at the first event past the budget,
// and knows at every moment the JSON pointer of the value being read, so that a refusal names the
// place. (Not json::parse with a callback: its parser rescans an object's parent at every object
// end, which makes an array of a million objects take hours.)
class BoundedBuilder {
 public:
  using json = nlohmann::json;

  BoundedBuilder(const JsonBudget& budget, const Cursor& cursor) : budget_(budget), cursor_(cursor) {}

  bool null() { return value(json(nullptr)); }
  bool boolean(bool b) { return value(json(b)); }
  bool number_integer(json::number_integer_t v) { return value(json(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return value(json(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return value(json(v)); }
  bool string(json::string_t& s) {
    check_string(s, "a string");
    work_.string_bytes += s.size();
    return value(json(std::move(s)));
  }
  bool binary(json::binary_t& b) { return value(json(std::move(b))); }
  bool start_object(std::size_t) { return open(json::value_t::object); }
  bool start_array(std::size_t) { return open(json::value_t::array); }
  bool key(json::string_t& k) {
    Frame& f = frames_.back();
    f.key = k;
    check_string(k, "a key");
    work_.string_bytes += k.size();
    // The lexer has just read the key's closing quote: the cursor is on the key's line.
    const auto [first, inserted] = f.key_lines.emplace(k, cursor_.line);
    if (!inserted && duplicates_.size() <= kMaxIssues)
      duplicates_.push_back(
          {path(), "key given twice (first at line " + std::to_string(first->second) + ")"});
    return true;
  }
  bool end_object() { return close(); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& e) {
    const std::string what = e.what();
    const auto close = what.find("] ");
    error_ = "invalid JSON: " + (close == std::string::npos ? what : what.substr(close + 2));
    return false;
  }

  json& root() { return root_; }
  const std::string& error() const { return error_; }
  std::vector<JsonIssue>& duplicates() { return duplicates_; }
  const JsonWork& work() const { return work_; }

 private:
  struct Frame {
    json* container;
    std::size_t index;                                          // arrays: of the element being read
    std::string key;                                            // objects: of the member being read
    std::map<std::string, std::size_t, std::less<>> key_lines;  // objects: each key's first line
  };

  std::string path() const {
    std::string out;
    for (const Frame& f : frames_)
      out = f.container->is_array() ? join_path(out, f.index) : join_path(out, shorten_key(f.key));
    return out;
  }

  void count() {
    if (++work_.values > budget_.max_values)
      throw OverBudget{path() + ": " + budget_.document + " may hold at most " +
                       std::to_string(budget_.max_values) +
                       " JSON values (numbers, strings, arrays, objects), and this one holds more"};
  }

  void check_string(const std::string& s, const char* what) const {
    if (s.size() > budget_.max_string_bytes)
      throw OverBudget{path() + ": " + what + " may be at most " + std::to_string(budget_.max_string_bytes) +
                       " bytes long, got one of " + std::to_string(s.size())};
  }

  // Puts a value where the parser is: the root, the next array element or the current member.
  json* place(json&& v) {
    if (frames_.empty()) {
      root_ = std::move(v);
      return &root_;
    }
    Frame& f = frames_.back();
    if (f.container->is_array()) {
      f.container->push_back(std::move(v));
      return &f.container->back();
    }
    json& slot = (*f.container)[f.key];  // a repeated key (reported in key()): the last one stays
    slot = std::move(v);
    return &slot;
  }

  bool value(json&& v) {
    count();
    place(std::move(v));
    if (!frames_.empty() && frames_.back().container->is_array()) ++frames_.back().index;
    return true;
  }

  bool open(json::value_t type) {
    count();
    if (frames_.size() >= static_cast<std::size_t>(budget_.max_depth))
      throw OverBudget{path() + ": nesting deeper than " + std::to_string(budget_.max_depth) +
                       " levels; arrays and objects may nest at most " + std::to_string(budget_.max_depth) +
                       " deep"};
    // The new container is the last element of its parent until it closes, so the pointer holds.
    frames_.push_back({place(json(type)), 0, {}, {}});
    return true;
  }

  bool close() {
    frames_.pop_back();
    if (!frames_.empty() && frames_.back().container->is_array()) ++frames_.back().index;
    return true;
  }

  const JsonBudget& budget_;
  const Cursor& cursor_;
  json root_;
  std::vector<Frame> frames_;
  std::vector<JsonIssue> duplicates_;
  JsonWork work_;
  std::string error_;
};

}  // namespace

// Refuses the text as soon as it nests deeper than the budget, holds more values (numbers,
// strings, booleans, nulls, arrays and objects) or a longer string than the budget allows: the
// document tree never grows past the budget.
JsonParse parse_json_bounded(const std::string& text, const JsonBudget& budget) {
  Cursor cursor;
  BoundedBuilder builder(budget, cursor);
  JsonParse out;
  try {
    const CountingIterator begin(text.data(), &cursor), end(text.data() + text.size(), &cursor);
    if (nlohmann::json::sax_parse(begin, end, &builder)) {
      out.doc = std::move(builder.root());
      out.duplicates = std::move(builder.duplicates());
    } else {
      out.error = builder.error();
    }
  } catch (const OverBudget& e) {
    out.error = e.what;
  }
  out.work = builder.work();
  out.work.parsed_bytes = cursor.bytes;
  return out;
}

void report_duplicates(const JsonParse& parse, std::vector<JsonIssue>& issues) {
  JsonReader reader(issues);
  for (const JsonIssue& d : parse.duplicates) reader.fail(d.path, d.message);
}

}  // namespace tire
