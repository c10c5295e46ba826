// Hostile input: levels and replays are shared between people, so every file may be an attack. Each
// case here is refused before any real work is done, quickly (the CPU time is measured) and without
// a large memory peak, with an error that names the file, the JSON path and what was expected.
#include <sys/resource.h>
#include <unistd.h>

#include <catch2/catch.hpp>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "../fuzz/fuzz_common.h"
#include "file_io.h"
#include "level.h"
#include "replay.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

// Sanitizers make every instruction several times slower and every allocation much slower (a JSON
// tree is millions of them): under AddressSanitizer the budgets below are stretched.
#if defined(__SANITIZE_ADDRESS__)
constexpr double kSlowdown = 15.0;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr double kSlowdown = 15.0;
#else
constexpr double kSlowdown = 1.0;
#endif
#else
constexpr double kSlowdown = 1.0;
#endif

// A refusal may take this much CPU time. The work measured is only the refusal: building the
// hostile text is done before the clock starts. (CPU time, not wall time, so that a loaded machine
// running the suite in parallel does not fail the test; the wall time is reported.)
constexpr double kRefusalSeconds = 1.0;
// And the process may peak at this many MiB while refusing (the hostile text itself included).
constexpr double kPeakMiB = 600.0;

double peak_rss_mib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

// Runs `refuse`, checks it took under the CPU budget and kept the peak memory bounded.
void timed(const char* what, const std::function<void()>& refuse) {
  const std::clock_t cpu0 = std::clock();
  const auto wall0 = std::chrono::steady_clock::now();
  refuse();
  const double cpu = static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC;
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double peak = peak_rss_mib();
  std::printf("hostile input: %-52s %7.3f s CPU  %7.3f s wall  peak RSS %6.1f MiB\n", what, cpu, wall, peak);
  INFO(what << ": " << cpu << " s CPU, " << wall << " s wall, peak RSS " << peak << " MiB");
  CHECK(cpu < kRefusalSeconds * kSlowdown);
  CHECK(peak < kPeakMiB * (kSlowdown > 1.0 ? 2.0 : 1.0));
}

bool has(const std::vector<std::string>& errors, const std::string& needle) {
  for (const std::string& e : errors)
    if (e.find(needle) != std::string::npos) return true;
  return false;
}

std::string joined(const std::vector<std::string>& errors) {
  std::string out;
  for (const std::string& e : errors) out += e.substr(0, 300) + "\n";
  return out;
}

// A level refused through load_level_text: returns its errors.
std::vector<std::string> refuse_level(const char* what, const std::string& text) {
  LevelLoad load;
  timed(what, [&] { load = load_level_text(text, "hostile.json"); });
  INFO(joined(load.errors));
  CHECK_FALSE(load.level.has_value());
  REQUIRE_FALSE(load.errors.empty());
  for (const std::string& e : load.errors) CHECK(e.rfind("hostile.json: ", 0) == 0);  // names the file
  return load.errors;
}

std::vector<std::string> refuse_replay(const char* what, const std::string& text) {
  ReplayLoad load;
  timed(what, [&] { load = load_replay_text(text, "hostile-replay.json"); });
  INFO(joined(load.errors));
  CHECK_FALSE(load.replay.has_value());
  REQUIRE_FALSE(load.errors.empty());
  for (const std::string& e : load.errors) CHECK(e.rfind("hostile-replay.json: ", 0) == 0);
  return load.errors;
}

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
  for (std::size_t i = 0; i < points; ++i) p += (i ? ",[" : "[") + std::to_string(static_cast<double>(i) * 0.02) + "," + std::to_string(y) + "]";
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
  const auto errors = refuse_level("10 000 tires x 256 segments", tires_level(10000, 256));
  CHECK(has(errors, "hostile.json: /tires/1953: the particles of the level's tires (2 x segments each), with those "
                    "its script spawns, may add up to at most 1000000, got 5120000"));
}

TEST_CASE("hostile level: 10 001 tires are refused, and 10 000 small ones are not", "[unit][hostile]") {
  CHECK(has(refuse_level("10 001 tires", tires_level(10001, 6)), "/tires: must have at most 10000 entries, got 10001"));
  LevelLoad load;
  timed("10 000 tires of 6 segments (valid)", [&] { load = load_level_text(tires_level(10000, 6), "ok.json"); });
  CHECK(load.level.has_value());
}

TEST_CASE("hostile level: a 60 MiB file of whitespace is refused", "[unit][hostile]") {
  TempFile file("whitespace.json");
  {
    std::ofstream out(file.path, std::ios::binary);
    const std::string mib(1 << 20, ' ');
    for (int i = 0; i < 60; ++i) out << mib;
  }
  LevelLoad load;
  timed("60 MiB of whitespace (file)", [&] { load = load_level_file(file.path); });
  REQUIRE(load.errors.size() == 1);
  CHECK(load.errors[0].find(file.path.string() + ": invalid JSON: parse error at line 1, column 62914561") == 0);
  CHECK(load.errors[0].find("unexpected end of input") != std::string::npos);
}

TEST_CASE("hostile level: a file over 64 MiB is refused before it is read", "[unit][hostile]") {
  TempFile file("huge.json");
  {
    std::ofstream out(file.path, std::ios::binary);
    out.seekp(static_cast<std::streamoff>(1) << 33);  // 8 GiB, sparse
    out.put('}');
  }
  LevelLoad load;
  timed("8 GiB file (sparse)", [&] { load = load_level_file(file.path); });
  CHECK(has(load.errors, file.path.string() + ": file is 8589934593 bytes; the limit is 67108864"));
}

TEST_CASE("hostile level: nesting bombs are refused while parsing, with the path", "[unit][hostile]") {
  const auto arrays = refuse_level("nesting bomb [[[[... (1 million deep)", std::string(1000000, '[') + std::string(1000000, ']'));
  REQUIRE(arrays.size() == 1);
  std::string pointer;
  for (int i = 0; i < 64; ++i) pointer += "/0";
  CHECK(arrays[0] == "hostile.json: " + pointer + ": nesting deeper than 64 levels; arrays and objects may nest at most 64 deep");
  std::string objects;
  for (int i = 0; i < 100000; ++i) objects += R"({"a":)";
  const auto members = refuse_level("nesting bomb {\"a\":{\"a\":... (100 000 deep)", objects);
  CHECK(has(members, "hostile.json: /a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a/a"));
  CHECK(has(members, "nesting deeper than 64 levels"));
  // Exactly 64 levels is allowed by the parser (and judged by validation like any other value).
  const auto at_limit = refuse_level("64 levels of nesting", R"({"name": )" + std::string(63, '[') + std::string(63, ']') + "}");
  CHECK(at_limit == std::vector<std::string>{"hostile.json: /name: must be a string of at most 200 characters, got an array of 1"});
  CHECK(has(refuse_level("65 levels of nesting", R"({"name": )" + std::string(64, '[') + std::string(64, ']') + "}"),
            "nesting deeper than 64 levels"));
}

TEST_CASE("hostile level: huge and overflowing numbers are refused with their range", "[unit][hostile]") {
  const auto errors = refuse_level("numbers 1e308", R"({"name": "x", "gravity": [1e308, -1e308],
      "solver": {"dt": 1e308, "substeps": 1e308, "iterations": -1e308},
      "tires": [{"position": [1e308, 0], "segments": 1e308, "mass": 1e308, "outer_radius": 1e-308}],
      "obstacles": [{"min": [-1e308, -1e308], "max": [1e308, 1e308]}],
      "props": [{"shape": "chain", "points": [[0, 0], [1e308, 0]]}]})");
  CHECK(has(errors, "hostile.json: /gravity: must be [x, y] with each in [-1000, 1000] m/s^2, got [1e+308,-1e+308]"));
  CHECK(has(errors, "hostile.json: /solver/dt: must be a number in [0.0001, 0.1] s, got 1e+308"));
  CHECK(has(errors, "hostile.json: /solver/substeps: must be an integer in [1, 256], got 1e+308"));
  CHECK(has(errors, "hostile.json: /solver/iterations: must be an integer in [1, 64], got -1e+308"));
  CHECK(has(errors, "hostile.json: /tires/0/position: must be [x, y] with each in [-10000, 10000] m, got [1e+308,0]"));
  CHECK(has(errors, "hostile.json: /tires/0/segments: must be an integer in [6, 256], got 1e+308"));
  CHECK(has(errors, "hostile.json: /tires/0/mass: must be a number in (0, 1e+06] kg, got 1e+308"));
  CHECK(has(errors, "hostile.json: /tires/0/outer_radius: must be a number in [0.01, 100] m, got 1e-308"));
  CHECK(has(errors, "hostile.json: /obstacles/0/min: must be [x, y] with each in [-10000, 10000] m"));
  CHECK(has(errors, "hostile.json: /props/0/points/1: must be [x, y] with each in [-10000, 10000] m, got [1e+308,0]"));
  // Past double's range the parser itself refuses.
  CHECK(has(refuse_level("number 1e400", R"({"name": "x", "gravity": [0, 1e400]})"),
            "hostile.json: invalid JSON: number overflow parsing '1e400'"));
  // Integers past 64 bits become doubles and are judged by range like any other.
  CHECK(has(refuse_level("integer 2^70", R"({"name": "x", "tires": [{"position": [0, 1], "segments": 1180591620717411303424}]})"),
            "hostile.json: /tires/0/segments: must be an integer in [6, 256], got 1.1805916207174113e+21"));
}

TEST_CASE("hostile level: long strings and keys are refused while parsing, cut short in messages", "[unit][hostile]") {
  const std::string huge(60u << 20, 'a');
  const auto name = refuse_level("60 MiB string", R"({"name": ")" + huge + R"("})");
  CHECK(name == std::vector<std::string>{"hostile.json: /name: a string may be at most 4096 bytes long, got one of 62914560"});
  const auto key = refuse_level("60 MiB key", R"({"name": "x", "tires": [{")" + huge + R"(": 1}]})");
  CHECK(key == std::vector<std::string>{"hostile.json: /tires/0/" + std::string(80, 'a') +
                                        "...(62914560 bytes): a key may be at most 4096 bytes long, got one of 62914560"});
  // Within the parser's limit, an unknown key of 4 KiB costs no "did you mean" search, and the
  // message shows its start only; a thousand of them are reported as the first 200.
  std::string keys;
  for (int i = 0; i < 1000; ++i) {
    const std::string suffix = std::to_string(i);
    keys += ", \"" + std::string(4000 - suffix.size(), 'k') + suffix + "\": 1";
  }
  const auto unknown = refuse_level("1000 unknown keys of 4000 bytes", R"({"name": "x")" + keys + "}");
  CHECK(unknown.size() == 201);
  CHECK(has(unknown, "hostile.json: /" + std::string(80, 'k') + "...(4000 bytes): unknown key; expected one of \"$schema\""));
  // A value of 20 long strings is described in a few dozen characters.
  const auto described = refuse_level("name of 20 strings of 4 KiB", R"({"name": [)" + repeat("\"" + std::string(4000, 'x') + "\"", 20) + "]}");
  CHECK(described == std::vector<std::string>{"hostile.json: /name: must be a string of at most 200 characters, got an array of 20"});
}

TEST_CASE("hostile level: 15 000 long trigger types and action names cost no did-you-mean search", "[unit][hostile]") {
  // Each name of 4 KiB was compared with every trigger type and action name: 8 s for this file.
  const std::string name(4090, 't');
  const std::string action = R"({"action": ")" + name + R"("})";
  const std::string trigger = R"({"when": {"type": ")" + name + R"("}, "do": [)" + repeat(action, 1000) + "]}";
  const std::string triggers = repeat(trigger, 15);
  const auto errors = refuse_level("15 000 names of 4 KiB in a script", R"({"name": "x", "triggers": [)" + triggers + "]}");
  CHECK(errors.front().rfind("hostile.json: /triggers/0/when/type: must be one of \"start\", \"time\"", 0) == 0);
  CHECK(errors.back() == "hostile.json: /: more problems follow; only the first 200 are reported");
}

TEST_CASE("hostile level: a chain of 100 000 points loads, one more point or three such chains do not", "[unit][hostile]") {
  LevelLoad ok;
  const std::string level = R"({"name": "long chain", "props": [)" + chain_prop(100000, 0) + "]}";
  timed("chain of 100 000 points (valid)", [&] { ok = load_level_text(level, "ok.json"); });
  CHECK(ok.level.has_value());
  CHECK(has(refuse_level("chain of 100 001 points", R"({"name": "x", "props": [)" + chain_prop(100001, 0) + "]}"),
            "hostile.json: /props/0/points: must be an array of 2 to 100000 points [x, y] in m, got an array of 100001"));
  const auto three = refuse_level("three chains of 100 000 points", R"({"name": "x", "props": [)" + chain_prop(100000, 0) + "," +
                                                                         chain_prop(100000, 1) + "," + chain_prop(100000, 2) + "]}");
  CHECK(three == std::vector<std::string>{
                     "hostile.json: /props/2: the points of the level's props (chain, polygon and path points), with those its "
                     "script spawns, may add up to at most 200000, got 300000 (this entry is the first past the limit)"});
}

TEST_CASE("hostile level: a file of millions of values is refused as soon as it passes the budget", "[unit][hostile]") {
  const auto objects = refuse_level("20 million empty objects", R"({"name": "x", "tires": [)" + repeat("{}", 20'000'000) + "]}");
  CHECK(objects == std::vector<std::string>{"hostile.json: /tires/999997: a level may hold at most 1000000 JSON values "
                                            "(numbers, strings, arrays, objects), and this one holds more"});
  const auto numbers = refuse_level("30 million numbers", "[" + repeat("0", 30'000'000) + "]");
  CHECK(has(numbers, "hostile.json: /999999: a level may hold at most 1000000 JSON values"));
}

TEST_CASE("hostile level: a million mistakes are reported as the first 200", "[unit][hostile]") {
  std::string obstacles;
  for (int i = 0; i < 100000; ++i) obstacles += (i ? "," : "") + std::string(R"({"min": [1, 1], "max": [0, 0], "frition": 1})");
  const auto errors = refuse_level("100 000 obstacles, each wrong twice", R"({"name": "x", "obstacles": [)" + obstacles + "]}");
  CHECK(errors.size() == 201);
  CHECK(errors.front() == "hostile.json: /obstacles/0/frition: unknown key; did you mean \"friction\"?");
  CHECK(errors.back() == "hostile.json: /: more problems follow; only the first 200 are reported");
}

TEST_CASE("hostile level: a script cannot spawn past the tire and prop budgets", "[unit][hostile]") {
  const std::string spawn_tire = R"({"action": "spawn_tire", "tire": {"position": [0, 5], "segments": 256}})";
  std::string triggers;
  for (int i = 0; i < 3; ++i)
    triggers += (i ? "," : "") + std::string(R"({"when": {"type": "start"}, "do": [)") + repeat(spawn_tire, 1000) + "]}";
  const auto tires = refuse_level("3000 spawn_tire actions of 256 segments", R"({"name": "x", "triggers": [)" + triggers + "]}");
  CHECK(tires == std::vector<std::string>{
                     "hostile.json: /triggers/1/do/953: the particles of the level's tires (2 x segments each), with those "
                     "its script spawns, may add up to at most 1000000, got 1536000 (this entry is the first past the limit)"});
  const std::string spawn_prop = R"({"action": "spawn_prop", "prop": {"shape": "circle", "radius": 1}})";
  triggers.clear();
  for (int i = 0; i < 11; ++i)
    triggers += (i ? "," : "") + std::string(R"({"when": {"type": "start"}, "do": [)") + repeat(spawn_prop, 1000) + "]}";
  CHECK(has(refuse_level("11 000 spawn_prop actions", R"({"name": "x", "triggers": [)" + triggers + "]}"),
            "hostile.json: /triggers/10/do/0: the level's props, with those its script spawns, may add up to at most 10000, "
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
  ReplayLoad big;
  timed("replay of 230 MB (10^7 inputs)", [&] { big = load_replay_file(file.path); });
  CHECK(has(big.errors, file.path.string() + ": file is 230000001 bytes; the limit is 67108864"));
  // 600 000 inputs fit in the file size but not in the input limit.
  const auto many = refuse_replay("replay of 600 000 inputs",
                                  kReplayHead + R"("ticks": 10, "inputs": [)" + repeat(R"({"tick":0,"jump":true})", 600000) + "]}");
  CHECK(many == std::vector<std::string>{"hostile-replay.json: /inputs: must have at most 500000 entries, got 600000"});
  const auto values = refuse_replay("replay of 2.55 million values",
                                    kReplayHead + R"("ticks": 10, "inputs": [)" + repeat(R"({"tick":0,"drag":[0,0]})", 510000) + "]}");
  CHECK(has(values, "hostile-replay.json: /inputs/499998/drag/1: a replay may hold at most 2500000 JSON values"));
}

TEST_CASE("hostile replay: 10^8 ticks, huge tuning values and spawn floods are refused", "[unit][hostile]") {
  CHECK(refuse_replay("replay of 10^8 ticks", kReplayHead + R"("ticks": 100000000, "inputs": []})") ==
        std::vector<std::string>{"hostile-replay.json: /ticks: must be an integer in [0, 5.184e+06], got 100000000"});
  const auto set = refuse_replay("replay setting 10^9 substeps and no mass", kReplayHead + R"("ticks": 10, "inputs": [
      {"tick": 0, "set": {"key": "solver.substeps", "value": 1e9}},
      {"tick": 0, "set": {"key": "tires.mass", "value": 0}},
      {"tick": 0, "set": {"key": "player.compliance.outer", "value": -1}},
      {"tick": 0, "set": {"key": "solver.iterations", "value": 2.5}}]})");
  CHECK(has(set, "hostile-replay.json: /inputs/0/set/value: must be an integer in [1, 256], got 1000000000.0"));
  CHECK(has(set, "hostile-replay.json: /inputs/1/set/value: must be a number in (0, 1e+07] kg, got 0"));
  CHECK(has(set, "hostile-replay.json: /inputs/2/set/value: must be a number in [0, 1] m/N, got -1"));
  CHECK(has(set, "hostile-replay.json: /inputs/3/set/value: must be an integer in [1, 64], got 2.5"));
  CHECK(has(refuse_replay("replay spawning 10 001 tires",
                          kReplayHead + R"("ticks": 10, "inputs": [)" + repeat(R"({"tick":0,"spawn":[0,5]})", 10001) + "]}"),
            "hostile-replay.json: /inputs/10000/spawn: a replay may spawn at most 10000 tires; this is one more"));
  CHECK(has(refuse_replay("replay restarting 10 001 times",
                          kReplayHead + R"("ticks": 10, "inputs": [)" + repeat(R"({"tick":0,"restart":true})", 10001) + "]}"),
            "hostile-replay.json: /inputs/10000/restart: a replay may restart the level at most 10000 times; this is one more"));
  CHECK(has(refuse_replay("replay nesting bomb", std::string(100000, '[')), "nesting deeper than 64 levels"));
}

TEST_CASE("hostile replay: 100 000 centroid boxes cost nothing on the ticks they do not name", "[unit][hostile]") {
  std::string boxes;
  for (int i = 0; i < 100000; ++i)
    boxes += (i ? "," : "") + std::string(R"({"tick": 60, "tire": 0, "min": [-100, -100], "max": [100, 100]})");
  const ReplayLoad load = load_replay_text(kReplayHead + R"("ticks": 60, "inputs": [], "expect": {"boxes": [)" + boxes + "]}}",
                                           "boxes.json");
  INFO(joined(load.errors));
  REQUIRE(load.replay);
  const Level level = default_level();
  ReplayOutcome outcome;
  timed("replay of 60 ticks with 100 000 boxes", [&] { outcome = run_replay(*load.replay, level); });
  CHECK(outcome.failures.empty());
}

TEST_CASE("fuzz regressions: every input that once broke a fuzz target now passes it", "[unit][hostile][fuzz]") {
  std::size_t files = 0;
  for (const std::string target : {"level", "replay", "simulate"}) {
    const std::filesystem::path dir = source_path("tests/fuzz-regressions/" + target);
    if (!std::filesystem::is_directory(dir)) continue;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      std::string error;
      const auto text = read_file(entry.path(), LevelLimits::max_file_bytes, error);
      INFO(entry.path().string() << ": " << error);
      REQUIRE(text);
      ++files;
      // The same call the fuzz target makes: its invariants abort on failure.
      timed(entry.path().filename().c_str(), [&] {
        if (target == "level") fuzz::fuzz_level(*text);
        else if (target == "replay") fuzz::fuzz_replay(*text);
        else fuzz::fuzz_simulate(*text);
      });
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
