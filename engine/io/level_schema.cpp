#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <vector>

#include "script_reader.h"
#include "tire/io/level_format.h"
#include "tire/tire/parameters.h"

namespace tire {

namespace {

using ojson = nlohmann::ordered_json;

constexpr std::size_t kWidth = 100;

// A whole number as an integer ("256", not "256.0"); anything else as a double.
ojson number(double v) {
  if (std::floor(v) == v && std::fabs(v) < 9.0e15) return static_cast<std::int64_t>(v);
  return v;
}

std::string number_for_docs(double v) {
  const double magnitude = std::fabs(v);
  if (magnitude >= 1e5) {
    const int exponent = static_cast<int>(std::lround(std::log10(magnitude)));
    if (std::pow(10.0, exponent) == magnitude) {
      static constexpr const char* kSuperscript[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
      std::string digits;
      for (const char c : std::to_string(exponent)) digits += kSuperscript[c - '0'];
      return std::string(v < 0 ? "-" : "") + "10" + digits;
    }
  }
  std::ostringstream s;
  s << v;
  return s.str();
}

// The bounds of a range as schema keywords, into `o`.
void put_bounds(ojson& o, const Range& range) {
  o[range.min_open ? "exclusiveMinimum" : "minimum"] = number(range.min);
  o[range.max_open ? "exclusiveMaximum" : "maximum"] = number(range.max);
}

ojson property(const Parameter& p) {
  ojson o;
  o["type"] = p.integer ? "integer" : "number";
  put_bounds(o, p.range);
  // A default that follows another key is not a fixed value: an example instead.
  if (p.default_follows)
    o["examples"] = ojson::array({number(p.default_value)});
  else
    o["default"] = number(p.default_value);
  o["description"] = described(p.description, p.range);
  return o;
}

// The object of $defs that holds a level row's key: "solver", "compliance" or "tire".
const char* definition_of(const Parameter& p) {
  const std::string_view key(p.key);
  if (key.starts_with("solver.")) return "solver";
  if (key.starts_with("budgets.")) return "budgets";
  if (key.starts_with("tires.compliance.")) return "compliance";
  if (key.starts_with("tires.")) return "tire";
  return nullptr;
}

ojson& at(ojson& node, const char* key, const std::string& where) {
  if (!node.is_object() || !node.contains(key)) throw std::runtime_error("no " + where + "/" + key);
  return node[key];
}

// The `set` action: its keys, and per group of keys with the same range, a rule for the value.
void generate_set_action(ojson& action) {
  ojson names = ojson::array();
  for (const SettableKey& k : settable_keys()) names.push_back(k.key);
  at(at(action, "properties", "action_set"), "key", "action_set/properties")["enum"] = names;

  struct Group {
    const Parameter* first;
    std::vector<std::string> keys;
  };
  std::vector<Group> groups;
  for (const SettableKey& k : settable_keys()) {
    Group* group = nullptr;
    for (Group& g : groups)
      if (g.first->range == k.parameter->range && g.first->integer == k.parameter->integer) group = &g;
    if (!group) group = &groups.emplace_back(Group{k.parameter, {}});
    group->keys.push_back(k.key);
  }
  ojson rules = ojson::array();
  for (const Group& g : groups) {
    ojson selector;
    if (g.keys.size() == 1)
      selector["const"] = g.keys.front();
    else
      selector["enum"] = g.keys;
    ojson value;
    if (g.first->integer) value["type"] = "integer";
    put_bounds(value, g.first->range);
    ojson rule;
    rule["if"] = {{"required", {"key"}}, {"properties", {{"key", selector}}}};
    rule["then"] = {{"properties", {{"value", value}}}};
    rules.push_back(rule);
  }
  action["allOf"] = rules;
}

std::string scalar(const ojson& v) {
  std::string text = v.dump();
  if (!v.is_number_float()) return text;
  // "1e-06" reads "1e-6"; "1e+06" reads "1e6".
  const std::size_t e = text.find('e');
  if (e == std::string::npos) return text;
  std::string mantissa = text.substr(0, e), exponent = text.substr(e + 1);
  std::string sign;
  if (exponent[0] == '+' || exponent[0] == '-') {
    if (exponent[0] == '-') sign = "-";
    exponent.erase(0, 1);
  }
  exponent.erase(0, std::min(exponent.find_first_not_of('0'), exponent.size() - 1));
  return mantissa + "e" + sign + exponent;
}

std::string one_line(const ojson& v) {
  if (v.is_object()) {
    if (v.empty()) return "{}";
    std::string out = "{ ";
    bool first = true;
    for (const auto& [key, child] : v.items()) {
      out += (first ? "" : ", ") + ojson(key).dump() + ": " + one_line(child);
      first = false;
    }
    return out + " }";
  }
  if (v.is_array()) {
    if (v.empty()) return "[]";
    std::string out = "[";
    for (std::size_t i = 0; i < v.size(); ++i) out += (i ? ", " : "") + one_line(v[i]);
    return out + "]";
  }
  return scalar(v);
}

// `column`: where the value starts on its line.
void write(std::string& out, const ojson& v, std::size_t indent, std::size_t column) {
  const std::string line = one_line(v);
  if ((!v.is_object() && !v.is_array()) || v.empty() || column + line.size() <= kWidth) {
    out += line;
    return;
  }
  const std::string inner(indent + 2, ' ');
  if (v.is_object()) {
    out += "{\n";
    std::size_t i = 0;
    for (const auto& [key, child] : v.items()) {
      const std::string name = ojson(key).dump() + ": ";
      out += inner + name;
      write(out, child, indent + 2, inner.size() + name.size());
      out += ++i < v.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "}";
  } else {
    out += "[\n";
    for (std::size_t i = 0; i < v.size(); ++i) {
      out += inner;
      write(out, v[i], indent + 2, inner.size());
      out += i + 1 < v.size() ? ",\n" : "\n";
    }
    out += std::string(indent, ' ') + "]";
  }
}

}  // namespace

std::string range_for_docs(const Range& range) {
  return std::string(range.min_open ? "(" : "[") + number_for_docs(range.min) + ", " +
         number_for_docs(range.max) + (range.max_open ? ")" : "]");
}

std::string described(std::string_view description, const Range& range) {
  std::string text(description);
  const std::size_t at = text.find("{range}");
  if (at != std::string::npos) text.replace(at, 7, range_for_docs(range));
  return text;
}

std::string format_json(const ojson& value) {
  std::string out;
  write(out, value, 0, 0);
  return out + "\n";
}

SchemaGeneration generate_level_schema(const std::string& current) {
  SchemaGeneration out;
  try {
    ojson doc = ojson::parse(current);
    ojson& defs = at(doc, "$defs", "");
    for (const Parameter& p : parameters()) {
      if (!p.may(by_level)) continue;
      const char* definition = definition_of(p);
      if (!definition) throw std::runtime_error(std::string("no definition holds the level key ") + p.key);
      at(at(defs, definition, "/$defs"), "properties", std::string("/$defs/") + definition)[p.field()] =
          property(p);
    }
    // Gravity: the level's, a set_gravity action's; each component in the table's range.
    const Parameter& g = parameter(ParamId::gravity_x);
    ojson& acceleration = at(defs, "acceleration", "/$defs");
    put_bounds(at(acceleration, "items", "/$defs/acceleration"), g.range);
    acceleration["description"] = described("An acceleration [x, y] (m/s²), each in {range}.", g.range);
    ojson& gravity = at(at(doc, "properties", ""), "gravity", "/properties");
    gravity["description"] = described("Gravity [x, y] (m/s²), each in {range}.", g.range);
    gravity["default"] = ojson::array({number(parameter(ParamId::gravity_x).default_value),
                                       number(parameter(ParamId::gravity_y).default_value)});
    at(at(at(defs, "action_set_gravity", "/$defs"), "properties", "/$defs/action_set_gravity"), "gravity",
       "/$defs/action_set_gravity/properties")["description"] =
        described("New gravity [x, y] (m/s²), each in {range}.", g.range);
    generate_set_action(at(defs, "action_set", "/$defs"));
    // A tire's material, as its level key has it: the presets in the table's order, the default, and
    // the description as a sentence.
    const LevelKey& material = *find_level_key(LevelObject::tire, "material");
    std::string sentence = material.description + " (levels/README.md, Materials).";
    sentence[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(sentence[0])));
    at(at(defs, "tire", "/$defs"), "properties", "/$defs/tire")["material"] =
        ojson{{"type", "string"},
              {"enum", material.choices},
              {"default", material.default_value.get<std::string>()},
              {"description", sentence}};
    out.text = format_json(doc);
  } catch (const std::exception& e) {
    out.error = e.what();
  }
  return out;
}

}  // namespace tire
