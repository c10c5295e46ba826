// Hostile input: levels and replays are shared between people, so every file may be an attack. Each
// case here is refused before any real work is done and without building a large tree, with an
// error that names the file, the JSON path and what was expected. The work is counted, never timed
// (JsonWork: bytes read from disk, characters parsed, values and string bytes built), so the suite
// gives the same answer on a slow machine, a busy one and in a Debug or sanitizer build.
#include <unistd.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include "../fuzz/fuzz_common.h"
#include "../fuzz/fuzz_session.h"
#include "error_messages.h"
#include "tire/io/file_io.h"
#include "tire/io/level.h"
#include "tire/replay/replay.h"
#include "tire_fixtures.h"

using tire_test::has;

using namespace tire;
using namespace tire::test;

namespace {

// What every refusal may cost at the most: the tree never holds more than the budget's values (one
// more is the one refused), and no character is read twice or string kept past the text's size.
void check_bounded(const JsonWork& work, std::size_t text_bytes, std::size_t max_values) {
  INFO("parsed " << work.parsed_bytes << " of " << text_bytes << " bytes, " << work.values << " values, "
                 << work.string_bytes << " string bytes");
  CHECK(work.parsed_bytes <= text_bytes);
  CHECK(work.values <= max_values + 1);
  CHECK(work.string_bytes <= text_bytes);
}

// A level refused through load_level_text: returns the load (its errors and what it cost).
LevelLoad refuse_level_load(const std::string& text) {
  LevelLoad load = load_level_text(text, "hostile.json");
  INFO(tire_test::joined(load.errors, 300));
  CHECK_FALSE(load.level.has_value());
  REQUIRE_FALSE(load.errors.empty());
  for (const std::string& e : load.errors) CHECK(e.rfind("hostile.json: ", 0) == 0);  // names the file
  check_bounded(load.work, text.size(), LevelLimits::max_json_values);
  return load;
}

std::vector<std::string> refuse_level(const std::string& text) { return refuse_level_load(text).errors; }

ReplayLoad refuse_replay_load(const std::string& text) {
  JsonWork work;
  ReplayLoad load = load_replay_text(text, "hostile-replay.json", work);
  INFO(tire_test::joined(load.errors, 300));
  CHECK_FALSE(load.replay.has_value());
  REQUIRE_FALSE(load.errors.empty());
  for (const std::string& e : load.errors) CHECK(e.rfind("hostile-replay.json: ", 0) == 0);
  check_bounded(work, text.size(), ReplayLimits::max_json_values);
  return load;
}

std::vector<std::string> refuse_replay(const std::string& text) { return refuse_replay_load(text).errors; }

std::string repeat(const std::string& item, std::size_t n, const std::string& separator = ",") {
  std::string out;
  out.reserve((item.size() + separator.size()) * n);
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0) out += separator;
    out += item;
  }
  return out;
}

std::string tires_level(std::size_t count, int segments) {
  std::string tires;
  tires.reserve(count * 48);
  for (std::size_t i = 0; i < count; ++i)
    tires += (i ? "," : "") + std::string(R"({"position": [)") + std::to_string(i % 100) + ", " +
             std::to_string(1 + i / 100) + R"(], "segments": )" + std::to_string(segments) + "}";
  return R"({"name": "many tires", "tires": [)" + tires + "]}";
}

std::string chain_prop(std::size_t points, double y) {
  std::string p;
  p.reserve(points * 16);
  for (std::size_t i = 0; i < points; ++i)
    p += (i ? ",[" : "[") + std::to_string(static_cast<double>(i) * 0.02) + "," + std::to_string(y) + "]";
  return R"({"shape": "chain", "points": [)" + p + "]}";
}

const std::string kReplayHead = R"({"format": "tire-replay/1", "level": "level.json", "level_sha256": ")" +
                                std::string(64, 'a') + R"(", )";

struct TempFile {
  std::filesystem::path path;
  explicit TempFile(const std::string& name)
      : path(std::filesystem::temp_directory_path() / (std::to_string(::getpid()) + "-" + name)) {}
  ~TempFile() {
    std::error_code ec;
    std::filesystem::remove(path, ec);
  }
};

}  // namespace

TEST_CASE("hostile level: 10 000 tires of 256 segments (5 million particles) is refused", "[unit][hostile]") {
  const auto errors = refuse_level(tires_level(10000, 256));
  CHECK(has(errors,
            "hostile.json: /tires/1953: the particles of the level's tires (2 x segments each), with those "
            "its script spawns, may add up to at most 1000000, got 5120000"));
}

TEST_CASE("hostile level: 10 001 tires are refused, and 10 000 small ones are not", "[unit][hostile]") {
  CHECK(has(refuse_level(tires_level(10001, 6)), "/tires: must have at most 10000 entries, got 10001"));
  const LevelLoad load = load_level_text(tires_level(10000, 6), "ok.json");
  CHECK(load.level.has_value());
}

TEST_CASE("hostile level: a 60 MiB file of whitespace is refused", "[unit][hostile]") {
  TempFile file("whitespace.json");
  {
    std::ofstream out(file.path, std::ios::binary);
    const std::string mib(1 << 20, ' ');
    for (int i = 0; i < 60; ++i) out << mib;
  }
  const LevelLoad load = load_level_file(file.path);
  REQUIRE(load.errors.size() == 1);
  // Read once and scanned once, and nothing built.
  CHECK(load.work.file_bytes == 60u << 20);
  CHECK(load.work.parsed_bytes == 60u << 20);
  CHECK(load.work.values == 0);
  CHECK(load.errors[0].find(file.path.string() + ": invalid JSON: parse error at line 1, column 62914561") ==
        0);
  CHECK(load.errors[0].find("unexpected end of input") != std::string::npos);
}

TEST_CASE("hostile level: a file over 64 MiB is refused before it is read", "[unit][hostile]") {
  TempFile file("huge.json");
  {
    std::ofstream out(file.path, std::ios::binary);
    out.seekp(static_cast<std::streamoff>(1) << 33);  // 8 GiB, sparse
    out.put('}');
  }
  const LevelLoad load = load_level_file(file.path);
  CHECK(has(load.errors, file.path.string() + ": file is 8589934593 bytes; the limit is 67108864"));
  CHECK(load.work.file_bytes == 0);
  CHECK(load.work.parsed_bytes == 0);
}

TEST_CASE("hostile level: nesting bombs are refused while parsing, with the path", "[unit][hostile]") {
  const LevelLoad bomb = refuse_level_load(std::string(1000000, '[') + std::string(1000000, ']'));
  // Refused at the 65th '[' of two million characters.
  CHECK(bomb.work.parsed_bytes == 65);
  CHECK(bomb.work.values == 65);
  const auto& arrays = bomb.errors;
  REQUIRE(arrays.size() == 1);
  std::string pointer;
  for (int i = 0; i < 64; ++i) pointer += "/0";
  CHECK(arrays[0] == "hostile.json: " + pointer +
                         ": nesting deeper than 64 levels; arrays and objects may nest at most 64 deep");
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += R"({"a":)";
  const LevelLoad deep = refuse_level_load(objects);
  CHECK(deep.work.parsed_bytes <= 65 * 5);
  const auto& members = deep.errors;
  CHECK(
      has(members,
          "hostile.json: /a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a"));
  CHECK(has(members, "nesting deeper than 64 levels"));
  // Exactly 64 levels is allowed by the parser (and judged by validation like any other value).
  const auto at_limit = refuse_level(R"({"name": )" + std::string(63, '[') + std::string(63, ']') + "}");
  CHECK(at_limit ==
        std::vector<std::string>{
            "hostile.json: /name: must be a string of at most 200 characters, got an array of 1"});
  CHECK(has(refuse_level(R"({"name": )" + std::string(64, '[') + std::string(64, ']') + "}"),
            "nesting deeper than 64 levels"));
}

TEST_CASE("hostile level: huge and overflowing numbers are refused with their range", "[unit][hostile]") {
  const auto errors = refuse_level(R"({"name": "x", "gravity": [1e308, -1e308],
      "solver": {"dt": 1e308, "substeps": 1e308, "iterations": -1e308},
      "tires": [{"position": [1e308, 0], "segments": 1e308, "mass": 1e308, "outer_radius": 1e-308}],
      "obstacles": [{"min": [-1e308, -1e308], "max": [1e308, 1e308]}],
      "props": [{"shape": "chain", "points": [[0, 0], [1e308, 0]]}]})");
  CHECK(has(errors,
            "hostile.json: /gravity: must be [x, y] with each in [-1000, 1000] m/s^2, got [1e+308,-1e+308]"));
  CHECK(has(errors, "hostile.json: /solver/dt: must be a number in [0.0001, 0.1] s, got 1e+308"));
  CHECK(has(errors, "hostile.json: /solver/substeps: must be an integer in [1, 256], got 1e+308"));
  CHECK(has(errors, "hostile.json: /solver/iterations: must be an integer in [1, 64], got -1e+308"));
  CHECK(
      has(errors,
          "hostile.json: /tires/0/position: must be [x, y] with each in [-10000, 10000] m, got [1e+308,0]"));
  CHECK(has(errors, "hostile.json: /tires/0/segments: must be an integer in [6, 256], got 1e+308"));
  CHECK(has(errors, "hostile.json: /tires/0/mass: must be a number in [0.001, 1e+06] kg, got 1e+308"));
  CHECK(has(errors, "hostile.json: /tires/0/outer_radius: must be a number in [0.01, 100] m, got 1e-308"));
  CHECK(has(errors, "hostile.json: /obstacles/0/min: must be [x, y] with each in [-10000, 10000] m"));
  CHECK(
      has(errors,
          "hostile.json: /props/0/points/1: must be [x, y] with each in [-10000, 10000] m, got [1e+308,0]"));
  // Past double's range the parser itself refuses.
  CHECK(has(refuse_level(R"({"name": "x", "gravity": [0, 1e400]})"),
            "hostile.json: invalid JSON: number overflow parsing '1e400'"));
  // Integers past 64 bits become doubles and are judged by range like any other.
  CHECK(has(
      refuse_level(R"({"name": "x", "tires": [{"position": [0, 1], "segments": 1180591620717411303424}]})"),
      "hostile.json: /tires/0/segments: must be an integer in [6, 256], got 1.1805916207174113e+21"));
  // A subnormal mass is positive, but its particles' inverse masses overflow to infinity: the tire
  // was accepted and then reset by the divergence guard on every tick.
  CHECK(has(refuse_level(R"({"name": "x", "tires": [{"position": [0, 1], "mass": 1e-310}]})"),
            "hostile.json: /tires/0/mass: must be a number in [0.001, 1e+06] kg, got 1e-310"));
}

TEST_CASE("hostile level: long strings and keys are refused while parsing, cut short in messages",
          "[unit][hostile]") {
  const std::string huge(60u << 20, 'a');
  const LevelLoad long_name = refuse_level_load(R"({"name": ")" + huge + R"("})");
  CHECK(long_name.work.string_bytes == 4);  // the key "name"; the string itself is never kept
  CHECK(long_name.work.values == 1);
  const auto& name = long_name.errors;
  CHECK(name == std::vector<std::string>{
                    "hostile.json: /name: a string may be at most 4096 bytes long, got one of 62914560"});
  const auto key = refuse_level(R"({"name": "x", "tires": [{")" + huge + R"(": 1}]})");
  CHECK(key == std::vector<std::string>{
                   "hostile.json: /tires/0/" + std::string(80, 'a') +
                   "...(62914560 bytes): a key may be at most 4096 bytes long, got one of 62914560"});
  // Within the parser's limit, an unknown key of 4 KiB costs no "did you mean" search, and the
  // message shows its start only; a thousand of them are reported as the first 200.
  std::string keys;
  for (int i = 0; i < 1000; ++i) {
    const std::string suffix = std::to_string(i);
    keys += ", \"" + std::string(4000 - suffix.size(), 'k') + suffix + "\": 1";
  }
  const auto unknown = refuse_level(R"({"name": "x")" + keys + "}");
  CHECK(unknown.size() == 201);
  CHECK(has(unknown, "hostile.json: /" + std::string(80, 'k') +
                         "...(4000 bytes): unknown key; expected one of \"$schema\""));
  // A value of 20 long strings is described in a few dozen characters.
  const auto described =
      refuse_level(R"({"name": [)" + repeat("\"" + std::string(4000, 'x') + "\"", 20) + "]}");
  CHECK(described ==
        std::vector<std::string>{
            "hostile.json: /name: must be a string of at most 200 characters, got an array of 20"});
}

TEST_CASE("hostile level: 15 000 long trigger types and action names cost no did-you-mean search",
          "[unit][hostile]") {
  // Each name of 4 KiB was compared with every trigger type and action name: 8 s for this file.
  const std::string name(4090, 't');
  const std::string action = R"({"action": ")" + name + R"("})";
  const std::string trigger =
      R"({"when": {"type": ")" + name + R"("}, "do": [)" + repeat(action, 1000) + "]}";
  const std::string triggers = repeat(trigger, 15);
  const auto errors = refuse_level(R"({"name": "x", "triggers": [)" + triggers + "]}");
  CHECK(errors.front().rfind("hostile.json: /triggers/0/when/type: must be one of \"start\", \"time\"", 0) ==
        0);
  CHECK(errors.back() == "hostile.json: /: more problems follow; only the first 200 are reported");
}

TEST_CASE("hostile level: a chain of 100 000 points loads, one more point or three such chains do not",
          "[unit][hostile]") {
  const std::string level = R"({"name": "long chain", "props": [)" + chain_prop(100000, 0) + "]}";
  const LevelLoad ok = load_level_text(level, "ok.json");
  CHECK(ok.level.has_value());
  CHECK(has(refuse_level(R"({"name": "x", "props": [)" + chain_prop(100001, 0) + "]}"),
            "hostile.json: /props/0/points: must be an array of 2 to 100000 points [x, y] in m, got an array "
            "of 100001"));
  const auto three = refuse_level(R"({"name": "x", "props": [)" + chain_prop(100000, 0) + "," +
                                  chain_prop(100000, 1) + "," + chain_prop(100000, 2) + "]}");
  CHECK(three == std::vector<std::string>{"hostile.json: /props/2: the points of the level's props (chain, "
                                          "polygon and path points), with those its "
                                          "script spawns, may add up to at most 200000, got 300000 (this "
                                          "entry is the first past the limit)"});
}

TEST_CASE("hostile level: a file of millions of values is refused as soon as it passes the budget",
          "[unit][hostile]") {
  const std::string objects_text = R"({"name": "x", "tires": [)" + repeat("{}", 20'000'000) + "]}";
  const LevelLoad objects_load = refuse_level_load(objects_text);
  // Refused at the budget's value: a twentieth of the text is read.
  CHECK(objects_load.work.values == LevelLimits::max_json_values + 1);
  CHECK(objects_load.work.parsed_bytes < objects_text.size() / 10);
  const auto& objects = objects_load.errors;
  CHECK(objects ==
        std::vector<std::string>{"hostile.json: /tires/999997: a level may hold at most 1000000 JSON values "
                                 "(numbers, strings, arrays, objects), and this one holds more"});
  const auto numbers = refuse_level("[" + repeat("0", 30'000'000) + "]");
  CHECK(has(numbers, "hostile.json: /999999: a level may hold at most 1000000 JSON values"));
}

TEST_CASE("hostile level: a million mistakes are reported as the first 200", "[unit][hostile]") {
  std::string obstacles;
  for (int i = 0; i < 100000; ++i)
    obstacles += (i ? "," : "") + std::string(R"({"min": [1, 1], "max": [0, 0], "frition": 1})");
  const auto errors = refuse_level(R"({"name": "x", "obstacles": [)" + obstacles + "]}");
  CHECK(errors.size() == 201);
  CHECK(errors.front() == "hostile.json: /obstacles/0/frition: unknown key; did you mean \"friction\"?");
  CHECK(errors.back() == "hostile.json: /: more problems follow; only the first 200 are reported");
}

TEST_CASE("hostile level: a script cannot spawn past the tire and prop budgets", "[unit][hostile]") {
  const std::string spawn_tire = R"({"action": "spawn_tire", "tire": {"position": [0, 5], "segments": 256}})";
  std::string triggers;
  for (int i = 0; i < 3; ++i)
    triggers.append(i ? "," : "")
        .append(R"({"when": {"type": "start"}, "do": [)")
        .append(repeat(spawn_tire, 1000))
        .append("]}");
  const auto tires = refuse_level(R"({"name": "x", "triggers": [)" + triggers + "]}");
  CHECK(has(tires,
            "hostile.json: /triggers/1/do/953: the particles of the level's tires (2 x segments each), "
            "with those its script spawns, may add up to at most 1000000, got 1536000 (this entry is the "
            "first past the limit)"));
  // And each firing alone passes the tick's budget of spawns (run_budgets.h).
  CHECK(has(tires,
            "hostile.json: /triggers/2/do: one firing adds 1000 tires and props, more than "
            "budgets.spawns_per_tick (16) allows: the rest would be dropped every time it fires"));
  CHECK(tires.size() == 4);
  const std::string spawn_prop = R"({"action": "spawn_prop", "prop": {"shape": "circle", "radius": 1}})";
  triggers.clear();
  for (int i = 0; i < 11; ++i)
    triggers.append(i ? "," : "")
        .append(R"({"when": {"type": "start"}, "do": [)")
        .append(repeat(spawn_prop, 1000))
        .append("]}");
  CHECK(has(refuse_level(R"({"name": "x", "triggers": [)" + triggers + "]}"),
            "hostile.json: /triggers/10/do/0: the level's props, with those its script spawns, may add up to "
            "at most 10000, "
            "got 11000"));
}

TEST_CASE("hostile replay: 10^7 inputs cannot fit, and half a million is the most", "[unit][hostile]") {
  // 10^7 of the shortest input are 230 MB: refused by size before a byte is read.
  TempFile file("ten-million-inputs.json");
  {
    std::ofstream out(file.path, std::ios::binary);
    out.seekp(230'000'000);
    out.put(']');
  }
  const ReplayLoad big = load_replay_file(file.path);
  CHECK(has(big.errors, file.path.string() + ": file is 230000001 bytes; the limit is 67108864"));
  // 600 000 inputs fit in the file size but not in the input limit.
  const auto many = refuse_replay(kReplayHead + R"("ticks": 10, "inputs": [)" +
                                  repeat(R"({"tick":0,"jump":true})", 600000) + "]}");
  CHECK(many == std::vector<std::string>{
                    "hostile-replay.json: /inputs: must have at most 500000 entries, got 600000"});
  const auto values = refuse_replay(kReplayHead + R"("ticks": 10, "inputs": [)" +
                                    repeat(R"({"tick":0,"drag":[0,0]})", 510000) + "]}");
  CHECK(has(values,
            "hostile-replay.json: /inputs/499998/drag/1: a replay may hold at most 2500000 JSON values"));
}

TEST_CASE("hostile replay: 10^8 ticks, huge tuning values and spawn floods are refused", "[unit][hostile]") {
  CHECK(refuse_replay(kReplayHead + R"("ticks": 100000000, "inputs": []})") ==
        std::vector<std::string>{
            "hostile-replay.json: /ticks: must be an integer in [0, 5.184e+06], got 100000000"});
  const auto set = refuse_replay(kReplayHead + R"("ticks": 10, "inputs": [
      {"tick": 0, "set": {"key": "solver.substeps", "value": 1e9}},
      {"tick": 0, "set": {"key": "tires.mass", "value": 0}},
      {"tick": 0, "set": {"key": "player.compliance.outer", "value": -1}},
      {"tick": 0, "set": {"key": "solver.iterations", "value": 2.5}}]})");
  CHECK(
      has(set, "hostile-replay.json: /inputs/0/set/value: must be an integer in [1, 256], got 1000000000.0"));
  // The range of the parameter table's tires.mass, the level's own (tire/parameters.h).
  CHECK(has(set, "hostile-replay.json: /inputs/1/set/value: must be a number in [0.001, 1e+06] kg, got 0"));
  CHECK(has(set, "hostile-replay.json: /inputs/2/set/value: must be a number in [0, 1] m/N, got -1"));
  CHECK(has(set, "hostile-replay.json: /inputs/3/set/value: must be an integer in [1, 64], got 2.5"));
  CHECK(has(
      refuse_replay(kReplayHead + R"("ticks": 10, "inputs": [)" +
                    repeat(R"({"tick":0,"spawn":[0,5]})", 10001) + "]}"),
      "hostile-replay.json: /inputs/10000/spawn: a replay may spawn at most 10000 tires; this is one more"));
  CHECK(has(refuse_replay(kReplayHead + R"("ticks": 10, "inputs": [)" +
                          repeat(R"({"tick":0,"restart":true})", 10001) + "]}"),
            "hostile-replay.json: /inputs/10000/restart: a replay may restart the level at most 10000 times; "
            "this is one more"));
  CHECK(has(refuse_replay(std::string(100000, '[')), "nesting deeper than 64 levels"));
}

TEST_CASE("hostile replay: 100 000 centroid boxes cost nothing on the ticks they do not name",
          "[unit][hostile]") {
  std::string boxes;
  for (int i = 0; i < 100000; ++i)
    boxes +=
        (i ? "," : "") + std::string(R"({"tick": 60, "tire": 0, "min": [-100, -100], "max": [100, 100]})");
  const ReplayLoad load = load_replay_text(
      kReplayHead + R"("ticks": 60, "inputs": [], "expect": {"boxes": [)" + boxes + "]}}", "boxes.json");
  INFO(tire_test::joined(load.errors, 300));
  REQUIRE(load.replay);
  const Level level = default_level();
  const ReplayOutcome outcome = run_replay(*load.replay, level);
  CHECK(outcome.failures.empty());
  CHECK(outcome.box_checks == 100000);  // each box looked at once, on its tick, not on every tick
}

TEST_CASE("fuzz regressions: every input that once broke a fuzz target now passes it",
          "[unit][hostile][fuzz]") {
  std::size_t files = 0;
  for (const std::string target : {"level", "replay", "simulate", "session"}) {
    const std::filesystem::path dir = source_path("tests/fuzz-regressions/" + target);
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::string error;
      const auto text = read_file(entry.path(), LevelLimits::max_file_bytes, error);
      INFO(entry.path().string() << ": " << error);
      REQUIRE(text);
      ++files;
      // The same call the fuzz target makes: its invariants abort on failure.
      if (target == "level")
        fuzz::fuzz_level(*text);
      else if (target == "replay")
        fuzz::fuzz_replay(*text);
      else if (target == "simulate")
        fuzz::fuzz_simulate(*text);
      else
        fuzz::fuzz_session(*text);
      // ".invalid.json" files are refused by tirectl; a level's by the loader, a replay's by the
      // loader or, when its own JSON is fine, because of the level it names.
      const bool invalid = entry.path().string().find(".invalid.json") != std::string::npos;
      if (target == "replay") {
        if (!invalid) CHECK(load_replay_text(*text, "f").replay.has_value());
      } else {
        CHECK(load_level_text(*text, "f").level.has_value() == !invalid);
      }
    }
  }
  CHECK(files > 0);
}

TEST_CASE("hostile level: every key given twice is refused with its path and the first one's line",
          "[unit][hostile]") {
  const std::string text =
      "{\"name\": \"a\",\n"
      " \"solver\": {\"substeps\": 8},\n"
      " \"name\": \"b\",\n"
      " \"solver\": {\"substeps\": 64, \"substeps\": 300},\n"
      " \"tires\": [{\"position\": [0, 1]}, {\"position\": [2, 1],\n"
      "                                     \"mass\": 1, \"mass\": 2}],\n"
      " \"gravity\": [0, -9.81], \"gravity\": [0, -9.81]}";
  const auto errors = refuse_level(text);
  CHECK(has(errors, "hostile.json: /name: key given twice (first at line 1)"));
  CHECK(has(errors, "hostile.json: /solver: key given twice (first at line 2)"));
  CHECK(has(errors, "hostile.json: /solver/substeps: key given twice (first at line 4)"));
  CHECK(has(errors, "hostile.json: /tires/1/mass: key given twice (first at line 6)"));
  CHECK(has(errors, "hostile.json: /gravity: key given twice (first at line 7)"));
  // One pass: the duplicates and the other problems together (the last substeps, 300, is out of range).
  CHECK(has(errors, "hostile.json: /solver/substeps: must be an integer in [1, 256], got 300"));
  CHECK(errors.size() == 6);
  // The same keys in different objects are no duplicates.
  CHECK(load_level_text(
            R"({"name": "a", "tires": [{"mass": 1, "position": [0, 1]}, {"mass": 2, "position": [2, 1]}]})",
            "ok.json")
            .level);
}

TEST_CASE("hostile level: 400 000 duplicated keys are reported as the first 200", "[unit][hostile]") {
  const LevelLoad load =
      refuse_level_load(R"({"name": "x", )" + repeat(R"("name": "y")", 400000, ", ") + "}");
  CHECK(load.errors.size() == 201);
  CHECK(load.errors.front() == "hostile.json: /name: key given twice (first at line 1)");
  CHECK(load.errors.back() == "hostile.json: /: more problems follow; only the first 200 are reported");
}

TEST_CASE("hostile replay: a key given twice is refused with its path", "[unit][hostile]") {
  const auto errors = refuse_replay(kReplayHead + R"("ticks": 10, "ticks": 20,
      "inputs": [{"tick": 0, "steer": 1, "steer": -1}], "expect": {"status": "won", "status": "lost"}})");
  CHECK(has(errors, "hostile-replay.json: /ticks: key given twice (first at line 1)"));
  CHECK(has(errors, "hostile-replay.json: /inputs/0/steer: key given twice (first at line 2)"));
  CHECK(has(errors, "hostile-replay.json: /expect/status: key given twice (first at line 2)"));
  CHECK(errors.size() == 3);
}

TEST_CASE("hostile level: --set refuses nan and inf, naming what was typed", "[unit][hostile]") {
  for (const char* typed : {"nan", "inf", "-inf", "infinity", "NAN"}) {
    const LevelLoad load =
        load_level_text(R"({"name": "x"})", "l.json", {std::string("solver.substeps=") + typed});
    CHECK_FALSE(load.level);
    CHECK(load.errors == std::vector<std::string>{std::string("l.json: --set solver.substeps=") + typed +
                                                  ": value must be a finite number, got " + typed});
  }
}
