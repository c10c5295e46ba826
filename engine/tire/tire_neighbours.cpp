#include "tire/tire/tire_neighbours.h"

#include <algorithm>
#include <cmath>

#include "tire/math/check.h"

namespace tire {

void TireNeighbours::reserve(const std::vector<Tire>& tires, std::size_t pairs) {
  std::size_t particles = 0;
  for (const Tire& t : tires) particles += t.n;
  adjacency_begin_.reserve(tires.size() + 1);
  adjacency_.reserve(2 * pairs);
  offset_.reserve(tires.size() + 1);
  x_.reserve(particles);
  motion_.reserve(particles);
  hub_.reserve(tires.size());
  reach_.reserve(tires.size());
  body_.reserve(tires.size());
  linear_.reserve(tires.size());
  angular_.reserve(tires.size());
  // A tire owes at most one push per tread particle an iteration; a list's room stays with its
  // index, which a later tire may take (a removed one's slot): room for the largest tread.
  std::uint32_t largest = 0;
  for (const Tire& t : tires) largest = std::max(largest, t.n);
  if (reactions_.size() < tires.size()) reactions_.resize(tires.size());
  for (auto& list : reactions_) list.reserve(largest);
}

void TireNeighbours::set_pairs(std::size_t tire_count, const std::vector<TirePair>& pairs) {
  // Counting sort by tire: each pair listed under both of its tires, in pair order.
  adjacency_begin_.assign(tire_count + 1, 0);
  for (const TirePair& p : pairs) {
    ++adjacency_begin_[p.a + 1];
    ++adjacency_begin_[p.b + 1];
  }
  for (std::size_t i = 0; i < tire_count; ++i) adjacency_begin_[i + 1] += adjacency_begin_[i];
  adjacency_.resize(adjacency_begin_[tire_count]);
  for (const TirePair& p : pairs) {
    adjacency_[adjacency_begin_[p.a]++] = p.b;
    adjacency_[adjacency_begin_[p.b]++] = p.a;
  }
  for (std::size_t i = tire_count; i > 0; --i) adjacency_begin_[i] = adjacency_begin_[i - 1];
  adjacency_begin_[0] = 0;
}

void TireNeighbours::capture(const std::vector<Tire>& tires, bool extrapolate) {
  first_ = tires.data();
  offset_.resize(tires.size() + 1);
  offset_[0] = 0;
  for (std::size_t i = 0; i < tires.size(); ++i) offset_[i + 1] = offset_[i] + tires[i].n;
  x_.resize(offset_.back());
  motion_.resize(offset_.back());
  hub_.resize(tires.size());
  reach_.resize(tires.size());
  body_.resize(tires.size());
  linear_.assign(tires.size(), Vec2{});
  angular_.assign(tires.size(), 0.0);
  if (reactions_.size() < tires.size()) reactions_.resize(tires.size());
  for (std::size_t i = 0; i < tires.size(); ++i) {
    const Tire& t = tires[i];
    Vec2* x = x_.data() + offset_[i];
    Vec2* motion = motion_.data() + offset_[i];
    Vec2 hub;
    for (std::uint32_t k = 0; k < t.n; ++k) {
      motion[k] = t.particles.x[k] - t.particles.x_prev[k];
      x[k] = extrapolate ? t.particles.x[k] + motion[k] : t.particles.x[k];
      hub += x[k];
    }
    hub = hub / static_cast<double>(t.n);
    double reach2 = 0.0;
    for (std::uint32_t k = 0; k < t.n; ++k) reach2 = std::max(reach2, length_squared(x[k] - hub));
    hub_[i] = hub;
    reach_[i] = std::sqrt(reach2);
    const RigidMotion rigid = t.rigid_motion();
    body_[i] = {rigid.centroid, 1.0 / t.total_mass(), rigid.inertia > 0.0 ? 1.0 / rigid.inertia : 0.0};
  }
}

TreadView TireNeighbours::tread(std::uint32_t tire) const {
  TIRE_ASSERT(tire + 1 < offset_.size(), "a tread asked for that was not captured");
  const Body& b = body_[tire];
  return {x_.data() + offset_[tire],
          motion_.data() + offset_[tire],
          first_ + tire,
          offset_[tire + 1] - offset_[tire],
          hub_[tire],
          reach_[tire],
          b.centroid,
          b.inverse_mass,
          b.inverse_inertia};
}

void TireNeighbours::apply_reactions(std::vector<Tire>& tires) const {
  // Summed per neighbour first (in tire order, then in each tire's order), then one rigid
  // displacement each, about its centroid as it is now.
  bool any = false;
  for (std::size_t a = 0; a < tires.size() && a < reactions_.size(); ++a) {
    for (const TireReaction& r : reactions_[a]) {
      Tire& b = tires[r.tire];
      linear_[r.tire] += r.push;
      angular_[r.tire] += cross(r.point - body_[r.tire].centroid, r.push);
      if (r.carried) b.on_tire[r.edge] = b.on_tire[(r.edge + 1) % b.n] = 1;
      any = true;
    }
    reactions_[a].clear();
  }
  if (!any) return;
  for (std::size_t i = 0; i < tires.size(); ++i) {
    if (linear_[i] == Vec2{} && angular_[i] == 0.0) continue;
    Tire& t = tires[i];
    const RigidMotion rigid = t.rigid_motion();
    // The angular push was taken about the captured centroid; moved to the current one.
    const double angular = angular_[i] + cross(body_[i].centroid - rigid.centroid, linear_[i]);
    const Vec2 shift = linear_[i] * (1.0 / t.total_mass());
    const double turn = rigid.inertia > 0.0 ? angular / rigid.inertia : 0.0;
    for (Vec2& x : t.particles.x) x -= shift + perp(x - rigid.centroid) * turn;
    linear_[i] = Vec2{};
    angular_[i] = 0.0;
  }
}

}  // namespace tire
