#include "tire/world/world.h"

#include <algorithm>
#include <bit>
#include <thread>
#include <cmath>

#include "tire/math/check.h"
#include "tire/math/state_hash.h"
#include "world_script_host.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/tire_solver.h"

namespace tire {

namespace {
// Colours of tire pairs that are solved in parallel; pairs beyond go to colour kColors, solved in order.
constexpr std::uint32_t kColors = 64;
}  // namespace

World::World(const SolverConfig& config, Vec2 gravity)
    : config_(config), gravity_(gravity), rigid_(gravity), threads_(std::max(1u, std::thread::hardware_concurrency())) {
  color_begin_.reserve(66);  // at most 64 colours and the overflow one, plus the end
}
World::~World() = default;
World::World(World&&) noexcept = default;
World& World::operator=(World&&) noexcept = default;

void World::set_script(const ScriptSpec& spec) {
  const bool empty = spec.regions.empty() && spec.triggers.empty() && spec.counters.empty() && !spec.goal &&
                     !spec.time_limit;
  script_ = empty ? nullptr : std::make_unique<ScriptRunner>(spec);
  if (script_) {
    WorldScriptHost host(*this);
    script_->update(host);
  }
}

void World::apply_impulse_to_tire(TireId id, Vec2 impulse) {
  Tire* t = find_tire(id);
  if (!t) return;
  const Vec2 dv = impulse / t->total_mass();
  for (Vec2& v : t->particles.v) v += dv;
}

namespace {
// The tire keys a script or the tuning panel may change, and where each lives.
bool set_tire_key(Tire& t, std::string_view key, double value) {
  TireSpec& s = t.spec;
  if (key == "friction") s.friction = value;
  else if (key == "kinetic_friction") s.kinetic_friction = value;
  else if (key == "pressure") s.pressure = t.area_constraint.pressure = value;
  else if (key == "material_damping") s.material_damping = value;
  else if (key == "rolling_resistance") s.rolling_resistance = value;
  else if (key == "drive_acceleration") s.drive_acceleration = value;
  else if (key == "jump_speed") s.jump_speed = value;
  else if (key == "max_speed") s.max_speed = value;
  else if (key == "mass") t.set_mass(value);
  else if (key == "mass_scale") t.set_mass(t.spawn_mass * value);
  else if (key.starts_with("compliance.")) {
    TireCompliance c = s.compliance;
    const std::string_view part = key.substr(11);
    if (part == "outer") c.outer = value;
    else if (part == "inner") c.inner = value;
    else if (part == "spoke") c.spoke = value;
    else if (part == "pressure") c.pressure = value;
    else return false;
    t.set_compliance(c);
  } else return false;
  return true;
}
}  // namespace

bool World::set_parameter(std::string_view key, double value) {
  if (!std::isfinite(value)) return false;
  if (key == "solver.substeps") return config_.substeps = static_cast<int>(value), true;
  if (key == "solver.iterations") return config_.iterations = static_cast<int>(value), true;
  if (key == "solver.damping") return config_.damping = value, true;
  if (key.starts_with("player.")) {
    const Tire* p = player();
    return p && set_tire_key(*find_tire(p->id), key.substr(7), value);
  }
  if (key.starts_with("tires.")) {
    bool known = true;
    for (Tire& t : tires_) known = set_tire_key(t, key.substr(6), value) && known;
    return known;
  }
  return false;
}

void World::show_message(std::string_view text, double seconds) {
  messages_.push_back({std::string(text), tick_ + static_cast<std::uint64_t>(std::ceil(seconds / config_.dt))});
}

std::optional<TireId> World::grab(Vec2 point, double radius) {
  release_grab();
  // The nearest tread particle within `radius`; failing that, the tire whose hub is under the
  // point, by its nearest tread particle.
  Tire* chosen = nullptr;
  std::uint32_t particle = 0;
  double best = radius * radius;
  for (Tire& t : tires_)
    for (std::uint32_t i = 0; i < t.n; ++i)
      if (const double d2 = length_squared(t.particles.x[i] - point); d2 < best) best = d2, chosen = &t, particle = i;
  if (!chosen) {
    for (Tire& t : tires_) {
      if (length(t.centroid() - point) >= t.spec.outer_radius) continue;
      chosen = &t;
      double nearest = 1e300;
      for (std::uint32_t i = 0; i < t.n; ++i)
        if (const double d2 = length_squared(t.particles.x[i] - point); d2 < nearest) nearest = d2, particle = i;
      break;
    }
  }
  if (!chosen) return std::nullopt;
  chosen->grabbed = true;
  chosen->grab_particle = particle;
  chosen->grab_target = point;
  grabbed_ = chosen->id;
  return grabbed_;
}

void World::move_grab(Vec2 target) {
  if (grabbed_)
    if (Tire* t = find_tire(*grabbed_)) t->grab_target = target;
}

void World::release_grab() {
  if (grabbed_)
    if (Tire* t = find_tire(*grabbed_)) t->grabbed = false;
  grabbed_.reset();
}

void World::respawn_player() {
  const Tire* p = player();
  if (!p) return;
  Tire& t = *find_tire(p->id);
  if (checkpoint_) t.spec.position = *checkpoint_;
  t.reset();
}

TireId World::add_tire(const TireSpec& spec) {
  const TireId id = next_id_++;
  tires_.emplace_back(id, spec);
  if (spec.player || !player_) player_ = id;
  // Room for the contacts between tires, so that stepping never allocates: a tire in a pile
  // touches at most six others, and a pair is counted once.
  const std::size_t pairs = 4 * tires_.size();
  tire_pairs_.reserve(pairs);
  colored_pairs_.reserve(pairs);
  pair_color_.reserve(pairs);
  tire_colors_.reserve(tires_.size());
  return id;
}

bool World::remove_tire(TireId id) {
  const auto it = std::find_if(tires_.begin(), tires_.end(), [id](const Tire& t) { return t.id == id; });
  if (it == tires_.end()) return false;
  tires_.erase(it);
  if (player_ == id) player_.reset();
  return true;
}

Tire* World::find_tire(TireId id) {
  for (Tire& t : tires_)
    if (t.id == id) return &t;
  return nullptr;
}

const Tire* World::player() const {
  for (const Tire& t : tires_)
    if (player_ && t.id == *player_) return &t;
  return nullptr;
}

void World::step(const TickInput& input) {
  TIRE_ASSERT(config_.substeps >= 1 && config_.iterations >= 1, "fewer than one substep or iteration a tick");
  TIRE_ASSERT(config_.dt > 0.0 && std::isfinite(config_.dt), "the tick is not a positive length of time");
  if (player_) {
    if (Tire* p = find_tire(*player_)) {
      p->control.steer = input.steer;
      p->control.jump = input.jump;
    }
  }
  rigid_.begin_tick(config_.dt);
  sweep_tires([&](Tire& t) { begin_tick(t, config_, rigid_); });
  // Tire–tire contacts only when there is more than one tire: a lone tire skips the pass.
  tire_pairs_.clear();
  if (tires_.size() > 1) pair_finder_.find(tires_, config_.dt, length(gravity_), tire_pairs_);
  color_pairs();
  const double h = config_.dt / config_.substeps;
  SubstepContext ctx{h, 0.0, gravity_, &config_, &rigid_, !tire_pairs_.empty()};
  const auto hand_over_impulses = [&] {
    for (Tire& t : tires_) apply_prop_impulses(t, rigid_);
  };
  const auto solve_tire_pairs = [&] {
    for (std::size_t c = 0; c + 1 < color_begin_.size(); ++c) {
      const TirePair* first = colored_pairs_.data() + color_begin_[c];
      auto solve = [&](std::size_t b, std::size_t e) {
        for (std::size_t k = b; k < e; ++k)
          solve_tire_contact(tires_[first[k].a], tires_[first[k].b], config_.ground_normal_y);
      };
      const std::size_t count = color_begin_[c + 1] - color_begin_[c];
      if (c < kColors) for_tires(count, solve);
      else solve(0, count);  // the overflow colour: its pairs may share a tire
    }
  };
  // Each tire's velocity pass of one substep runs in the same sweep over the tires as its prediction
  // and first iteration of the next, so its data is read from memory once per substep, not three
  // times. That is exact when no tire can push a prop: the impulses handed over between the two
  // (which a free prop feels at once) are then always none. With dynamic props, the velocity pass
  // and the hand-over keep their own place.
  const bool fuse_substeps = !rigid_.takes_impulses();
  const auto end_substeps = [&](const SubstepContext& previous) {
    sweep_tires([&](Tire& t) { end_substep(t, previous); });
    hand_over_impulses();
  };
  for (int s = 0; s < config_.substeps; ++s) {
    const SubstepContext previous = ctx;
    ctx.time = s * h;
    const bool end_previous_here = s > 0 && fuse_substeps;
    if (s > 0 && !fuse_substeps) end_substeps(previous);
    sweep_tires([&](Tire& t) {
      if (end_previous_here) end_substep(t, previous);
      begin_substep(t, ctx);
      solve_iteration(t, ctx, config_.iterations == 1);
    });
    hand_over_impulses();
    solve_tire_pairs();
    for (int it = 1; it < config_.iterations; ++it) {
      sweep_tires([&](Tire& t) { solve_iteration(t, ctx, it + 1 == config_.iterations); });
      hand_over_impulses();
      solve_tire_pairs();
    }
  }
  end_substeps(ctx);
  rigid_.end_tick(config_.dt);
  for (Tire& t : tires_) guard_divergence(t);
  ++tick_;
  std::erase_if(messages_, [this](const ScriptMessage& m) { return m.until_tick <= tick_; });
  if (script_) {
    WorldScriptHost host(*this);
    script_->update(host);
  }
}

namespace {
// Below this many tires a tick is too short to be worth waking threads for; below this many items
// (tires, or tire pairs of one colour) neither is a phase.
constexpr std::size_t kParallelMinTires = 32;
constexpr std::size_t kParallelMinItems = 4;
}  // namespace

unsigned World::threads_in_use() const { return tires_.size() >= kParallelMinTires ? threads_ : 1u; }

void World::set_threads(unsigned threads) {
  threads_ = std::max(1u, threads);
  pool_.reset();
}

template <typename F>
void World::sweep_tires(F&& fn) {
  for_tires(tires_.size(), [&](std::size_t b, std::size_t e) {
    for (std::size_t i = b; i < e; ++i) {
      if (i + 1 < e) tires_[i + 1].prefetch();  // memory-bound in big scenes: load the next one early
      fn(tires_[i]);
    }
  });
}

template <typename F>
void World::for_tires(std::size_t n, F&& fn) {
  if (threads_ > 1 && tires_.size() >= kParallelMinTires && n >= kParallelMinItems) {
    if (!pool_) pool_ = std::make_unique<WorkerPool>(threads_);
    pool_->parallel_for(n, fn);
  } else {
    fn(std::size_t{0}, n);
  }
}

void World::color_pairs() {
  // Greedy colouring in pair order: each pair takes the lowest colour neither tire uses yet. A tire
  // with 64 neighbours or more sends its extra pairs to a last colour of their own.
  tire_colors_.assign(tires_.size(), 0);
  pair_color_.resize(tire_pairs_.size());
  std::uint32_t color_count = 0;
  for (std::size_t k = 0; k < tire_pairs_.size(); ++k) {
    const TirePair p = tire_pairs_[k];
    const std::uint64_t used = tire_colors_[p.a] | tire_colors_[p.b];
    const auto c = static_cast<std::uint32_t>(std::countr_one(used));  // 64 when all are taken
    if (c < kColors) {
      tire_colors_[p.a] |= std::uint64_t{1} << c;
      tire_colors_[p.b] |= std::uint64_t{1} << c;
    }
    pair_color_[k] = static_cast<std::uint8_t>(c);
    color_count = std::max(color_count, c + 1);
  }
  // Counting sort by colour, keeping pair order within a colour.
  color_begin_.assign(color_count + 1, 0);
  for (const std::uint8_t c : pair_color_) ++color_begin_[c + 1u];
  for (std::uint32_t c = 0; c < color_count; ++c) color_begin_[c + 1] += color_begin_[c];
  colored_pairs_.resize(tire_pairs_.size());
  for (std::size_t k = 0; k < tire_pairs_.size(); ++k) colored_pairs_[color_begin_[pair_color_[k]]++] = tire_pairs_[k];
  // The scatter moved each start to the next colour's start: shift back.
  for (std::uint32_t c = color_count; c > 0; --c) color_begin_[c] = color_begin_[c - 1];
  color_begin_[0] = 0;
  TIRE_ASSERT(color_begin_.back() == tire_pairs_.size(), "the colours do not hold every tire pair");
  TIRE_ASSERT(colors_share_no_tire(), "two pairs of one parallel colour share a tire: solving them would race");
}

bool World::colors_share_no_tire() {
  std::fill(tire_colors_.begin(), tire_colors_.end(), std::uint64_t{0});
  for (std::uint32_t c = 0; c + 1 < color_begin_.size() && c < kColors; ++c) {
    const std::uint64_t bit = std::uint64_t{1} << c;
    for (std::uint32_t k = color_begin_[c]; k < color_begin_[c + 1]; ++k) {
      const TirePair p = colored_pairs_[k];
      if (p.a == p.b || ((tire_colors_[p.a] | tire_colors_[p.b]) & bit) != 0) return false;
      tire_colors_[p.a] |= bit;
      tire_colors_[p.b] |= bit;
    }
  }
  return true;
}

void World::guard_divergence(Tire& t) {
  if (t.is_finite() && t.max_abs_coordinate() <= config_.divergence_limit) return;
  warnings_.push_back("tick " + std::to_string(tick_) + ": tire " + std::to_string(t.id) +
                      " diverged (NaN, Inf or beyond " + std::to_string(config_.divergence_limit) +
                      " m); reset to its spawn state");
  t.reset();
}

std::uint64_t World::state_hash() const {
  StateHash h;
  h.add(tick_);
  for (const Tire& t : tires_) {
    h.add(t.id);
    h.add_bytes(t.particles.x.data(), t.particles.x.size() * sizeof(Vec2));
    h.add_bytes(t.particles.v.data(), t.particles.v.size() * sizeof(Vec2));
    h.add_bytes(t.grounded_flags.data(), t.grounded_flags.size());
  }
  rigid_.hash_into(h);
  if (script_) script_->hash_into(h);
  return h.digest();
}

}  // namespace tire
