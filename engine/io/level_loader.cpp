// Level files: size and depth limits, parse errors with line and column, --set overrides.
#include <algorithm>
#include <charconv>
#include <cmath>

#include "tire/io/file_io.h"
#include "tire/io/level.h"
#include "tire/math/numbers.h"
#include "tire/session/level_session.h"
#include "tire/world/world.h"

namespace tire {

namespace {

using json = nlohmann::json;

// What a level file may hold, enforced while parsing, before a hostile file can build a large or
// deep tree: the largest legitimate level (a 100 000-point chain, 10 000 tires, 100 000
// obstacles) holds under a million values, and no string it needs is longer than 4 KiB. A
// million values make a tree of at most about 150 MB.
constexpr JsonBudget kLevelBudget{LevelLimits::max_depth, LevelLimits::max_json_values,
                                  LevelLimits::max_string_bytes, "a level"};

// Splits "a.b.0.c" into its parts, keeping empty ones: "solver.dt." is "solver", "dt", "".
std::vector<std::string> split_dotted(const std::string& path) {
  std::vector<std::string> parts(1);
  for (const char c : path) {
    if (c == '.')
      parts.emplace_back();
    else
      parts.back() += c;
  }
  return parts;
}

}  // namespace

std::string apply_override(json& doc, const std::string& assignment) {
  const std::string shown = "--set " + printable(assignment);
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0) return shown + ": expected key=value, e.g. solver.substeps=16";
  const std::string key = assignment.substr(0, eq);
  const std::string text = assignment.substr(eq + 1);
  const std::vector<std::string> parts = split_dotted(key);
  // "solver.dt." is not solver.dt: every part between the dots is a name or an index.
  if (std::find(parts.begin(), parts.end(), "") != parts.end())
    return shown + ": the key \"" + printable(key) +
           "\" has an empty part (a leading, trailing or doubled dot); expected names and indices joined by "
           "single dots, e.g. tires.0.mass";
  const std::optional<double> parsed = tire::parse_double(text);
  if (!parsed) return shown + ": value must be a number, got \"" + printable(text) + "\"";
  const double value = *parsed;
  // from_chars reads "nan" and "inf"; JSON has no such numbers, and no key takes one.
  if (!std::isfinite(value)) return shown + ": value must be a finite number, got " + printable(text);

  json* node = &doc;
  for (const std::string& part : parts) {
    if (node->is_array()) {
      std::size_t index = 0;
      const auto [p, e] = std::from_chars(part.data(), part.data() + part.size(), index);
      if (e != std::errc{} || p != part.data() + part.size() || index >= node->size())
        return shown + ": \"" + printable(part) + "\" is not an index of the " +
               std::to_string(node->size()) + "-entry array";
      node = &(*node)[index];
    } else if (node->is_object() || node->is_null()) {
      node = &(*node)[part];
    } else {
      return shown + ": \"" + printable(part) + "\" goes inside a value that is not an object";
    }
  }
  if (node->is_object() || node->is_array())
    return shown + ": \"" + printable(key) + "\" is an object or array, not a number";
  if (std::floor(value) == value && std::abs(value) < 9e15)
    *node = static_cast<std::int64_t>(value);
  else
    *node = value;
  return "";
}

LevelLoad load_level_text(const std::string& text, const std::string& file,
                          const std::vector<std::string>& overrides) {
  LevelLoad out;
  JsonParse parse = parse_json_bounded(text, kLevelBudget);
  out.work = parse.work;
  if (!parse.doc) {
    out.errors.push_back(printable(file) + ": " + parse.error);
    return out;
  }
  json& doc = *parse.doc;
  for (const std::string& assignment : overrides) {
    if (std::string err = apply_override(doc, assignment); !err.empty())
      out.errors.push_back(printable(file) + ": " + err);
  }
  if (!out.errors.empty()) return out;
  std::vector<JsonIssue> issues;
  report_duplicates(parse, issues);
  out.level = read_level(doc, issues);
  if (!issues.empty()) out.level.reset();
  for (const JsonIssue& issue : issues)
    out.errors.push_back(printable(file) + ": " + (issue.path.empty() ? "/" : issue.path) + ": " +
                         issue.message);
  return out;
}

LevelLoad load_level_file(const std::filesystem::path& file, const std::vector<std::string>& overrides) {
  std::string error;
  const auto text = read_file(file, LevelLimits::max_file_bytes, error);
  if (!text) return {std::nullopt, {printable(file.string()) + ": " + error}, {}};
  LevelLoad out = load_level_text(*text, file.string(), overrides);
  out.work.file_bytes = text->size();
  return out;
}

void populate_world(const Level& level, World& world) {
  world.set_budgets(level.budgets);
  for (const Obstacle& o : level.obstacles) world.add_obstacle(o);
  for (const PropSpec& p : level.props) world.add_prop(p);
  for (const TireSpec& t : level.tires) world.add_tire(t);
  // The reader has checked what add_vehicle refuses (the method, the wheel count): each is added.
  for (const LevelVehicle& v : level.vehicles) {
    const std::optional<std::uint32_t> added = world.add_vehicle(v.spec);
    if (added && v.player) world.set_player_vehicle(*added);
  }
}

std::unique_ptr<LevelSession> make_session(const Level& level) {
  auto session = std::make_unique<LevelSession>(level.solver, level.gravity);
  populate_world(level, session->world());
  for (std::size_t v = 0; v < level.vehicles.size(); ++v)
    if (level.vehicles[v].head)
      session->set_vehicle_head(static_cast<std::uint32_t>(v), *level.vehicles[v].head);
  session->set_bounds(level.bounds.box);
  session->set_script(level.script);
  return session;
}

}  // namespace tire
