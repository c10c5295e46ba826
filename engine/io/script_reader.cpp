// Script validation: every key of levels/SCRIPTING.md, with its unit, default and range, and every
// cross-reference (regions, counters, props) checked at load so that a running script never meets
// a name it cannot resolve.
#include "script_reader.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <string_view>

#include "level_reader.h"
#include "tire/io/file_io.h"
#include "tire/io/level.h"

namespace tire {

namespace {

using json = nlohmann::json;

const Range kCoordinate{-LevelLimits::max_coordinate, LevelLimits::max_coordinate};
const Range kImpulse{-1.0e6, 1.0e6};
const Range kSeconds{0.0, ScriptLimits::max_seconds};
const Range kPositiveSeconds{0.0, ScriptLimits::max_seconds, true};
const Range kMessageSeconds{0.0, 3600.0, true};
const Range kCounterValue{-ScriptLimits::max_counter_value, ScriptLimits::max_counter_value};
const Range kFireCount{1.0, 1.0e9};

const std::vector<std::string>& settable_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const SettableKey& k : settable_keys()) out.push_back(k.key);
    return out;
  }();
  return names;
}

constexpr std::array<std::string_view, 7> kTriggerTypes{"start", "time",       "every",  "enter",
                                                        "leave", "prop_enter", "counter"};
constexpr std::array<std::string_view, 13> kActionNames{
    "spawn_tire", "spawn_prop", "remove_prop", "set_gravity", "impulse", "set",       "path",
    "message",    "checkpoint", "counter",     "win",         "lose",    "next_level"};

// The closest candidate within the same distance json_reader.cpp accepts for unknown keys.
template <typename Names>
std::string_view closest(std::string_view name, const Names& candidates) {
  std::string_view best;
  std::size_t best_distance = 3;
  for (const auto& candidate : candidates) {
    const std::string_view c(candidate);
    if (c.empty()) continue;
    const std::size_t d = edit_distance(name, c);
    if (d < best_distance) best_distance = d, best = c;
  }
  return best;
}

template <typename Names>
std::string quoted_list(const Names& items) {
  std::string out;
  for (const auto& item : items) {
    const std::string_view s(item);
    if (!s.empty()) out += (out.empty() ? "\"" : ", \"") + printable(s) + "\"";
  }
  return out;
}

std::string as_json_string(std::string_view s) { return JsonReader::describe(json(std::string(s))); }
std::string in_quotes(std::string_view s) { return "\"" + printable(s) + "\""; }

bool is_string_at(const json& obj, const char* key) {
  const auto it = obj.find(key);
  return it != obj.end() && it->is_string();
}

// A required string naming something; "" when missing or not a string (already reported).
std::string read_name(JsonReader& r, const json& obj, const std::string& path, const char* key) {
  return r.string(obj, path, key, "", ScriptLimits::max_name_length, true);
}

// Reports `name` at `path` unless it is one of `known` (empty entries are placeholders for names
// that were themselves invalid). `what` reads "a region", "a counter", ...
void check_reference(JsonReader& r, const std::string& path, const std::string& name,
                     const std::vector<std::string>& known, const std::string& what) {
  if (std::find(known.begin(), known.end(), name) != known.end() && !name.empty()) return;
  const std::string list = quoted_list(known);
  std::string message = "must name " + what;
  if (list.empty()) {
    r.fail(path, message + ", got " + as_json_string(name) + ", and the level defines none");
    return;
  }
  if (const std::string_view best = closest(name, known); !best.empty()) {
    r.fail(path, message + ", got " + as_json_string(name) + "; did you mean " + in_quotes(best) + "?");
    return;
  }
  const bool short_list =
      std::count_if(known.begin(), known.end(), [](const std::string& k) { return !k.empty(); }) <= 10;
  r.fail(path, message + (short_list ? " (one of " + list + ")" : "") + ", got " + as_json_string(name));
}

std::optional<std::size_t> index_of(const std::vector<std::string>& names, const std::string& name) {
  if (name.empty()) return std::nullopt;
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<std::size_t>(it - names.begin());
}

// A required value that must be one of `options`: the index of the one given.
template <std::size_t N>
std::optional<std::size_t> read_choice(JsonReader& r, const json& obj, const std::string& path,
                                       const char* key, const std::array<std::string_view, N>& options) {
  const std::string p = join_path(path, key);
  const auto it = obj.find(key);
  if (it == obj.end()) {
    r.fail(p, "is required: one of " + quoted_list(options));
    return std::nullopt;
  }
  if (it->is_string()) {
    const auto found = std::find(options.begin(), options.end(), it->get_ref<const std::string&>());
    if (found != options.end()) return static_cast<std::size_t>(found - options.begin());
  }
  std::string message = "must be one of " + quoted_list(options) + ", got " + JsonReader::describe(*it);
  if (it->is_string())
    if (const std::string_view best = closest(it->get_ref<const std::string&>(), options); !best.empty())
      message += "; did you mean " + in_quotes(best) + "?";
  r.fail(p, message);
  return std::nullopt;
}

// Reads the script; keeps the cross-references that can only be checked once everything is read.
class ScriptReader {
 public:
  ScriptReader(JsonReader& r, const std::vector<std::string>& prop_names) : r_(r), prop_names_(prop_names) {}

  ScriptSpec read(const json& doc) {
    ScriptSpec spec;
    if (!doc.is_object()) return spec;  // the level reader reports it
    if (const auto it = doc.find("regions"); it != doc.end()) read_regions(*it, spec);
    if (const auto it = doc.find("goal"); it != doc.end()) {
      const std::string goal = read_string(r_, doc, "", level_key(LevelObject::root, "goal"), "");
      if (it->is_string()) {
        spec.goal = index_of(region_names_, goal);
        if (!spec.goal) check_reference(r_, "/goal", goal, region_names_, "a region");
      }
    }
    if (doc.contains("time_limit"))
      spec.time_limit = read_number(r_, doc, "", level_key(LevelObject::root, "time_limit"), 60.0);
    if (const auto it = doc.find("counters"); it != doc.end()) read_counters(*it, spec);
    if (const auto it = doc.find("triggers");
        it != doc.end() && r_.array(*it, "/triggers", ScriptLimits::max_triggers)) {
      spec.triggers.reserve(it->size());
      for (std::size_t i = 0; i < it->size(); ++i)
        spec.triggers.push_back(read_trigger((*it)[i], join_path("/triggers", i)));
    }
    check_prop_references();
    return spec;
  }

 private:
  struct PropReference {
    std::string name;
    std::string path;
    bool impulse_target;  // "player" and "all_tires" were also allowed there
  };

  void read_regions(const json& j, ScriptSpec& spec) {
    if (!r_.array(j, "/regions", ScriptLimits::max_regions)) return;
    std::map<std::string, std::string> first_path;  // name -> path of the region that has it
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string path = join_path("/regions", i);
      const json& rj = j[i];
      Region region;
      const auto key = [](std::string_view name) -> const LevelKey& {
        return level_key(LevelObject::region, name);
      };
      if (r_.object(rj, path, level_key_names(LevelObject::region))) {
        region.name = read_string(r_, rj, path, key("name"), "");
        if (is_string_at(rj, "name") && region.name.empty())
          r_.fail(path + "/name", "must be a non-empty string, got \"\"");
        if (!region.name.empty()) {
          const auto [where, inserted] = first_path.emplace(region.name, path);
          if (!inserted) {
            r_.fail(path + "/name", "must be unique, got " + as_json_string(region.name) + ", which " +
                                        where->second + " already has");
            region.name.clear();  // references resolve to the first one
          }
        }
        const double nan = std::numeric_limits<double>::quiet_NaN();
        region.box.min = read_vec2(r_, rj, path, key("min"), {nan, nan});
        region.box.max = read_vec2(r_, rj, path, key("max"), {nan, nan});
        if (is_finite(region.box.min) && is_finite(region.box.max) &&
            !(region.box.min.x < region.box.max.x && region.box.min.y < region.box.max.y))
          r_.fail(path + "/max", "must be greater than min on both axes, got " +
                                     JsonReader::describe(rj["max"]) + " with min " +
                                     JsonReader::describe(rj["min"]));
      }
      region_names_.push_back(region.name);
      spec.regions.push_back(std::move(region));
    }
  }

  void read_counters(const json& j, ScriptSpec& spec) {
    if (!j.is_object()) {
      r_.fail("/counters", "must be an object of counter names to integers, got " + JsonReader::describe(j));
      return;
    }
    if (j.size() > ScriptLimits::max_counters) {
      r_.fail("/counters", "must have at most " + std::to_string(ScriptLimits::max_counters) +
                               " entries, got " + std::to_string(j.size()));
      return;
    }
    for (const auto& [name, value] : j.items()) {  // a json object iterates in key order
      Counter c;
      if (name.empty() || name.size() > ScriptLimits::max_name_length) {
        r_.fail(join_path("/counters", name), "must be named by a non-empty string of at most " +
                                                  std::to_string(ScriptLimits::max_name_length) +
                                                  " characters");
      } else {
        c.name = name;
      }
      c.initial = r_.integer(j, "/counters", name.c_str(), 0, kCounterValue, true);
      counter_names_.push_back(c.name);
      spec.counters.push_back(std::move(c));
    }
  }

  // A required reference to a region or counter: its index, or nullopt (reported).
  std::optional<std::size_t> read_reference(const json& obj, const std::string& path, const char* key,
                                            const std::vector<std::string>& known, const std::string& what) {
    const std::string name = read_name(r_, obj, path, key);
    if (!is_string_at(obj, key)) return std::nullopt;
    const auto index = index_of(known, name);
    if (!index) check_reference(r_, join_path(path, key), name, known, what);
    return index;
  }

  // A required prop name, checked once every spawned prop's name is known.
  std::string read_prop_reference(const json& obj, const std::string& path, const char* key) {
    const std::string name = r_.string(obj, path, key, "", ScriptLimits::max_prop_name_length, true);
    if (is_string_at(obj, key)) prop_references_.push_back({name, join_path(path, key), false});
    return name;
  }

  std::optional<Condition> read_condition(const json& j, const std::string& path) {
    if (!j.is_object()) {
      r_.fail(path, "must be an object, got " + JsonReader::describe(j));
      return std::nullopt;
    }
    const auto type = read_choice(r_, j, path, "type", kTriggerTypes);
    if (!type) {  // without a type, judge the keys against every type's
      r_.object(j, path,
                {"type", "at", "period", "start", "count", "region", "who", "prop", "counter", "value"});
      return std::nullopt;
    }
    const std::string_view name = kTriggerTypes[*type];
    // Each type has exactly its own keys.
    if (name == "start") {
      r_.object(j, path, {"type"});
      return AtStart{};
    }
    if (name == "time") {
      r_.object(j, path, {"type", "at"});
      return AtTime{r_.number(j, path, "at", 0.0, kSeconds, "s", true)};
    }
    if (name == "every") {
      r_.object(j, path, {"type", "period", "start", "count"});
      Every e;
      e.period = r_.number(j, path, "period", e.period, kPositiveSeconds, "s", true);
      e.start = r_.number(j, path, "start", e.start, kSeconds, "s");
      if (j.contains("count")) e.count = r_.integer(j, path, "count", 1, kFireCount);
      return e;
    }
    if (name == "enter" || name == "leave") {
      r_.object(j, path, {"type", "region", "who"});
      RegionCrossing c;
      c.entering = name == "enter";
      const auto region = read_reference(j, path, "region", region_names_, "a region");
      c.who = r_.choice(j, path, "who", "player", {"player", "any"}) == "any" ? Who::any : Who::player;
      if (!region) return std::nullopt;
      c.region = *region;
      return c;
    }
    if (name == "prop_enter") {
      r_.object(j, path, {"type", "region", "prop"});
      PropEnters p;
      const auto region = read_reference(j, path, "region", region_names_, "a region");
      p.prop = read_prop_reference(j, path, "prop");
      if (!region) return std::nullopt;
      p.region = *region;
      return p;
    }
    r_.object(j, path, {"type", "counter", "value"});
    CounterReaches c;
    const auto counter = read_reference(j, path, "counter", counter_names_, "a counter");
    c.value = r_.integer(j, path, "value", 0, kCounterValue, true);
    if (!counter) return std::nullopt;
    c.counter = *counter;
    return c;
  }

  Trigger read_trigger(const json& j, const std::string& path) {
    Trigger t;
    if (!r_.object(j, path, {"name", "when", "once", "do"})) return t;
    t.name = r_.string(j, path, "name", "", ScriptLimits::max_name_length);
    if (const auto it = j.find("when"); it == j.end()) {
      r_.fail(path + "/when", "is required: an object with a \"type\"");
    } else if (const auto when = read_condition(*it, path + "/when")) {
      t.when = *when;
    }
    // Region crossings and periodic triggers repeat by nature; the rest are one-off events.
    const bool repeats =
        std::holds_alternative<RegionCrossing>(t.when) || std::holds_alternative<Every>(t.when);
    t.once = r_.boolean(j, path, "once", !repeats);
    if (const auto it = j.find("do"); it == j.end()) {
      r_.fail(path + "/do", "is required: an array of actions");
    } else if (r_.array(*it, path + "/do", ScriptLimits::max_actions)) {
      t.actions.reserve(it->size());
      for (std::size_t i = 0; i < it->size(); ++i) {
        if (auto action = read_action((*it)[i], join_path(path + "/do", i)))
          t.actions.push_back(std::move(*action));
      }
    }
    return t;
  }

  std::optional<Action> read_action(const json& j, const std::string& path) {
    if (!j.is_object()) {
      r_.fail(path, "must be an object, got " + JsonReader::describe(j));
      return std::nullopt;
    }
    const auto kind = read_choice(r_, j, path, "action", kActionNames);
    if (!kind) {  // without an action, judge the keys against every action's
      r_.object(j, path,
                {"action", "tire", "prop", "gravity", "target", "impulse", "key", "value", "command", "text",
                 "seconds", "position", "counter", "add", "set"});
      return std::nullopt;
    }
    const std::string_view name = kActionNames[*kind];

    if (name == "spawn_tire") {
      r_.object(j, path, {"action", "tire"});
      if (!j.contains("tire")) {
        r_.fail(path + "/tire", "is required: a tire object");
        return std::nullopt;
      }
      return SpawnTire{read_tire(r_, j["tire"], path + "/tire")};
    }
    if (name == "spawn_prop") {
      r_.object(j, path, {"action", "prop"});
      if (!j.contains("prop")) {
        r_.fail(path + "/prop", "is required: a prop object");
        return std::nullopt;
      }
      SpawnProp s{read_prop(r_, j["prop"], path + "/prop")};
      if (!s.prop.name.empty()) spawned_props_.insert(s.prop.name);
      return s;
    }
    if (name == "remove_prop") {
      r_.object(j, path, {"action", "prop"});
      return RemoveProp{read_prop_reference(j, path, "prop")};
    }
    if (name == "set_gravity") {
      r_.object(j, path, {"action", "gravity"});
      return SetGravity{read_gravity(r_, j, path, "gravity", kDefaultGravity, true)};
    }
    if (name == "impulse") {
      r_.object(j, path, {"action", "target", "impulse"});
      ApplyImpulse a;
      const std::string target = r_.string(j, path, "target", "", ScriptLimits::max_prop_name_length, true);
      if (target == "all_tires") {
        a.target = ImpulseTarget::all_tires;
      } else if (target != "player" && is_string_at(j, "target")) {
        a.target = ImpulseTarget::prop;
        a.prop = target;
        prop_references_.push_back({target, path + "/target", true});
      }
      a.impulse = r_.vec2(j, path, "impulse", {}, kImpulse, "N*s", true);
      return a;
    }
    if (name == "set") {
      r_.object(j, path, {"action", "key", "value"});
      return read_set(j, path);
    }
    if (name == "path") {
      r_.object(j, path, {"action", "prop", "command"});
      ControlPath c;
      c.prop = read_prop_reference(j, path, "prop");
      static constexpr std::array<std::string_view, 3> commands{"start", "stop", "reverse"};
      if (const auto command = read_choice(r_, j, path, "command", commands))
        c.command = std::array{PathCommand::start, PathCommand::stop, PathCommand::reverse}[*command];
      return c;
    }
    if (name == "message") {
      r_.object(j, path, {"action", "text", "seconds"});
      ShowMessage m;
      m.text = r_.string(j, path, "text", "", ScriptLimits::max_message_length, true);
      m.seconds = r_.number(j, path, "seconds", m.seconds, kMessageSeconds, "s");
      return m;
    }
    if (name == "checkpoint") {
      r_.object(j, path, {"action", "position"});
      return SetCheckpoint{r_.vec2(j, path, "position", {}, kCoordinate, "m", true)};
    }
    if (name == "counter") {
      r_.object(j, path, {"action", "counter", "add", "set"});
      ChangeCounter c;
      const auto counter = read_reference(j, path, "counter", counter_names_, "a counter");
      const bool has_add = j.contains("add");
      const bool has_set = j.contains("set");
      if (has_add == has_set)
        r_.fail(path, std::string("must have exactly one of \"add\" or \"set\", got ") +
                          (has_add ? "both" : "neither"));
      c.set = has_set && !has_add;
      c.amount = r_.integer(j, path, c.set ? "set" : "add", 0, kCounterValue);
      if (has_add && has_set) r_.integer(j, path, "set", 0, kCounterValue);  // report a bad value there too
      if (!counter) return std::nullopt;
      c.counter = *counter;
      return c;
    }
    r_.object(j, path, {"action"});
    if (name == "win") return Win{};
    if (name == "lose") return Lose{};
    return NextLevel{};
  }

  std::optional<Action> read_set(const json& j, const std::string& path) {
    SetParameter s;
    const Parameter* key = nullptr;
    if (const auto it = j.find("key"); it == j.end()) {
      r_.fail(path + "/key", "is required: one of " + quoted_list(settable_names()));
    } else {
      if (it->is_string()) {
        s.key = it->get<std::string>();
        for (const SettableKey& k : settable_keys())
          if (k.key == s.key) key = k.parameter;
      }
      if (!key) {
        std::string message =
            "must be one of " + quoted_list(settable_names()) + ", got " + JsonReader::describe(*it);
        if (it->is_string())
          if (const std::string_view best = closest(s.key, settable_names()); !best.empty())
            message += "; did you mean " + in_quotes(best) + "?";
        r_.fail(path + "/key", message);
      }
    }
    if (key) {
      s.value = key->integer ? r_.integer(j, path, "value", 0, key->range, true)
                             : r_.number(j, path, "value", 0.0, key->range, key->unit, true);
      return s;
    }
    // Without a valid key there is no range to judge the value by; it must still be a number.
    if (const auto it = j.find("value"); it == j.end())
      r_.fail(path + "/value", "is required: a number");
    else if (!it->is_number() || !std::isfinite(it->get<double>()))
      r_.fail(path + "/value", "must be a number, got " + JsonReader::describe(*it));
    return std::nullopt;
  }

  void check_prop_references() {
    std::set<std::string> names(prop_names_.begin(), prop_names_.end());
    names.insert(spawned_props_.begin(), spawned_props_.end());
    const std::vector<std::string> known(names.begin(), names.end());
    for (const PropReference& ref : prop_references_) {
      if (!ref.name.empty() && std::find(known.begin(), known.end(), ref.name) != known.end()) continue;
      check_reference(r_, ref.path, ref.name, known,
                      ref.impulse_target ? "\"player\", \"all_tires\" or a prop" : "a prop");
    }
  }

  JsonReader& r_;
  const std::vector<std::string>& prop_names_;
  std::vector<std::string> region_names_;   // by region index; "" where the name was invalid
  std::vector<std::string> counter_names_;  // by counter index; "" where the name was invalid
  std::set<std::string> spawned_props_;
  std::vector<PropReference> prop_references_;
};

}  // namespace

const std::vector<SettableKey>& settable_keys() {
  static const std::vector<SettableKey> keys = [] {
    std::vector<SettableKey> out;
    for (const Parameter& p : parameters())
      if (p.may(by_script) && !p.is_tire()) out.push_back({p.key, &p});
    for (const char* prefix : {"player.", "tires."})
      for (const Parameter& p : parameters())
        if (p.may(by_script) && p.is_tire()) out.push_back({prefix + std::string(p.key).substr(6), &p});
    return out;
  }();
  return keys;
}

ScriptSpec read_script(JsonReader& r, const json& level_doc, const std::vector<std::string>& prop_names) {
  return ScriptReader(r, prop_names).read(level_doc);
}

}  // namespace tire
