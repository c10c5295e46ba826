// A level session as its script sees it (ScriptHost), by index over its tires and props.
#pragma once

#include "tire/script/script_host.h"

namespace tire {

class LevelSession;
class World;

class SessionScriptHost final : public ScriptHost {
 public:
  explicit SessionScriptHost(LevelSession& session);

  std::uint64_t tick() const override;
  double dt() const override;
  std::optional<TireId> player() const override;
  std::size_t tire_count() const override;
  TireId tire_id(std::size_t index) const override;
  Vec2 tire_centroid(std::size_t index) const override;
  std::optional<Vec2> player_vehicle_center() const override;
  std::optional<std::size_t> find_prop(std::string_view name) const override;
  Vec2 prop_position(std::size_t index) const override;

  bool take_firing() override;
  void spawn_tire(const TireSpec& spec) override;
  void spawn_prop(const PropSpec& spec) override;
  void remove_prop(std::string_view name) override;
  void set_gravity(Vec2 gravity) override;
  void apply_impulse_to_player(Vec2 impulse) override;
  void apply_impulse_to_all_tires(Vec2 impulse) override;
  void apply_impulse_to_prop(std::string_view name, Vec2 impulse) override;
  void set_parameter(std::string_view key, double value) override;
  void path_command(std::string_view prop, PathCommand command) override;
  void show_message(std::string_view text, double seconds) override;
  void set_checkpoint(Vec2 position) override;
  void next_level() override;

 private:
  LevelSession& session_;
  World& world_;
};

}  // namespace tire
