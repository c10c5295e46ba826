#include "tire/tire/tire_neighbours.h"

#include <algorithm>
#include <cmath>

#include "tire/math/check.h"
#include "tire/math/reserve_doubling.h"

namespace tire {

namespace {

// Tire::rigid_motion's centroid and inertia, from the positions alone (the same sums, the same bits).
struct MassFrame {
  Vec2 centroid;
  double inertia = 0.0;
};
MassFrame mass_frame(const Tire& t) {
  MassFrame f{t.centroid(), 0.0};
  for (const Vec2& x : t.particles.x) f.inertia += length_squared(x - f.centroid);
  f.inertia *= t.particle_mass();
  return f;
}

}  // namespace

void TireNeighbours::reserve(const std::vector<Tire>& tires, std::size_t pairs) {
  std::size_t particles = 0;
  for (const Tire& t : tires) particles += t.n;
  reserve_doubling(members_, tires.size());
  reserve_doubling(adjacency_begin_, tires.size() + 1);
  reserve_doubling(adjacency_, 2 * pairs);
  reserve_doubling(colour_, tires.size());
  reserve_doubling(colour_seen_, tires.size() + 1);
  reserve_doubling(colour_begin_, tires.size() + 2);
  reserve_doubling(by_colour_, tires.size());
  reserve_doubling(offset_, tires.size() + 1);
  reserve_doubling(owed_, tires.size());
  reserve_doubling(x_, particles);
  reserve_doubling(motion_, particles);
  reserve_doubling(hub_, tires.size());
  reserve_doubling(reach_, tires.size());
  reserve_doubling(body_, tires.size());
  reserve_doubling(linear_, tires.size());
  reserve_doubling(angular_, tires.size());
  // A tire owes at most one push per tread particle an iteration; a list's room stays with its
  // index, which a later tire may take (a removed one's slot): room for the largest tread.
  std::uint32_t largest = 0;
  for (const Tire& t : tires) largest = std::max(largest, t.n);
  if (reactions_.size() < tires.size()) {
    reserve_doubling(reactions_, tires.size());
    reactions_.resize(tires.size());
  }
  for (auto& list : reactions_) list.reserve(largest);
}

void TireNeighbours::set_pairs(std::size_t tire_count, std::span<const std::uint32_t> members,
                               const std::vector<TirePair>& pairs) {
  members_.assign(members.begin(), members.end());
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

  // Greedy colouring in tire order: at most (a tire's neighbours + 1) colours.
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  colour_.assign(tire_count, kNone);
  colour_seen_.assign(tire_count + 1, kNone);
  std::uint32_t count = 0;
  for (const std::uint32_t i : members_) {
    for (const std::uint32_t j : neighbours(i))
      if (colour_[j] != kNone) colour_seen_[colour_[j]] = i;
    std::uint32_t c = 0;
    while (colour_seen_[c] == i) ++c;
    colour_[i] = c;
    count = std::max(count, c + 1);
  }
  // Counting sort by colour, keeping tire order within one.
  colour_begin_.assign(count + 1, 0);
  for (const std::uint32_t i : members_) ++colour_begin_[colour_[i] + 1];
  for (std::uint32_t c = 0; c < count; ++c) colour_begin_[c + 1] += colour_begin_[c];
  by_colour_.resize(members_.size());
  for (const std::uint32_t i : members_) by_colour_[colour_begin_[colour_[i]]++] = i;
  for (std::uint32_t c = count; c > 0; --c) colour_begin_[c] = colour_begin_[c - 1];
  colour_begin_[0] = 0;
}

void TireNeighbours::begin_capture(const std::vector<Tire>& tires, double h) {
  first_ = tires.data();
  h_ = h;
  offset_.resize(tires.size() + 1);
  offset_[0] = 0;
  for (std::size_t i = 0; i < tires.size(); ++i) offset_[i + 1] = offset_[i] + tires[i].n;
  x_.resize(offset_.back());
  motion_.resize(offset_.back());
  hub_.resize(tires.size());
  reach_.resize(tires.size());
  body_.resize(tires.size());
  linear_.resize(tires.size());
  angular_.resize(tires.size());
  if (reactions_.size() < tires.size()) reactions_.resize(tires.size());
}

void TireNeighbours::capture(const std::vector<Tire>& tires, double h) {
  begin_capture(tires, h);
  for (const std::uint32_t i : members_) capture_tire(tires[i], i);
}

void TireNeighbours::capture_tire(const Tire& t, std::size_t i) {
  linear_[i] = Vec2{};
  angular_[i] = 0.0;
  Vec2* x = x_.data() + offset_[i];
  Vec2* motion = motion_.data() + offset_[i];
  Vec2 hub;
  // Before its first solve of the substep, its motion less the late push and the fall its
  // prediction took (Tire::predicted_push): the pushes of the tires that now anchor to it, coming
  // back, and a fall its supports will take back.
  const Tire::LatePush& push = t.predicted_push;
  for (std::uint32_t k = 0; k < t.n; ++k) {
    motion[k] = t.particles.x[k] - t.particles.x_prev[k];
    if (push.any) motion[k] -= (push.velocity + perp(t.particles.x_prev[k] - push.centre) * push.spin) * h_;
    x[k] = t.particles.x[k];
    hub += x[k];
  }
  hub = hub / static_cast<double>(t.n);
  double reach2 = 0.0;
  for (std::uint32_t k = 0; k < t.n; ++k) reach2 = std::max(reach2, length_squared(x[k] - hub));
  hub_[i] = hub;
  reach_[i] = std::sqrt(reach2);
  const MassFrame frame = mass_frame(t);
  body_[i] = {frame.centroid, 1.0 / t.total_mass(), frame.inertia > 0.0 ? 1.0 / frame.inertia : 0.0};
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
          b.inverse_inertia,
          static_cast<double>(std::max<std::size_t>(1, neighbours(tire).size()))};
}

std::span<const std::uint32_t> TireNeighbours::gather_reactions(std::vector<Tire>& tires) const {
  // Summed per neighbour, in tire order, then in each tire's order.
  owed_.clear();
  for (const std::uint32_t a : members_) {
    for (const TireReaction& r : reactions_[a]) {
      Tire& b = tires[r.tire];
      linear_[r.tire] += r.push;
      angular_[r.tire] += cross(r.point - body_[r.tire].centroid, r.push);
      if (r.carried) b.on_tire[r.edge] = b.on_tire[(r.edge + 1) % b.n] = 1;
    }
    reactions_[a].clear();
  }
  for (const std::uint32_t i : members_)
    if (linear_[i] != Vec2{} || angular_[i] != 0.0) owed_.push_back(i);
  return owed_;
}

bool TireNeighbours::apply_reaction(Tire& t, std::uint32_t i, double tunnel_clamp, double h,
                                    std::size_t colour) const {
  // One rigid displacement about the tire's centroid as it is now.
  const MassFrame rigid = mass_frame(t);
  // The angular push was taken about the captured centroid; moved to the current one.
  const double angular = angular_[i] + cross(body_[i].centroid - rigid.centroid, linear_[i]);
  Vec2 shift = linear_[i] * (1.0 / t.total_mass());
  double turn = rigid.inertia > 0.0 ? angular / rigid.inertia : 0.0;
  // The anti-tunnelling clamp: the farthest any particle would move, scaled to the limit.
  double farthest2 = 0.0;
  for (const Vec2& x : t.particles.x)
    farthest2 = std::max(farthest2, length_squared(shift + perp(x - rigid.centroid) * turn));
  const double limit = tunnel_clamp * t.segment_length;
  if (farthest2 > limit * limit) {
    const double scale = limit / std::sqrt(farthest2);
    shift = shift * scale;
    turn *= scale;
  }
  linear_[i] = Vec2{};
  angular_[i] = 0.0;
  if (colour_[i] <= colour) {
    // Solved already: the push waits for its next prediction, as the velocity −Δx/h.
    t.late_push.add(shift * (-1.0 / h), turn * (-1.0 / h), rigid.centroid);
    return false;
  }
  // The push is an impulse: it moves the particles and their velocities alike, so that the
  // inertial target x̃ = xₙ + h v of the tire's own solve (global_solver.h) moves with them and a
  // later solve of this substep does not pull the tire back (which lost a collision's momentum).
  Particles& p = t.particles;
  for (std::size_t k = 0; k < p.x.size(); ++k) {
    const Vec2 dx = shift + perp(p.x[k] - rigid.centroid) * turn;
    p.x[k] -= dx;
    p.v[k] -= dx * (1.0 / h);
  }
  return true;
}

void TireNeighbours::apply_reactions(std::vector<Tire>& tires, double tunnel_clamp, double h,
                                     std::size_t colour) const {
  for (const std::uint32_t i : gather_reactions(tires)) apply_reaction(tires[i], i, tunnel_clamp, h, colour);
}

}  // namespace tire
