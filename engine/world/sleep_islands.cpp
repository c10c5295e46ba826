#include "tire/world/sleep_islands.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tire/math/trig.h"

namespace tire {

namespace {

// f(p) for each prop an island joins to tire t: those its broad phase found near it, and a wheel's
// chassis, near or not (a vehicle sleeps and wakes whole; its chassis hangs on its wheels).
template <typename F>
void for_each_prop_near(const Tire& t, F&& f) {
  for (const std::uint32_t p : t.prop_candidates) f(p);
  if (t.chassis >= 0) f(static_cast<std::uint32_t>(t.chassis));
}

// Marks where tire t is now as where it became still: its hub, and each particle's offset from it.
void mark_still(Tire& t, Vec2 hub) {
  t.still_anchor = hub;
  for (std::size_t k = 0; k < t.particles.size(); ++k) t.still_shape[k] = t.particles.x[k] - hub;
}

// How tire t (hub at `hub`) stands against the shape it had when it became still (Tire::
// still_shape, offsets s_k): the turn θ that best lays those offsets onto today's, r_k (the least
// squares rotation, tan θ = Σ s_k × r_k / Σ s_k · r_k), and the root mean square of what is left,
// |r_k − R(θ) s_k|: how far its shape has changed, its turn taken out.
struct ShapeChange {
  double turn = 0.0;      // rad
  double deformed = 0.0;  // m
};
ShapeChange shape_change(const Tire& t, Vec2 hub) {
  const Particles& p = t.particles;
  double c = 0.0, s = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec2 r = p.x[k] - hub;
    c += dot(t.still_shape[k], r);
    s += cross(t.still_shape[k], r);
  }
  const double norm = std::sqrt(c * c + s * s);
  if (!(norm > 0.0)) return {0.0, std::numeric_limits<double>::infinity()};
  const double cos_t = c / norm, sin_t = s / norm;
  double left2 = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k) {
    left2 += length_squared(p.x[k] - hub - rotate(t.still_shape[k], cos_t, sin_t));
  }
  return {tire::atan2(s, c), std::sqrt(left2 / static_cast<double>(p.size()))};
}

// The tire's motion over the tick's last substep, from its positions (Tire::substep_motion), not
// its velocities: the velocity pass leaves in them what the next solve takes back (the kinetic
// friction of a contact that slips while the solve holds the tire in place), so a tire wedged in a
// pile can keep 0.3 rad/s of spin in v while it does not move by a micrometre. `deform2`: the mean
// over the particles of |u − the rigid motion's|², u their motion.
RigidMotion last_motion(const Tire& t, double h, double& deform2) {
  const RigidMotion m = t.substep_motion(h);
  const Particles& p = t.particles;
  deform2 = 0.0;
  for (std::size_t k = 0; k < p.size(); ++k)
    deform2 += length_squared((p.x[k] - p.x_prev[k]) / h - m.velocity - perp(p.x[k] - m.centroid) * m.omega);
  deform2 /= static_cast<double>(p.size());
  return m;
}

}  // namespace

void SleepIslands::reserve(std::size_t tires, std::size_t props) {
  awake_.reserve(tires);
  sleeping_.reserve(tires);
  bounds_.resize(std::max(bounds_.size(), tires));
  woken_.reserve(tires);
  parent_.resize(std::max(parent_.size(), tires + props));
  still_.resize(std::max(still_.size(), tires));
  blocked_.resize(std::max(blocked_.size(), tires));
  members_.reserve(tires);
  island_.reserve(tires);
  near_.resize(std::max(near_.size(), props));
  picked_.resize(std::max(picked_.size(), props));
  props_.reserve(props);
  stale_ = true;
}

void SleepIslands::refresh(const std::vector<Tire>& tires) {
  awake_.clear();
  sleeping_.clear();
  widest_ = 0.0;
  for (std::uint32_t i = 0; i < tires.size(); ++i) {
    const Tire& t = tires[i];
    if (!t.asleep) {
      awake_.push_back(i);
      continue;
    }
    // The tread bounds the tire; the skin is the broad phase's between tires.
    const Aabb b = bounds_of(std::span<const Vec2>(t.particles.x.data(), t.n)).expanded(kTirePairSkin);
    bounds_[i] = b;
    widest_ = std::max(widest_, b.max.x - b.min.x);
    sleeping_.push_back({b.min.x, i});
  }
  std::sort(sleeping_.begin(), sleeping_.end(), [](const Entry& l, const Entry& r) {
    return l.min_x < r.min_x || (l.min_x == r.min_x && l.index < r.index);
  });
  asleep_ = sleeping_.size();
  stale_ = false;
}

void SleepIslands::gather_props(const std::vector<Tire>& tires, std::span<const std::uint32_t> members,
                                const RigidWorld& rigid) {
  props_.clear();
  for (const std::uint32_t i : members)
    for_each_prop_near(tires[i], [&](std::uint32_t p) {
      if (!picked_[p] && rigid.props()[p].alive && rigid.props()[p].spec.type == PropType::dynamic_body) {
        picked_[p] = 1;
        props_.push_back(p);
      }
    });
  for (const std::uint32_t p : props_) picked_[p] = 0;
}

bool SleepIslands::wake(std::vector<Tire>& tires, std::uint32_t i, RigidWorld& rigid) {
  if (!tires[i].asleep) return false;
  const TireId island = tires[i].island;
  island_.clear();
  for (std::uint32_t j = 0; j < tires.size(); ++j) {
    Tire& t = tires[j];
    if (!t.asleep || t.island != island) continue;
    t.asleep = false;
    t.still_time = 0.0;
    mark_still(t, t.centroid());
    --asleep_;
    island_.push_back(j);
    woken_.push_back(j);
  }
  gather_props(tires, island_, rigid);
  rigid.wake_group(props_);
  stale_ = true;
  return true;
}

void SleepIslands::wake_all(std::vector<Tire>& tires, RigidWorld& rigid) {
  for (std::uint32_t i = 0; i < tires.size(); ++i) wake(tires, i, rigid);
}

std::uint32_t SleepIslands::find(std::uint32_t node) {
  while (parent_[node] != node) {
    parent_[node] = parent_[parent_[node]];  // path halving
    node = parent_[node];
  }
  return node;
}

void SleepIslands::join(std::uint32_t a, std::uint32_t b) {
  a = find(a);
  b = find(b);
  if (a == b) return;
  // The lower index is the root: an island's root is its first tire, whatever the order of joins.
  if (b < a) std::swap(a, b);
  parent_[b] = a;
}

void SleepIslands::settle(std::vector<Tire>& tires, std::span<const TirePair> pairs, RigidWorld& rigid,
                          const SolverConfig& config, std::optional<std::uint32_t> keep_awake) {
  const auto n = static_cast<std::uint32_t>(tires.size());
  const double limit2 = config.sleep_deform_speed * config.sleep_deform_speed;
  bool any_ready = false;
  const double h = config.dt / config.substeps;
  for (const std::uint32_t i : awake_) {
    Tire& t = tires[i];
    double deform2 = 0.0;
    const RigidMotion m = last_motion(t, h, deform2);
    // Where it has got to since it became still, by its positions: its hub, its tread by the angle
    // it has turned through, and its shape.
    const ShapeChange change = shape_change(t, m.centroid);
    const double drift = length(m.centroid - t.still_anchor) + std::abs(change.turn) * t.spec.outer_radius;
    // A tire held, driven or grabbed is not resting, however slowly it moves.
    const bool still = drift <= config.sleep_speed * config.sleep_time && deform2 < limit2 &&
                       change.deformed <= config.sleep_deform && !t.grabbed && t.control.steer == 0.0 &&
                       !t.driven;
    t.still_time = still ? t.still_time + config.dt : 0.0;
    if (!still) mark_still(t, m.centroid);
    any_ready = any_ready || t.still_time >= config.sleep_time;
  }
  if (any_ready) {
    // The islands of the awake bodies: tires joined through their pairs, and through the dynamic
    // props near them (a prop's node is n + its index).
    for (const std::uint32_t i : awake_) parent_[i] = i;
    const auto& props = rigid.props();
    for (std::uint32_t p = 0; p < props.size(); ++p) parent_[n + p] = n + p;
    for (const TirePair& pair : pairs) join(pair.a, pair.b);
    for (const std::uint32_t i : awake_)
      for_each_prop_near(tires[i], [&](std::uint32_t p) {
        if (props[p].alive && props[p].spec.type == PropType::dynamic_body) join(i, n + p);
      });
    for (const std::uint32_t i : awake_) {
      still_[i] = std::numeric_limits<double>::infinity();
      blocked_[i] = 0;
    }
    members_.clear();
    for (const std::uint32_t i : awake_) {
      const std::uint32_t r = find(i);
      still_[r] = std::min(still_[r], tires[i].still_time);
      if (keep_awake && *keep_awake == i) blocked_[r] = 1;
      members_.push_back(std::uint64_t{r} << 32 | i);
    }
    std::sort(members_.begin(), members_.end());
    for (std::size_t k = 0; k < members_.size();) {
      const auto r = static_cast<std::uint32_t>(members_[k] >> 32);
      island_.clear();
      for (; k < members_.size() && members_[k] >> 32 == r; ++k)
        island_.push_back(static_cast<std::uint32_t>(members_[k]));
      if (blocked_[r] || still_[r] < config.sleep_time) continue;
      gather_props(tires, island_, rigid);
      if (!rigid.group_still(props_, config.sleep_speed)) continue;
      rigid.sleep_group(props_);
      for (const std::uint32_t i : island_) {
        Tire& t = tires[i];
        t.asleep = true;
        ++asleep_;
        t.island = tires[r].id;
        std::fill(t.particles.v.begin(), t.particles.v.end(), Vec2{});
        t.late_push = {};  // the island's weight passed between its tires: none while it sleeps
      }
      stale_ = true;
    }
  }
}

void SleepIslands::hold_props_near_awake_tires(const std::vector<Tire>& tires, RigidWorld& rigid) {
  const auto& props = rigid.props();
  std::fill(near_.begin(), near_.begin() + static_cast<std::ptrdiff_t>(props.size()), std::uint8_t{0});
  for (const std::uint32_t i : awake_) for_each_prop_near(tires[i], [&](std::uint32_t p) { near_[p] = 1; });
  for (std::uint32_t p = 0; p < props.size(); ++p)
    if (props[p].alive && props[p].spec.type == PropType::dynamic_body)
      rigid.set_sleeping_allowed(p, !near_[p]);
}

}  // namespace tire
