#include "world_script_host.h"

#include "tire/world/world.h"

namespace tire {

std::uint64_t WorldScriptHost::tick() const { return world_.tick(); }
double WorldScriptHost::dt() const { return world_.config().dt; }

std::optional<TireId> WorldScriptHost::player() const {
  const Tire* p = world_.player();
  return p ? std::optional<TireId>(p->id) : std::nullopt;
}

std::size_t WorldScriptHost::tire_count() const { return world_.tires().size(); }
TireId WorldScriptHost::tire_id(std::size_t index) const { return world_.tires()[index].id; }
Vec2 WorldScriptHost::tire_centroid(std::size_t index) const { return world_.tires()[index].centroid(); }

std::optional<std::size_t> WorldScriptHost::find_prop(std::string_view name) const {
  const auto i = world_.rigid().find_prop(name);
  return i ? std::optional<std::size_t>(*i) : std::nullopt;
}

Vec2 WorldScriptHost::prop_position(std::size_t index) const {
  return world_.rigid().current_pose(static_cast<std::uint32_t>(index)).position;
}

void WorldScriptHost::spawn_tire(const TireSpec& spec) { world_.add_tire(spec); }
void WorldScriptHost::spawn_prop(const PropSpec& spec) { world_.add_prop(spec); }
void WorldScriptHost::remove_prop(std::string_view name) { world_.rigid().remove_prop(name); }
void WorldScriptHost::set_gravity(Vec2 gravity) { world_.set_gravity(gravity); }

void WorldScriptHost::apply_impulse_to_player(Vec2 impulse) {
  if (const Tire* p = world_.player()) world_.apply_impulse_to_tire(p->id, impulse);
}

void WorldScriptHost::apply_impulse_to_all_tires(Vec2 impulse) {
  for (std::size_t i = 0; i < world_.tires().size(); ++i) world_.apply_impulse_to_tire(world_.tires()[i].id, impulse);
}

void WorldScriptHost::apply_impulse_to_prop(std::string_view name, Vec2 impulse) {
  world_.rigid().apply_impulse_now(name, impulse);
}

void WorldScriptHost::set_parameter(std::string_view key, double value) { world_.set_parameter(key, value); }
void WorldScriptHost::path_command(std::string_view prop, PathCommand command) {
  world_.rigid().path_command(prop, command);
}
void WorldScriptHost::show_message(std::string_view text, double seconds) { world_.show_message(text, seconds); }
void WorldScriptHost::set_checkpoint(Vec2 position) { world_.set_checkpoint(position); }
void WorldScriptHost::next_level() { world_.request_next_level(); }

}  // namespace tire
