#include "session_script_host.h"

#include "tire/session/level_session.h"

namespace tire {

SessionScriptHost::SessionScriptHost(LevelSession& session) : session_(session), world_(session.world()) {}

std::uint64_t SessionScriptHost::tick() const { return world_.tick(); }
double SessionScriptHost::dt() const { return world_.config().dt; }

std::optional<TireId> SessionScriptHost::player() const {
  const Tire* p = world_.player();
  return p ? std::optional<TireId>(p->id) : std::nullopt;
}

std::size_t SessionScriptHost::tire_count() const { return world_.tires().size(); }
TireId SessionScriptHost::tire_id(std::size_t index) const { return world_.tires()[index].id; }
Vec2 SessionScriptHost::tire_centroid(std::size_t index) const { return world_.tires()[index].centroid(); }

std::optional<Vec2> SessionScriptHost::player_vehicle_center() const {
  if (!world_.player_vehicle()) return std::nullopt;
  return session_.player_position();
}

std::optional<std::size_t> SessionScriptHost::find_prop(std::string_view name) const {
  const auto i = world_.rigid().find_prop(name);
  return i ? std::optional<std::size_t>(*i) : std::nullopt;
}

Vec2 SessionScriptHost::prop_position(std::size_t index) const {
  return world_.rigid().current_pose(static_cast<std::uint32_t>(index)).position;
}

bool SessionScriptHost::take_firing() { return session_.take_firing(); }
void SessionScriptHost::spawn_tire(const TireSpec& spec) { world_.spawn_tire(spec); }
void SessionScriptHost::spawn_prop(const PropSpec& spec) { world_.spawn_prop(spec); }
void SessionScriptHost::remove_prop(std::string_view name) { world_.rigid().remove_prop(name); }
void SessionScriptHost::set_gravity(Vec2 gravity) { world_.set_gravity(gravity); }

void SessionScriptHost::apply_impulse_to_player(Vec2 impulse) {
  if (const std::optional<std::uint32_t> v = world_.player_vehicle())
    world_.apply_impulse_to_vehicle(*v, impulse);
  else if (const Tire* p = world_.player())
    world_.apply_impulse_to_tire(p->id, impulse);
}

void SessionScriptHost::apply_impulse_to_all_tires(Vec2 impulse) {
  for (std::size_t i = 0; i < world_.tires().size(); ++i)
    world_.apply_impulse_to_tire(world_.tires()[i].id, impulse);
}

void SessionScriptHost::apply_impulse_to_prop(std::string_view name, Vec2 impulse) {
  world_.rigid().apply_impulse_now(name, impulse);
}

void SessionScriptHost::set_parameter(std::string_view key, double value) {
  world_.set_parameter(key, value);
}
void SessionScriptHost::path_command(std::string_view prop, PathCommand command) {
  world_.rigid().path_command(prop, command);
}
void SessionScriptHost::show_message(std::string_view text, double seconds) {
  session_.show_message(text, seconds);
}
void SessionScriptHost::set_checkpoint(Vec2 position) { session_.set_checkpoint(position); }
void SessionScriptHost::next_level() { session_.request_next_level(); }

}  // namespace tire
