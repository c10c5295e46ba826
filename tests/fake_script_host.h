// A ScriptHost without physics: tires and props are points the test moves by hand, and every
// action is recorded as one line of text, in the order the script issued it.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "tire/script/script_host.h"
#include "tire/script/script_runner.h"

namespace tire::test {

class FakeScriptHost : public ScriptHost {
 public:
  struct FakeTire {
    TireId id;
    Vec2 centroid;
  };
  struct FakeProp {
    std::string name;
    Vec2 position;
  };

  std::uint64_t now = 0;
  double step = 0.1;  // dt (s): a round number, so that times map to ticks visibly
  std::optional<TireId> player_id;
  std::vector<FakeTire> tires;
  std::vector<FakeProp> props;
  std::vector<std::string> calls;  // "spawn_tire 1 2", "message Hello 3", ...
  TireId next_id = 100;            // ids of spawned tires

  // Adds a tire at `where`; the first one added becomes the player.
  TireId add_tire(Vec2 where) {
    const TireId id = next_id++;
    tires.push_back({id, where});
    if (!player_id) player_id = id;
    return id;
  }
  void move_tire(TireId id, Vec2 where) {
    for (FakeTire& t : tires)
      if (t.id == id) t.centroid = where;
  }
  void move_prop(const std::string& name, Vec2 where) {
    for (FakeProp& p : props)
      if (p.name == name) p.position = where;
  }
  // Runs one tick the way the game does: the clock advances, then the script looks.
  void advance(ScriptRunner& runner) {
    ++now;
    runner.update(*this);
  }

  std::uint64_t tick() const override { return now; }
  double dt() const override { return step; }
  std::optional<TireId> player() const override { return player_id; }
  std::size_t tire_count() const override { return tires.size(); }
  TireId tire_id(std::size_t index) const override { return tires[index].id; }
  Vec2 tire_centroid(std::size_t index) const override { return tires[index].centroid; }
  std::optional<std::size_t> find_prop(std::string_view name) const override {
    for (std::size_t i = 0; i < props.size(); ++i)
      if (props[i].name == name) return i;
    return std::nullopt;
  }
  Vec2 prop_position(std::size_t index) const override { return props[index].position; }

  void spawn_tire(const TireSpec& spec) override {
    const TireId id = next_id++;
    tires.push_back({id, spec.position});
    if (spec.player) player_id = id;
    record("spawn_tire", spec.position);
  }
  void spawn_prop(const PropSpec& spec) override {
    props.push_back({spec.name, spec.position});
    record("spawn_prop " + spec.name, spec.position);
  }
  void remove_prop(std::string_view name) override {
    props.erase(std::remove_if(props.begin(), props.end(), [&](const FakeProp& p) { return p.name == name; }),
                props.end());
    calls.push_back("remove_prop " + std::string(name));
  }
  void set_gravity(Vec2 gravity) override { record("set_gravity", gravity); }
  void apply_impulse_to_player(Vec2 impulse) override { record("impulse player", impulse); }
  void apply_impulse_to_all_tires(Vec2 impulse) override { record("impulse all_tires", impulse); }
  void apply_impulse_to_prop(std::string_view name, Vec2 impulse) override {
    record("impulse " + std::string(name), impulse);
  }
  void set_parameter(std::string_view key, double value) override {
    std::ostringstream s;
    s << "set " << key << " " << value;
    calls.push_back(s.str());
  }
  void path_command(std::string_view prop, PathCommand command) override {
    const char* names[] = {"start", "stop", "reverse"};
    calls.push_back("path " + std::string(prop) + " " + names[static_cast<int>(command)]);
  }
  void show_message(std::string_view text, double seconds) override {
    std::ostringstream s;
    s << "message " << text << " " << seconds;
    calls.push_back(s.str());
  }
  void set_checkpoint(Vec2 position) override { record("checkpoint", position); }
  void next_level() override { calls.push_back("next_level"); }

  // How many recorded calls start with `prefix`.
  std::size_t count(const std::string& prefix) const {
    return static_cast<std::size_t>(std::count_if(calls.begin(), calls.end(), [&](const std::string& c) {
      return c.compare(0, prefix.size(), prefix) == 0;
    }));
  }

 private:
  void record(const std::string& what, Vec2 v) {
    std::ostringstream s;
    s << what << " " << v.x << " " << v.y;
    calls.push_back(s.str());
  }
};

}  // namespace tire::test
