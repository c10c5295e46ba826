#include "tire/replay/replay.h"

#include <algorithm>
#include <cctype>

#include "tire/io/file_io.h"
#include "tire/math/numbers.h"
#include "tire/math/state_hash.h"

namespace tire {

namespace {

using json = nlohmann::json;
const Range kCoordinate{-LevelLimits::max_coordinate, LevelLimits::max_coordinate};

// What a replay may hold, enforced before the work it asks for, and tighter than ReplayLimits (whose
// 10^8 ticks would run for days and whose 10^7 inputs would need gigabytes as a JSON tree): a day
// of play at 60 Hz, half a million inputs (an hour of dragging every tick is 216 000), and a JSON
// tree of at most about 350 MB.
constexpr std::uintmax_t kMaxFileBytes = 64ull << 20;
constexpr std::uint64_t kMaxTicks = 24ull * 3600 * 60;
constexpr std::size_t kMaxInputs = 500'000;
constexpr std::size_t kMaxCheckpoints = 500'000;
constexpr std::size_t kMaxBoxes = 100'000;
constexpr std::size_t kMaxSpawns = LevelLimits::max_tires;
constexpr std::size_t kMaxRestarts = 10'000;
constexpr JsonBudget kReplayBudget{LevelLimits::max_depth, ReplayLimits::max_json_values,
                                   LevelLimits::max_string_bytes, "a replay"};

// A tick: an integer in [0, max].
std::uint64_t read_tick(JsonReader& r, const json& j, const std::string& path, std::uint64_t max, bool& ok) {
  const std::string p = join_path(path, "tick");
  const auto it = j.find("tick");
  if (it == j.end()) {
    r.fail(p, "is required: an integer tick in [0, " + std::to_string(max) + "]");
    ok = false;
    return 0;
  }
  if (!it->is_number_unsigned() && !(it->is_number_integer() && it->get<std::int64_t>() >= 0)) {
    r.fail(p,
           "must be an integer tick in [0, " + std::to_string(max) + "], got " + JsonReader::describe(*it));
    ok = false;
    return 0;
  }
  const auto tick = it->get<std::uint64_t>();
  if (tick > max) {
    r.fail(p, "must be at most " + std::to_string(max) + " (the replay's last tick), got " +
                  std::to_string(tick));
    ok = false;
  }
  return tick;
}

bool read_flag(JsonReader& r, const json& j, const std::string& path, const char* key) {
  const auto it = j.find(key);
  if (it == j.end()) return false;
  const bool value = r.boolean(j, path, key, false);
  if (it->is_boolean() && !value)
    r.fail(join_path(path, key), "must be true when present (leave it out otherwise), got false");
  return value;
}

ReplayInput read_input(JsonReader& r, const json& j, const std::string& path, std::uint64_t ticks) {
  ReplayInput in;
  if (!r.object(j, path,
                {"tick", "steer", "jump", "inflate", "lean", "brake", "spawn", "grab", "grab_radius", "drag",
                 "release", "set", "gravity", "restart"}))
    return in;
  bool ok = true;
  // Inputs act before the step of their tick, so the last one that can act is ticks − 1.
  in.tick = read_tick(r, j, path, ticks == 0 ? 0 : ticks - 1, ok);
  if (j.contains("steer")) in.steer = r.number(j, path, "steer", 0.0, {-1.0, 1.0}, "");
  if (j.contains("inflate")) in.inflate = r.number(j, path, "inflate", 0.0, {-1.0, 1.0}, "");
  if (j.contains("lean")) in.lean = r.number(j, path, "lean", 0.0, {-1.0, 1.0}, "");
  if (j.contains("brake")) in.brake = r.boolean(j, path, "brake", false);
  in.jump = read_flag(r, j, path, "jump");
  if (j.contains("spawn")) in.spawn = r.vec2(j, path, "spawn", {}, kCoordinate, "m");
  if (j.contains("grab")) in.grab = r.vec2(j, path, "grab", {}, kCoordinate, "m");
  in.grab_radius = r.number(j, path, "grab_radius", kGrabRadius, {0.0, 100.0}, "m");
  if (j.contains("drag")) in.drag = r.vec2(j, path, "drag", {}, kCoordinate, "m");
  in.release = read_flag(r, j, path, "release");
  if (j.contains("gravity")) {
    const Parameter& g = parameter(ParamId::gravity_x);  // gravity.y has the same range
    in.gravity = r.vec2(j, path, "gravity", {}, g.range, g.unit);
  }
  in.restart = read_flag(r, j, path, "restart");
  if (const auto it = j.find("set"); it != j.end()) {
    const std::string p = join_path(path, "set");
    if (r.object(*it, p, {"key", "value"})) {
      const std::string key = r.string(*it, p, "key", "", 100, true);
      const Parameter* param = key.empty() ? nullptr : find_parameter(key);
      if (!key.empty() && !(param && param->may(by_replay)))
        r.fail(join_path(p, "key"),
               "must be a tunable key such as \"tires.pressure\" or \"solver.substeps\", got \"" +
                   printable(key) + "\"");
      else if (!key.empty())
        in.set_key = key;
      // A value the world can take (the parameter table's range): 10^9 substeps would never finish
      // a tick, a mass or mass scale of 0 divides by it.
      if (in.set_key)
        in.set_value =
            param->integer
                ? r.integer(*it, p, "value", static_cast<int>(param->default_value), param->range, true)
                : r.number(*it, p, "value", param->default_value, param->range, param->unit, true);
      else
        in.set_value = r.number(*it, p, "value", 0.0, {-1e9, 1e9}, "", true);
    }
  }
  if (j.size() == 1 && j.contains("tick")) r.fail(path, "has a tick but no input (steer, jump, spawn, ...)");
  return in;
}

ReplayExpect read_expect(JsonReader& r, const json& j, const std::string& path, std::uint64_t ticks) {
  ReplayExpect e;
  if (!r.object(j, path, {"status", "checkpoints", "hash", "boxes"})) return e;
  if (j.contains("status")) e.status = r.choice(j, path, "status", "running", {"running", "won", "lost"});
  if (j.contains("hash")) {
    if (!j["hash"].is_string() || !is_lowercase_hex(j["hash"].get<std::string>(), 16))
      r.fail(path + "/hash", "must be 16 lowercase hex digits, got " + JsonReader::describe(j["hash"]));
    else
      e.hash = j["hash"].get<std::string>();
  }
  if (const auto it = j.find("checkpoints");
      it != j.end() && r.array(*it, path + "/checkpoints", kMaxCheckpoints)) {
    std::uint64_t previous = 0;
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string p = join_path(path + "/checkpoints", i);
      const json& c = (*it)[i];
      if (!r.object(c, p, {"tick", "hash"})) continue;
      bool ok = true;
      ReplayCheckpoint cp{read_tick(r, c, p, ticks, ok), r.string(c, p, "hash", "", 16, true)};
      if (ok && i > 0 && cp.tick <= previous)
        r.fail(p + "/tick", "must be after the previous checkpoint's tick " + std::to_string(previous) +
                                ", got " + std::to_string(cp.tick));
      if (!cp.hash.empty() && !is_lowercase_hex(cp.hash, 16))
        r.fail(p + "/hash", "must be 16 lowercase hex digits, got \"" + printable(cp.hash) + "\"");
      previous = cp.tick;
      e.checkpoints.push_back(cp);
    }
  }
  if (const auto it = j.find("boxes"); it != j.end() && r.array(*it, path + "/boxes", kMaxBoxes)) {
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string p = join_path(path + "/boxes", i);
      const json& b = (*it)[i];
      if (!r.object(b, p, {"tick", "tire", "min", "max"})) continue;
      bool ok = true;
      ReplayBox box;
      box.tick = read_tick(r, b, p, ticks, ok);
      box.tire = static_cast<std::size_t>(r.integer(b, p, "tire", 0, {0, 1e7}));
      box.min = r.vec2(b, p, "min", {}, kCoordinate, "m", true);
      box.max = r.vec2(b, p, "max", {}, kCoordinate, "m", true);
      if (!(box.min.x <= box.max.x && box.min.y <= box.max.y))
        r.fail(p + "/max", "must be at least min on both axes");
      e.boxes.push_back(box);
    }
  }
  return e;
}

}  // namespace

bool is_tunable_key(std::string_view key) {
  const Parameter* p = find_parameter(key);
  return p && p->may(by_replay);
}

std::optional<Replay> read_replay(const json& doc, std::vector<JsonIssue>& issues) {
  const std::size_t before = issues.size();
  JsonReader r(issues);
  Replay replay;
  if (!r.object(doc, "", {"format", "level", "level_sha256", "ticks", "inputs", "expect"}))
    return std::nullopt;
  const std::string format = r.string(doc, "", "format", "", 40, true);
  if (!format.empty() && format != kReplayFormat)
    r.fail("/format", std::string("must be \"") + kReplayFormat + "\", got \"" + printable(format) + "\"");
  replay.level = r.string(doc, "", "level", "", 4096, true);
  // The level is found from the replay file's folder (load_replay_level): a path relative to it, as
  // the recorders write it. An absolute path would name the same file on every machine, whatever
  // it is; "" would name the folder.
  if (const auto it = doc.find("level");
      it != doc.end() && it->is_string() &&
      (replay.level.empty() || std::filesystem::path(replay.level).is_absolute() ||
       replay.level.find('\0') != std::string::npos))
    r.fail("/level",
           "must be the level file's path relative to the replay file's folder (as "
           "\"../levels/01-first-roll.json\"), got " +
               JsonReader::describe(*it));
  replay.level_sha256 = r.string(doc, "", "level_sha256", "", 64, true);
  if (doc.contains("level_sha256") && !is_lowercase_hex(replay.level_sha256, 64))
    r.fail("/level_sha256", "must be 64 lowercase hex digits (SHA-256 of the level file), got " +
                                JsonReader::describe(doc["level_sha256"]));
  replay.ticks =
      static_cast<std::uint64_t>(r.integer(doc, "", "ticks", 0, {0, static_cast<double>(kMaxTicks)}, true));
  if (const auto it = doc.find("inputs"); it != doc.end() && r.array(*it, "/inputs", kMaxInputs)) {
    std::size_t spawns = 0, restarts = 0;
    // This tick's steer and jump so far (their inputs' indices): inputs sharing a tick all act, in
    // file order, but a second steer would silently replace the first and a second jump would do
    // nothing, and a restart drops the steer given before it (a level starts unsteered). Each is
    // refused rather than left for the last to win.
    constexpr std::size_t kNone = SIZE_MAX;
    std::size_t tick_steer = kNone, tick_jump = kNone, tick_inflate = kNone, tick_lean = kNone,
                tick_brake = kNone;
    replay.inputs.reserve(it->size());
    for (std::size_t i = 0; i < it->size(); ++i) {
      const std::string path = join_path("/inputs", i);
      replay.inputs.push_back(read_input(r, (*it)[i], path, replay.ticks));
      const ReplayInput& in = replay.inputs[i];
      if (i > 0 && in.tick < replay.inputs[i - 1].tick)
        r.fail(path + "/tick", "inputs must be in tick order: " + std::to_string(in.tick) + " comes after " +
                                   std::to_string(replay.inputs[i - 1].tick));
      if (i == 0 || in.tick != replay.inputs[i - 1].tick) {
        tick_steer = kNone;
        tick_jump = kNone;
        tick_inflate = kNone;
        tick_lean = kNone;
        tick_brake = kNone;
      }
      if (in.restart && tick_steer != kNone)
        r.fail(path + "/restart",
               "restarts the level after the steer of /inputs/" + std::to_string(tick_steer) +
                   " on the same tick " + std::to_string(in.tick) +
                   ", which the restart drops (a level starts unsteered); give the steer after the restart");
      if (in.restart) tick_steer = kNone;
      if (in.steer && tick_steer != kNone)
        r.fail(path + "/steer", "a second steer on tick " + std::to_string(in.tick) +
                                    " (the first is /inputs/" + std::to_string(tick_steer) +
                                    "/steer): only the last would act; give one steer per tick");
      if (in.jump && tick_jump != kNone)
        r.fail(path + "/jump", "a second jump on tick " + std::to_string(in.tick) +
                                   " (the first is /inputs/" + std::to_string(tick_jump) +
                                   "/jump): give one jump per tick");
      if (in.inflate && tick_inflate != kNone)
        r.fail(path + "/inflate", "a second inflate on tick " + std::to_string(in.tick) +
                                      " (the first is /inputs/" + std::to_string(tick_inflate) +
                                      "/inflate): only the last would act; give one inflate per tick");
      if (in.lean && tick_lean != kNone)
        r.fail(path + "/lean", "a second lean on tick " + std::to_string(in.tick) +
                                   " (the first is /inputs/" + std::to_string(tick_lean) +
                                   "/lean): only the last would act; give one lean per tick");
      if (in.brake && tick_brake != kNone)
        r.fail(path + "/brake", "a second brake on tick " + std::to_string(in.tick) +
                                    " (the first is /inputs/" + std::to_string(tick_brake) +
                                    "/brake): only the last would act; give one brake per tick");
      if (in.lean) tick_lean = i;
      if (in.brake) tick_brake = i;
      if (in.steer) tick_steer = i;
      if (in.jump) tick_jump = i;
      if (in.inflate) tick_inflate = i;
      // Each spawn builds a tire and each restart the whole level: bounded like a level's tires.
      if (in.spawn && ++spawns == kMaxSpawns + 1)
        r.fail(path + "/spawn",
               "a replay may spawn at most " + std::to_string(kMaxSpawns) + " tires; this is one more");
      if (in.restart && ++restarts == kMaxRestarts + 1)
        r.fail(path + "/restart", "a replay may restart the level at most " + std::to_string(kMaxRestarts) +
                                      " times; this is one more");
    }
  }
  if (const auto it = doc.find("expect"); it != doc.end())
    replay.expect = read_expect(r, *it, "/expect", replay.ticks);
  if (issues.size() != before) return std::nullopt;
  return replay;
}

ReplayLoad load_replay_text(const std::string& text, const std::string& file, JsonWork& work) {
  ReplayLoad out;
  const JsonParse parse = parse_json_bounded(text, kReplayBudget);
  work = parse.work;
  if (!parse.doc) {
    out.errors.push_back(printable(file) + ": " + parse.error);
    return out;
  }
  std::vector<JsonIssue> issues;
  report_duplicates(parse, issues);
  out.replay = read_replay(*parse.doc, issues);
  if (!issues.empty()) out.replay.reset();
  for (const JsonIssue& issue : issues)
    out.errors.push_back(printable(file) + ": " + (issue.path.empty() ? "/" : issue.path) + ": " +
                         issue.message);
  return out;
}

ReplayLoad load_replay_text(const std::string& text, const std::string& file) {
  JsonWork work;
  return load_replay_text(text, file, work);
}

ReplayLoad load_replay_file(const std::filesystem::path& file) {
  std::string error;
  const auto text = read_file(file, std::min(kMaxFileBytes, ReplayLimits::max_file_bytes), error);
  if (!text) return {std::nullopt, {printable(file.string()) + ": " + error}};
  return load_replay_text(*text, file.string());
}

ReplayLevel load_replay_level(const std::filesystem::path& replay_file, const Replay& replay) {
  ReplayLevel out;
  out.path = replay_file.parent_path() / replay.level;
  const std::string where = printable(replay_file.string()) + ": /level: ";
  const std::string shown = printable(out.path.string());
  // `replay --update` rewrites the replay: never as its own level.
  if (same_file(out.path, replay_file)) {
    out.errors.push_back(where + "names the replay file itself (" + shown + ")");
    return out;
  }
  std::string error;
  const std::optional<std::string> text = read_file(out.path, LevelLimits::max_file_bytes, error);
  if (!text) {
    out.errors.push_back(where + "cannot read " + shown + ": " + error);
    return out;
  }
  LevelLoad load = load_level_text(*text, out.path.string());
  if (!load.level) {
    // The loader's messages, under the replay's /level, without the JSON parser's excerpt of the
    // bytes it stopped at: the file may be anything the replay's author named.
    for (std::string e : load.errors) {
      if (e.starts_with(shown + ": ")) e.erase(0, shown.size() + 2);
      if (const auto cut = e.find("; last read: "); cut != std::string::npos) e.resize(cut);
      out.errors.push_back(where + shown + " is not a valid level: " + e);
    }
    return out;
  }
  out.level = std::make_shared<const Level>(std::move(*load.level));
  out.sha256 = sha256_hex(*text);
  return out;
}

std::optional<std::string> level_changed(const ReplayLevel& level, const Replay& replay) {
  if (level.sha256 == replay.level_sha256) return std::nullopt;
  return level.path.string() + " has changed since this replay was recorded (SHA-256 " + level.sha256 +
         ", recorded on " + replay.level_sha256 + ")";
}

std::string replay_to_json(const Replay& replay) {
  using ojson = nlohmann::ordered_json;
  const auto vec = [](Vec2 v) { return ojson::array({v.x, v.y}); };
  ojson inputs = ojson::array();
  for (const ReplayInput& in : replay.inputs) {
    ojson o{{"tick", in.tick}};
    if (in.steer) o["steer"] = *in.steer;
    if (in.inflate) o["inflate"] = *in.inflate;
    if (in.lean) o["lean"] = *in.lean;
    if (in.brake) o["brake"] = *in.brake;
    if (in.jump) o["jump"] = true;
    if (in.spawn) o["spawn"] = vec(*in.spawn);
    if (in.grab) o["grab"] = vec(*in.grab);
    if (in.grab && in.grab_radius != kGrabRadius) o["grab_radius"] = in.grab_radius;
    if (in.drag) o["drag"] = vec(*in.drag);
    if (in.release) o["release"] = true;
    if (in.set_key) o["set"] = {{"key", *in.set_key}, {"value", in.set_value}};
    if (in.gravity) o["gravity"] = vec(*in.gravity);
    if (in.restart) o["restart"] = true;
    inputs.push_back(o);
  }
  ojson expect = ojson::object();
  if (replay.expect.status) expect["status"] = *replay.expect.status;
  ojson checkpoints = ojson::array();
  for (const ReplayCheckpoint& c : replay.expect.checkpoints)
    checkpoints.push_back({{"tick", c.tick}, {"hash", c.hash}});
  expect["checkpoints"] = checkpoints;
  if (replay.expect.hash) expect["hash"] = *replay.expect.hash;
  if (!replay.expect.boxes.empty()) {
    ojson boxes = ojson::array();
    for (const ReplayBox& b : replay.expect.boxes)
      boxes.push_back({{"tick", b.tick}, {"tire", b.tire}, {"min", vec(b.min)}, {"max", vec(b.max)}});
    expect["boxes"] = boxes;
  }
  const ojson doc{{"format", kReplayFormat}, {"level", replay.level}, {"level_sha256", replay.level_sha256},
                  {"ticks", replay.ticks},   {"inputs", inputs},      {"expect", expect}};
  return doc.dump(1) + "\n";
}

void apply_input(const ReplayInput& in, LevelSession& session, const Level& level, TickInput& held) {
  if (in.restart) {
    session = std::move(*make_session(level));
    held.steer = held.inflate = held.lean = 0.0;
    held.brake = false;
  }
  World& world = session.world();
  if (in.steer) held.steer = *in.steer;
  if (in.inflate) held.inflate = *in.inflate;
  if (in.lean) held.lean = *in.lean;
  if (in.brake) held.brake = *in.brake;
  if (in.jump) held.jump = true;
  if (in.spawn) {
    TireSpec spec;
    spec.position = *in.spawn;
    world.spawn_tire(spec);  // within the level's budgets (run_budgets.h)
  }
  if (in.grab) session.grab(*in.grab, in.grab_radius);
  if (in.drag) session.move_grab(*in.drag);
  if (in.release) session.release_grab();
  if (in.set_key) world.set_parameter(*in.set_key, in.set_value);
  if (in.gravity) world.set_gravity(*in.gravity);
}

ReplayOutcome run_replay(const Replay& replay, const Level& level,
                         const std::function<void(std::uint64_t)>& after_tick) {
  ReplayOutcome out;
  std::unique_ptr<LevelSession> session = make_session(level);
  InputFeed feed(replay.inputs);
  std::size_t next_checkpoint = 0, next_box = 0;
  // The boxes in tick order (file order within a tick): each tick looks only at its own, so that
  // 100 000 boxes cost nothing on the ticks they do not name.
  std::vector<const ReplayBox*> boxes;
  boxes.reserve(replay.expect.boxes.size());
  for (const ReplayBox& b : replay.expect.boxes) boxes.push_back(&b);
  std::stable_sort(boxes.begin(), boxes.end(),
                   [](const ReplayBox* a, const ReplayBox* b) { return a->tick < b->tick; });
  const auto check = [&](std::uint64_t tick) {
    while (next_checkpoint < replay.expect.checkpoints.size() &&
           replay.expect.checkpoints[next_checkpoint].tick == tick) {
      const ReplayCheckpoint& want = replay.expect.checkpoints[next_checkpoint++];
      const std::string got = to_hex(session->state_hash());
      out.checkpoints.push_back({tick, got});
      if (got == want.hash) {
        if (!out.first_divergent_tick) out.last_matching_tick = tick;
      } else if (!out.first_divergent_tick) {
        out.first_divergent_tick = tick;
        out.failures.push_back("state diverged at tick " + std::to_string(tick) + ": hash " + got +
                               ", expected " + want.hash + " (it still matched at tick " +
                               std::to_string(out.last_matching_tick.value_or(0)) + ")");
      }
    }
    for (; next_box < boxes.size() && boxes[next_box]->tick <= tick; ++next_box) {
      const ReplayBox& b = *boxes[next_box];
      ++out.box_checks;
      if (b.tick != tick) continue;
      if (b.tire >= session->world().tires().size()) {
        out.failures.push_back("tick " + std::to_string(tick) + ": no tire " + std::to_string(b.tire) +
                               " (there are " + std::to_string(session->world().tires().size()) + ")");
        continue;
      }
      const Vec2 c = session->world().tires()[b.tire].centroid();
      if (c.x < b.min.x || c.x > b.max.x || c.y < b.min.y || c.y > b.max.y)
        out.failures.push_back("tick " + std::to_string(tick) + ": tire " + std::to_string(b.tire) +
                               " centroid (" + std::to_string(c.x) + ", " + std::to_string(c.y) +
                               ") is outside its box");
    }
  };
  check(0);
  for (std::uint64_t tick = 0; tick < replay.ticks; ++tick) {
    step(feed, *session, level);
    check(tick + 1);
    if (after_tick) after_tick(tick + 1);
  }
  out.status = to_string(session->status());
  out.hash = to_hex(session->state_hash());
  if (replay.expect.status && *replay.expect.status != out.status)
    out.failures.push_back("status is " + out.status + ", expected " + *replay.expect.status);
  if (replay.expect.hash && *replay.expect.hash != out.hash) {
    out.failures.push_back("final hash is " + out.hash + ", expected " + *replay.expect.hash);
    if (!out.first_divergent_tick) out.first_divergent_tick = replay.ticks;
  }
  return out;
}

void step(InputFeed& feed, LevelSession& session, const Level& level) {
  session.step(feed.next_tick(
      [&](const ReplayInput& input, TickInput& held) { apply_input(input, session, level, held); }));
}

ReplayRecorder::ReplayRecorder(std::string level_path, std::string level_sha256,
                               std::uint64_t checkpoint_every)
    : checkpoint_every_(checkpoint_every) {
  replay_.level = std::move(level_path);
  replay_.level_sha256 = std::move(level_sha256);
}

void ReplayRecorder::after_step(std::uint64_t state_hash) {
  ++replay_.ticks;
  if (checkpoint_every_ > 0 && replay_.ticks % checkpoint_every_ == 0)
    replay_.expect.checkpoints.push_back({replay_.ticks, to_hex(state_hash)});
}

Replay ReplayRecorder::finish(ScriptStatus status, std::uint64_t state_hash) const {
  Replay r = replay_;
  r.expect.status = to_string(status);
  r.expect.hash = to_hex(state_hash);
  return r;
}

}  // namespace tire
