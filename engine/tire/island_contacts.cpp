#include "tire/tire/island_contacts.h"

#include <algorithm>
#include <cmath>

#include "tire/math/reserve_doubling.h"
#include "tire/math/worker_pool.h"
#include "tire/rigid/rigid_world.h"
#include "tire/tire/tire_solver.h"
#include "tire/xpbd/contact.h"

namespace tire {

namespace {

// How far outside a neighbour's tread a particle may be where the tires are predicted and still be
// a candidate: solved alone, a tire springs back from what its neighbours pressed in.
constexpr double kCandidateMargin = 0.01;  // m
// A particle this close to a surface at the substep's start was on it (m): at 0.1 mm, the tires of a
// pile of 150 that bounced off their supports by more took kinetic friction and jiggled for ever.
constexpr double kTouching = 1e-3;
// Room per tire of an island: contact rows (a soft tire in a pile has about 9, a stiff one 4) and
// entries of D per row (the rows of its two tires).
constexpr std::size_t kRowsPerTire = 32;
constexpr std::size_t kEntriesPerRow = 96;
constexpr int kPasses = 8;         // active-set passes
constexpr int kPolishSweeps = 32;  // projected Gauss–Seidel sweeps when they run out
// Two rows of one touch seen from either tire are twins (nearly dependent) when their normals are
// this close to opposite (within 26°); edges that cross at a larger angle make two contacts.
constexpr double kTwinCos = 0.9;
// Tires whose hubs are closer than this fraction of the larger radius are inside each other.
constexpr double kTangled = 0.5;
// Conjugate gradients: until the residual is this small against the right-hand side, or
// kMaxIterations.
constexpr double kTolerance = 1e-10;
constexpr std::size_t kMaxIterations = 1000;
// An incomplete Cholesky pivot under this fraction of its row's diagonal is a breakdown; the factor
// is then made again with its diagonal shifted, from kFirstShift, kShiftGrowth times more each try,
// while the shift is at most kLastShift (then the diagonal alone preconditions).
constexpr double kPivotFloor = 1e-6;
constexpr double kFirstShift = 1e-3;
constexpr double kShiftGrowth = 4.0;
constexpr double kLastShift = 1.0;

// fn(begin, end) over [0, n): on the pool's threads if there is one.
template <typename F>
void for_range(WorkerPool* pool, std::size_t n, F&& fn) {
  if (pool != nullptr)
    pool->parallel_for(n, fn);
  else
    fn(std::size_t{0}, n);
}

}  // namespace

void IslandContacts::reserve(std::size_t largest, std::uint32_t segments, std::size_t tires) {
  // Room for the largest island the option allows, made once, when a second tire makes an island
  // possible: a solver per tire made as tires are added cost each added tire some twenty allocations.
  largest_ = tires >= 2 ? largest : 0;
  if (largest_ < 2) return;  // no island is solved here: nothing to make room for
  while (solvers_.size() < largest_) solvers_.push_back(std::make_unique<GlobalSolver>());
  for (auto& s : solvers_) s->reserve(segments);
  max_rows_ = largest_ * kRowsPerTire;
  max_entries_ = max_rows_ * kEntriesPerRow;
  // The lists sized by the world's tires: for as many as the largest island at once, then doubling.
  const std::size_t room = std::max(largest_, tires);
  reserve_doubling(per_tire_, room);
  reserve_doubling(tires_, room);
  reserve_doubling(group_begin_, room + 1);
  reserve_doubling(pairs_, 4 * room);
  reserve_doubling(pair_begin_, room + 1);
  reserve_doubling(overflow_, room);
  reserve_doubling(rows_, max_rows_);
  reserve_doubling(rows_of_tire_begin_, largest_ + 1);
  reserve_doubling(rows_of_tire_, 2 * max_rows_);
  reserve_doubling(w_, 2 * max_rows_ * CyclicBlockCholesky::kBlock * segments);
  reserve_doubling(load_, largest_ * CyclicBlockCholesky::kBlock * segments);
  reserve_doubling(correction_, largest_ * CyclicBlockCholesky::kBlock * segments);
  reserve_doubling(dof_begin_, largest_ + 1);
  reserve_doubling(entry_begin_, max_rows_ + 1);
  reserve_doubling(entry_column_, max_entries_);
  reserve_doubling(entry_value_, max_entries_);
  for (auto* v : {&x_, &r_, &z_, &p_, &q_, &diagonal_}) reserve_doubling(*v, max_rows_);
  reserve_doubling(live_, max_rows_);
  reserve_doubling(live_rows_, max_rows_);
  reserve_doubling(live_slot_, max_rows_);
  reserve_doubling(ic_value_, max_entries_);
  reserve_doubling(ic_diagonal_, max_rows_);
  reserve_doubling(live_begin_, max_rows_ + 1);
  reserve_doubling(live_column_, max_entries_);
  reserve_doubling(live_value_, max_entries_);
  reserve_doubling(ready_, largest_);
  for (auto* v : {&older_lambda_, &last_lambda_, &next_lambda_})
    reserve_doubling(*v, 4 * room * kRowsPerTire);
  for (auto* v : {&anchors_, &next_anchors_}) reserve_doubling(*v, 4 * room * kRowsPerTire);
}

void IslandContacts::set_islands(const std::vector<Tire>& tires, std::span<const std::uint32_t> members,
                                 const std::vector<TirePair>& pairs, std::size_t largest,
                                 const RigidWorld& rigid) {
  const std::size_t tire_count = tires.size();
  tires_.clear();
  pairs_.clear();
  group_begin_.clear();
  pair_begin_.clear();
  for (Member& m : per_tire_) m.solves = 0;
  // The multipliers and anchors are the last iteration's (find() passes them on each iteration): a
  // tick with no island solved here leaves none. Kept, an island solved again after ticks of block
  // Gauss–Seidel was loaded with the forces of contacts long gone: a pile of 60 left to it for half
  // a second was thrown about at 5.6 m/s (tests/test_island_contacts.cpp).
  const auto forget = [&] {
    for (auto* v : {&older_lambda_, &last_lambda_, &next_lambda_}) v->clear();
    last_h_ = older_h_ = next_h_ = 0.0;
    anchors_.clear();
    next_anchors_.clear();
  };
  if (pairs.empty() || largest < 2 || largest_ < 2) return forget();
  per_tire_.assign(tire_count, Member{});
  largest = std::min(largest, largest_);
  // Union–find over the pairs, the smaller index the root (the same islands in any pair order).
  for (const std::uint32_t i : members) per_tire_[i].root = i;
  const auto find_root = [&](std::uint32_t i) {
    while (per_tire_[i].root != i) {
      per_tire_[i].root = per_tire_[per_tire_[i].root].root;
      i = per_tire_[i].root;
    }
    return i;
  };
  for (const TirePair& p : pairs) {
    const std::uint32_t a = find_root(p.a), b = find_root(p.b);
    if (a != b) per_tire_[std::max(a, b)].root = std::min(a, b);
  }
  for (const std::uint32_t i : members) {
    Member& root = per_tire_[find_root(i)];
    ++root.size;
    for (const PropFrame& f : tires[i].prop_frames) root.near_prop |= rigid.props()[f.prop].is_dynamic();
    root.near_prop |= tires[i].wheel >= 0;  // a wheel is solved with its vehicle (vehicle_joints.h)
  }
  // Tires inside each other (a hub within half the larger radius of the other's: spawned on one
  // spot, or driven through by a script) are tangled: the island's one linear step cannot part
  // them. Forty tires spawned on one point were thrown at 780 m/s; block Gauss–Seidel parts them.
  // (Only an island small enough to be solved here is looked at: a pile of a thousand is not.)
  for (const TirePair& p : pairs) {
    Member& root = per_tire_[find_root(p.a)];
    if (root.size > largest || root.tangled) continue;
    const double reach = kTangled * std::max(tires[p.a].spec.outer_radius, tires[p.b].spec.outer_radius);
    if (length_squared(tires[p.a].centroid() - tires[p.b].centroid()) < reach * reach) root.tangled = true;
  }
  // The islands of 2 … largest tires, in order of their first tire (a root is its island's first
  // tire, and members are in tire order), batched into groups of at most `largest` tires; each
  // island's tires in tire order.
  constexpr std::uint32_t kNone = ~std::uint32_t{0};
  for (Member& m : per_tire_) m.cursor = kNone;
  std::uint32_t in_group = 0;
  for (const std::uint32_t i : members) {
    if (find_root(i) != i || per_tire_[i].size < 2 || per_tire_[i].size > largest || per_tire_[i].near_prop ||
        per_tire_[i].tangled)
      continue;
    if (group_begin_.empty() || in_group + per_tire_[i].size > largest) {
      group_begin_.push_back(static_cast<std::uint32_t>(tires_.size()));
      in_group = 0;
    }
    per_tire_[i].cursor = static_cast<std::uint32_t>(tires_.size());
    tires_.resize(tires_.size() + per_tire_[i].size);
    in_group += per_tire_[i].size;
  }
  if (group_begin_.empty()) return forget();
  group_begin_.push_back(static_cast<std::uint32_t>(tires_.size()));
  for (const std::uint32_t i : members) {
    const std::uint32_t r = find_root(i);
    if (per_tire_[r].cursor == kNone) continue;
    tires_[per_tire_[r].cursor++] = i;
    per_tire_[i].solves = 1;
  }
  // Each group's pairs, in pair order.
  for (std::size_t g = 0; g + 1 < group_begin_.size(); ++g)
    for (std::uint32_t k = group_begin_[g]; k < group_begin_[g + 1]; ++k) {
      per_tire_[tires_[k]].group = static_cast<std::uint32_t>(g);
      per_tire_[tires_[k]].slot = k - group_begin_[g];
    }
  pair_begin_.assign(groups() + 1, 0);
  for (const TirePair& p : pairs)
    if (per_tire_[p.a].solves) ++pair_begin_[per_tire_[p.a].group + 1];
  for (std::size_t g = 0; g < groups(); ++g) pair_begin_[g + 1] += pair_begin_[g];
  pairs_.resize(pair_begin_.back());
  for (const TirePair& p : pairs)
    if (per_tire_[p.a].solves) pairs_[pair_begin_[per_tire_[p.a].group]++] = p;
  for (std::size_t g = groups(); g > 0; --g) pair_begin_[g] = pair_begin_[g - 1];
  pair_begin_[0] = 0;
  overflow_.assign(groups(), 0);
}

double IslandContacts::along(const Row& r, bool side_a, const double* w, std::uint32_t n) {
  const auto at = [&](std::uint32_t i) {
    const std::size_t k = GlobalSolver::dof(i, n);
    return Vec2{w[k], w[k + 1]};
  };
  if (side_a) return dot(r.d, at(r.particle));
  return -dot(r.d, at(r.e0) * (1.0 - r.s) + at(r.e1) * r.s);
}

void IslandContacts::spread(const Row& r, bool side_a, double scale, double* v, std::uint32_t n) {
  if (side_a) {
    const std::size_t p = GlobalSolver::dof(r.particle, n);
    v[p] += r.d.x * scale;
    v[p + 1] += r.d.y * scale;
    return;
  }
  const std::size_t e0 = GlobalSolver::dof(r.e0, n), e1 = GlobalSolver::dof(r.e1, n);
  v[e0] -= r.d.x * ((1.0 - r.s) * scale);
  v[e0 + 1] -= r.d.y * ((1.0 - r.s) * scale);
  v[e1] -= r.d.x * (r.s * scale);
  v[e1 + 1] -= r.d.y * (r.s * scale);
}

double IslandContacts::d_times(std::size_t row, double Row::*multiplier) const {
  double sum = 0.0;
  for (std::uint32_t k = entry_begin_[row]; k < entry_begin_[row + 1]; ++k)
    sum += entry_value_[k] * (rows_[entry_column_[k]].*multiplier);
  return sum;
}

double IslandContacts::relaxed(std::size_t row, double alpha_tilde) const {
  double moved = 0.0, self = 0.0;
  for (std::uint32_t k = entry_begin_[row]; k < entry_begin_[row + 1]; ++k) {
    moved += entry_value_[k] * rows_[entry_column_[k]].lambda;
    if (entry_column_[k] == row) self = entry_value_[k];
  }
  const Row& r = rows_[row];
  if (!(self > 0.0)) return r.lambda;
  return r.lambda + (r.rhs - moved - alpha_tilde * r.lambda) / (self + alpha_tilde);
}

// A tread particle of ta inside (or within kCandidateMargin of) tb's tread, against the edge it
// crossed, as GlobalSolver::find_tire_contacts finds it: a normal row, and a friction row after it.
// False when the rows do not fit.
bool IslandContacts::add_contacts(const Tire& ta, std::uint32_t a, const Tire& tb, std::uint32_t b,
                                  std::size_t first_of_pair) {
  const Vec2* xb = tb.particles.x.data();
  Vec2 hub;
  for (std::uint32_t k = 0; k < tb.n; ++k) hub += xb[k];
  hub = hub / static_cast<double>(tb.n);
  double reach2 = 0.0;
  for (std::uint32_t k = 0; k < tb.n; ++k) reach2 = std::max(reach2, length_squared(xb[k] - hub));
  const double reach = std::sqrt(reach2) + kCandidateMargin;
  const double mu = mix_friction(ta.spec.friction, tb.spec.friction);
  for (std::uint32_t i = 0; i < ta.n; ++i) {
    const Vec2 x = ta.particles.x[i];
    const Vec2 d = x - hub;
    if (length_squared(d) >= reach * reach) continue;
    const std::uint32_t k = tread_edge_towards(xb, tb.n, hub, d);
    const std::uint32_t k1 = k + 1 == tb.n ? 0 : k + 1;
    const Vec2 e = xb[k1] - xb[k];
    const double e2 = length_squared(e);
    if (!(e2 > 0.0)) continue;
    const Vec2 normal = Vec2{e.y, -e.x} * (1.0 / std::sqrt(e2));  // outward: treads run counter-clockwise
    const double depth = -dot(normal, x - xb[k]);
    if (!(depth > -kCandidateMargin)) continue;
    // The same touch seen from the other tire (its particle, an end of this edge, inside ta against
    // an edge that ends at this particle) gives a nearly dependent row: D nearly singular, λ runs
    // away. One of the two is kept (pile_oracle's rule): the one that held last substep, else the
    // deeper. (Twins that took turns turned the load's path every substep, and a pile crept.)
    bool twin = false;
    for (std::size_t q = first_of_pair; q < rows_.size(); ++q) {
      Row& o = rows_[q];
      if (o.normal >= 0 || o.dropped || o.a != b || o.b != a) continue;
      // One touch: its particle the end of this edge nearer to ours, and ours the end of its edge
      // nearer to its. (Two tires face to face, two edges overlapping, touch at both ends: a row
      // at each end, or the upper one balanced on a point and rolled off.)
      const std::uint32_t nearer = dot(x - xb[k], e) < 0.5 * e2 ? k : k1;
      if (o.particle != nearer || (o.s < 0.5 ? o.e0 : o.e1) != i) continue;
      if (dot(o.d, normal) > -kTwinCos) continue;  // edges that cross: two contacts, both kept
      const bool mine_held = held(a, i, b), its_held = held(b, o.particle, a);
      if (mine_held != its_held ? its_held : o.target >= depth) {
        twin = true;
      } else {
        o.dropped = true;
        if (q + 1 < rows_.size() && rows_[q + 1].normal == static_cast<std::int32_t>(q))
          rows_[q + 1].dropped = true;
      }
    }
    if (twin) continue;
    if (rows_.size() + 2 > max_rows_) return false;
    Row r;
    r.a = a;
    r.particle = i;
    r.b = b;
    r.e0 = k;
    r.e1 = k1;
    r.s = std::clamp(dot(x - xb[k], e) / e2, 0.0, 1.0);
    r.d = normal;
    r.target = depth;
    r.mu = mu;
    rows_.push_back(r);
    if (!(mu > 0.0)) continue;
    r.normal = static_cast<std::int32_t>(rows_.size() - 1);
    r.d = perp(normal);
    rows_.push_back(r);
  }
  return true;
}

void IslandContacts::find(const std::vector<Tire>& tires, std::size_t group, double h) {
  if (group == 0) {  // what held, and the multipliers, in the last iteration of every group
    older_lambda_.swap(last_lambda_);
    last_lambda_.swap(next_lambda_);
    older_h_ = last_h_;
    last_h_ = next_h_;
    next_lambda_.clear();
    std::sort(last_lambda_.begin(), last_lambda_.end());
    anchors_.swap(next_anchors_);
    next_anchors_.clear();
    std::sort(anchors_.begin(), anchors_.end(),
              [](const Anchor& x, const Anchor& y) { return x.key < y.key; });
  }
  first_ = tires.data();
  rows_.clear();
  overflow_[group] = 0;
  bool fits = true;
  for (std::uint32_t k = pair_begin_[group]; k < pair_begin_[group + 1] && fits; ++k) {
    const TirePair& p = pairs_[k];
    const std::size_t first = rows_.size();
    fits = add_contacts(tires[p.a], p.a, tires[p.b], p.b, first) &&
           add_contacts(tires[p.b], p.b, tires[p.a], p.a, first);
  }
  // The twins left out; the friction rows' normals renumbered.
  std::size_t kept = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    if (rows_[r].dropped) continue;
    Row row = rows_[r];
    if (row.normal >= 0) row.normal = static_cast<std::int32_t>(kept - 1);
    rows_[kept++] = row;
  }
  rows_.resize(kept);
  // D's entries: a row's columns are the rows of its two tires.
  std::size_t entries = 0;
  if (fits) {
    index_rows_by_tire(group_tires(group).size());
    const auto count = [&](std::uint32_t tire) {
      return rows_of_tire_begin_[per_tire_[tire].slot + 1] - rows_of_tire_begin_[per_tire_[tire].slot];
    };
    for (const Row& r : rows_) entries += count(r.a) + count(r.b);
  }
  if (!fits || entries > max_entries_) {
    overflow_[group] = 1;
    rows_.clear();
    ++work_.overflows;
    return;
  }
  load_tires(tires, group_tires(group), h);
}

// Each row's last multiplier, put on its two tires as a load for their solves: each tire is then
// solved as its neighbours push it, and the island's solve adds only what changed. Solved alone with
// no load, a tire pressed against a wall by the pile let the wall go and sprang back, the island's
// solve pressed it in again through a response that did not hold the wall, and tires between a
// pile and a wall rang at half the substep rate (docs/at-rest.md).
void IslandContacts::load_tires(const std::vector<Tire>& tires, std::span<const std::uint32_t> members,
                                double h) {
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  // A multiplier is a force times h² (K̂ = M + h² ∇²E) where it holds a resting load, an impulse
  // times h where it stops a blow. Loaded at another substep than it was solved at (the refinement
  // changed the substeps between ticks), it is scaled by the smaller of (h/h')² and h/h': the load is
  // a guess the island's solve corrects, and what throws a tire is too much of it. Unscaled, a pile at
  // rest was pressed by 4 times its neighbours' weight when its substeps halved, the jolt turned its
  // links past refine_turn, and its substeps went 4, 4, 2, 4, 8, 8 for ever; scaled by (h/h')² both
  // ways, a blow that refined to 2 substeps and back to 1 was loaded twice its impulse and gained 27 %.
  const auto rescale = [h](double solved_at) {
    if (!(solved_at > 0.0) || solved_at == h) return 1.0;
    const double ratio = h / solved_at;
    return std::min(ratio, ratio * ratio);
  };
  const double last_scale = rescale(last_h_), older_scale = rescale(older_h_);
  dof_begin_.assign(1, 0);
  for (const std::uint32_t i : members) dof_begin_.push_back(dof_begin_.back() + B * tires[i].n);
  load_.assign(dof_begin_.back(), 0.0);
  for (Row& r : rows_) {
    r.lambda = lambda_in(last_lambda_, lambda_key(r)) * last_scale;
    const double older = lambda_in(older_lambda_, lambda_key(r)) * older_scale;
    r.applied =
        r.lambda * older > 0.0 ? std::copysign(std::min(std::abs(r.lambda), std::abs(older)), older) : 0.0;
    if (r.applied == 0.0) continue;
    for (const bool side_a : {true, false}) {  // Jᵀ λ (island_contacts.h)
      const std::uint32_t tire = side_a ? r.a : r.b;
      spread(r, side_a, r.applied, load_.data() + dof_begin_[per_tire_[tire].slot], tires[tire].n);
    }
  }
  for (std::size_t k = 0; k < members.size(); ++k) solvers_[k]->load_next_solve(load_.data() + dof_begin_[k]);
}

// Each tire's contacts with fixed surfaces (obstacles, static and kinematic props): rows on that
// tire alone, applied as its solve held them (its μ). Of a contact the solve holds, the static
// friction (its normal stays in the response, GlobalSolver::respond), bounded by μ μ_n of the
// solve; of one it let go, the normal and the friction, so that the island may press it in again.
// One active set for every contact. False when they do not all fit.
bool IslandContacts::add_surface_rows(const std::vector<Tire>& tires,
                                      std::span<const std::uint32_t> members) {
  bool fits = true;
  for (std::size_t k = 0; k < members.size(); ++k) {
    if (!ready_[k]) continue;
    const std::uint32_t a = members[k];
    const Tire& t = tires[a];
    solvers_[k]->for_each_fixed_contact(
        t.particles, [&](std::uint32_t particle, Vec2 normal, double plane, Vec2 motion, Vec2 stuck_at,
                         double mu, std::int32_t prop, bool held, double mu_n, double mu_t) {
          if (rows_.size() + 2 > max_rows_) {
            fits = false;
            return;
          }
          const Vec2 x = t.particles.x[particle];
          Row r;
          r.surface = true;
          r.a = r.b = a;
          r.particle = particle;
          r.plane = plane;
          r.surface_motion = motion;
          r.prop = prop;
          r.mu = mu;
          r.d = normal;
          r.target = plane - dot(normal, x);
          r.applied = r.lambda = mu_n;
          if (held) {  // its normal stays in the tire's response: its friction alone, bounded by μ μ_n
            if (!(mu > 0.0 && mu_n > 0.0)) return;
            r.bound = mu * mu_n;
          } else {
            rows_.push_back(r);
            if (!(mu > 0.0)) return;
            // Its friction kinetic unless the particle was on the surface at the substep's start: its
            // motion over the substep was not slip while it was off it, and a static row taking all of
            // it back (12 cm for a tire rolling at 5 m/s at one substep) yanked the tread back and
            // deformed it (the pair's energy up by half).
            r.kinetic = plane - dot(normal, t.particles.x_prev[particle] + motion) < -kTouching;
          }
          const Vec2 tangent = perp(normal);
          r.normal = static_cast<std::int32_t>(held ? rows_.size() : rows_.size() - 1);
          r.d = tangent;
          r.target = -dot(tangent, x - stuck_at);
          r.applied = r.lambda = mu_t;
          rows_.push_back(r);
        });
  }
  return fits;
}

void IslandContacts::index_rows_by_tire(std::size_t tires_in_group) {
  rows_of_tire_begin_.assign(tires_in_group + 1, 0);
  for (const Row& r : rows_) {
    ++rows_of_tire_begin_[per_tire_[r.a].slot + 1];
    if (!r.surface) ++rows_of_tire_begin_[per_tire_[r.b].slot + 1];
  }
  for (std::size_t t = 0; t < tires_in_group; ++t) rows_of_tire_begin_[t + 1] += rows_of_tire_begin_[t];
  rows_of_tire_.resize(rows_of_tire_begin_.back());
  for (std::uint32_t r = 0; r < rows_.size(); ++r) {
    rows_of_tire_[rows_of_tire_begin_[per_tire_[rows_[r].a].slot]++] = r;
    if (!rows_[r].surface) rows_of_tire_[rows_of_tire_begin_[per_tire_[rows_[r].b].slot]++] = r;
  }
  for (std::size_t t = tires_in_group; t > 0; --t) rows_of_tire_begin_[t] = rows_of_tire_begin_[t - 1];
  rows_of_tire_begin_[0] = 0;
}

// D_qr = Σ over the tires rows q and r share of J_q · K̂⁻¹ J_rᵀ, by rows (its columns in order).
bool IslandContacts::assemble(const std::vector<Tire>& tires) {
  entry_begin_.assign(1, 0);
  entry_column_.clear();
  entry_value_.clear();
  for (std::size_t q = 0; q < rows_.size(); ++q) {
    const Row& rq = rows_[q];
    const auto list = [&](std::uint32_t tire) {
      const std::uint32_t slot = per_tire_[tire].slot;
      return std::span<const std::uint32_t>(rows_of_tire_.data() + rows_of_tire_begin_[slot],
                                            rows_of_tire_begin_[slot + 1] - rows_of_tire_begin_[slot]);
    };
    const std::span<const std::uint32_t> la = list(rq.a);
    const std::span<const std::uint32_t> lb = rq.surface ? std::span<const std::uint32_t>() : list(rq.b);
    if (entry_column_.size() + la.size() + lb.size() > max_entries_) return false;
    std::size_t i = 0, j = 0;
    while (i < la.size() || j < lb.size()) {  // the union of the two sorted lists
      std::uint32_t r;
      if (j == lb.size() || (i < la.size() && la[i] < lb[j])) {
        r = la[i++];
      } else if (i == la.size() || lb[j] < la[i]) {
        r = lb[j++];
      } else {
        r = la[i++];
        ++j;
      }
      const Row& rr = rows_[r];
      const double* wa = w_.data() + rr.wa;
      const double* wb = w_.data() + rr.wb;
      double v = 0.0;
      if (rq.a == rr.a) v += along(rq, true, wa, tires[rq.a].n);
      if (!rr.surface && rq.a == rr.b) v += along(rq, true, wb, tires[rq.a].n);
      if (!rq.surface && rq.b == rr.a) v += along(rq, false, wa, tires[rq.b].n);
      if (!rq.surface && !rr.surface && rq.b == rr.b) v += along(rq, false, wb, tires[rq.b].n);
      entry_column_.push_back(r);
      entry_value_.push_back(v);
    }
    entry_begin_.push_back(static_cast<std::uint32_t>(entry_column_.size()));
  }
  return true;
}

// The incomplete Cholesky factor of the live rows' D + α̃ on D's own pattern, IC(0) (Saad,
// Iterative Methods for Sparse Linear Systems, 2nd ed., §10.3.2): L's row j holds, at the entries
// of columns up to j, L_jk = (A_jk − Σ_{i<k} L_ji L_ki) / L_kk and L_jj = √(A_jj − Σ_{i<j} L_ji²),
// with A's diagonal taken (1 + shift) times larger. False when a pivot is not positive (D is not an
// M-matrix, so IC(0) may break down): solve_active() then factors again with a larger shift.
bool IslandContacts::incomplete_cholesky(double shift) {
  const std::size_t n = live_rows_.size();
  ic_value_.resize(live_value_.size());
  ic_diagonal_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t begin = live_begin_[j];
    std::uint32_t k = begin;
    for (; k < live_begin_[j + 1] && live_column_[k] < j; ++k) {
      const std::uint32_t c = live_column_[k];
      // Σ_{i<c} L_ji L_ci over the columns rows j and c share: a merge of the two sorted rows.
      double sum = live_value_[k];
      std::uint32_t a = begin, b = live_begin_[c];
      while (a < k && b < ic_diagonal_[c]) {
        if (live_column_[a] < live_column_[b]) {
          ++a;
        } else if (live_column_[b] < live_column_[a]) {
          ++b;
        } else {
          sum -= ic_value_[a++] * ic_value_[b++];
        }
      }
      ic_value_[k] = sum / ic_value_[ic_diagonal_[c]];
    }
    if (k == live_begin_[j + 1] || live_column_[k] != j) return false;  // no diagonal entry
    double pivot = diagonal_[j] * (1.0 + shift);
    for (std::uint32_t i = begin; i < k; ++i) pivot -= ic_value_[i] * ic_value_[i];
    if (!(pivot > kPivotFloor * diagonal_[j])) return false;
    ic_diagonal_[j] = k;
    ic_value_[k] = std::sqrt(pivot);
  }
  return true;
}

// (D + α̃) λ = c on the live rows, by conjugate gradients preconditioned by incomplete_cholesky()
// (by the diagonal when no shift mends its breakdown), from the multipliers the rows have (the last
// pass's, or the last substep's). D is symmetric (each tire's K̂⁻¹ is) and positive definite on rows
// that are not dependent (twins are left out; α̃ > 0 keeps it definite). The rows not live are left
// with no multiplier. False when it is not (a direction of no positive curvature), not finite, or
// not converged within kMaxIterations, the multipliers untouched.
bool IslandContacts::solve_active(double alpha_tilde) {
  // The live rows and their entries, in the order D holds them (so the sums are D's, term by term).
  const std::size_t m = rows_.size();
  live_rows_.clear();
  live_slot_.resize(m);
  for (std::uint32_t i = 0; i < m; ++i) {
    if (!live_[i]) continue;
    live_slot_[i] = static_cast<std::uint32_t>(live_rows_.size());
    live_rows_.push_back(i);
  }
  const std::size_t n = live_rows_.size();
  live_begin_.assign(1, 0);
  live_column_.clear();
  live_value_.clear();
  diagonal_.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const std::uint32_t i = live_rows_[j];
    diagonal_[j] = alpha_tilde;
    for (std::uint32_t k = entry_begin_[i]; k < entry_begin_[i + 1]; ++k) {
      const std::uint32_t c = entry_column_[k];
      if (!live_[c]) continue;
      if (c == i) diagonal_[j] += entry_value_[k];
      live_column_.push_back(live_slot_[c]);
      live_value_.push_back(entry_value_[k]);
    }
    live_begin_.push_back(static_cast<std::uint32_t>(live_column_.size()));
  }
  const auto product = [&](const std::vector<double>& v, std::vector<double>& out) {
    for (std::size_t j = 0; j < n; ++j) {
      double sum = alpha_tilde * v[j];
      for (std::uint32_t k = live_begin_[j]; k < live_begin_[j + 1]; ++k)
        sum += live_value_[k] * v[live_column_[k]];
      out[j] = sum;
    }
  };
  x_.resize(n);
  r_.resize(n);
  z_.resize(n);
  p_.resize(n);
  q_.resize(n);
  // A factor that breaks down is made again from a diagonal made heavier, by kFirstShift and then
  // kShiftGrowth times more each try (Manteuffel, "An incomplete factorization technique for
  // positive definite linear systems", Math. Comp. 34, 1980): still close to D, where the diagonal
  // alone is far from it. In level 08's pile of 301 light, stiff tires solved as one island the
  // unshifted factor broke down in a fifth of the passes, and falling back to the diagonal there
  // took 10 million iterations in 40 s (docs/at-rest.md).
  bool factored = incomplete_cholesky(0.0);
  if (!factored) ++work_.breakdowns;
  for (double shift = kFirstShift; !factored && shift <= kLastShift; shift *= kShiftGrowth)
    factored = incomplete_cholesky(shift);
  const auto precondition = [&] {
    if (!factored) {
      for (std::size_t j = 0; j < n; ++j) z_[j] = r_[j] / diagonal_[j];
      return;
    }
    // L y = r, then Lᵀ z = y in place.
    for (std::size_t j = 0; j < n; ++j) {
      double sum = r_[j];
      for (std::uint32_t k = live_begin_[j]; k < ic_diagonal_[j]; ++k)
        sum -= ic_value_[k] * z_[live_column_[k]];
      z_[j] = sum / ic_value_[ic_diagonal_[j]];
    }
    for (std::size_t j = n; j-- > 0;) {
      z_[j] /= ic_value_[ic_diagonal_[j]];
      for (std::uint32_t k = live_begin_[j]; k < ic_diagonal_[j]; ++k)
        z_[live_column_[k]] -= ic_value_[k] * z_[j];
    }
  };
  for (std::size_t j = 0; j < n; ++j) x_[j] = rows_[live_rows_[j]].lambda;
  product(x_, q_);
  double rhs2 = 0.0, rz = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    const double c = rows_[live_rows_[j]].rhs;
    rhs2 += c * c;
    r_[j] = c - q_[j];
  }
  precondition();
  for (std::size_t j = 0; j < n; ++j) {
    p_[j] = z_[j];
    rz += r_[j] * z_[j];
  }
  const double stop = kTolerance * kTolerance * rhs2;
  bool converged = false;
  for (std::size_t it = 0; it < kMaxIterations; ++it) {
    double rr = 0.0;
    for (std::size_t j = 0; j < n; ++j) rr += r_[j] * r_[j];
    if (!(rr > stop)) {
      converged = true;
      break;
    }
    ++work_.iterations;
    product(p_, q_);
    double pq = 0.0;
    for (std::size_t j = 0; j < n; ++j) pq += p_[j] * q_[j];
    if (!(pq > 0.0) || !std::isfinite(pq)) return false;
    const double alpha = rz / pq;
    double rz_next = 0.0;
    for (std::size_t j = 0; j < n; ++j) {
      x_[j] += alpha * p_[j];
      r_[j] -= alpha * q_[j];
    }
    precondition();
    for (std::size_t j = 0; j < n; ++j) rz_next += r_[j] * z_[j];
    const double beta = rz_next / rz;
    rz = rz_next;
    for (std::size_t j = 0; j < n; ++j) p_[j] = z_[j] + beta * p_[j];
  }
  // Multipliers the iterations left far from the answer are no answer: such solves threw level 08's
  // pile, solved as one island, at up to 300 m/s (docs/at-rest.md).
  if (!converged) return false;
  for (std::size_t i = 0; i < m; ++i) rows_[i].lambda = 0.0;
  for (std::size_t j = 0; j < n; ++j) rows_[live_rows_[j]].lambda = x_[j];
  return true;
}

void IslandContacts::solve(std::vector<Tire>& tires, std::size_t group, const SubstepContext& ctx,
                           WorkerPool* pool) {
  if (overflow_[group] || rows_.empty()) return;
  const std::span<const std::uint32_t> members = group_tires(group);
  ready_.resize(members.size());
  for_range(pool, members.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) ready_[k] = solvers_[k]->prepare_response() ? 1 : 0;
  });
  // Each candidate where the tires are now: a normal row's direction and gap, a friction row's slip
  // over the substep. A row on a tire whose response is not to be had (a free prop in its system)
  // is left out, with its friction.
  std::size_t kept = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    Row row = rows_[r];
    if (row.surface) {  // added below, after the tires' rows
      continue;
    }
    if (!ready_[per_tire_[row.a].slot] || !ready_[per_tire_[row.b].slot]) {
      ++work_.failures;
      continue;
    }
    if (row.normal >= 0) {  // its normal is the row kept just before, or was left out
      if (kept == 0) continue;
      const Row& n = rows_[kept - 1];
      if (n.normal >= 0 || n.a != row.a || n.particle != row.particle || n.b != row.b) continue;
      row.normal = static_cast<std::int32_t>(kept - 1);
    }
    const Tire& ta = tires[row.a];
    const Tire& tb = tires[row.b];
    const Vec2* xb = tb.particles.x.data();
    const Vec2* pb = tb.particles.x_prev.data();
    // The directions are find()'s, which the loads were put on with: the tires feel Jᵀ λ in all.
    const Vec2 x = ta.particles.x[row.particle];
    if (row.normal < 0) {
      row.target = -dot(row.d, x - (xb[row.e0] * (1.0 - row.s) + xb[row.e1] * row.s));
    } else {
      const Vec2 tangent = row.d;
      if (const Anchor* anchor = anchor_of(key(row))) {
        // Stuck since the anchor was laid: back to it, so that what slid in earlier substeps is
        // taken back too (a pile whose frictions each let go a little each substep crept).
        const std::uint32_t a1 = anchor->e0 + 1 == tb.n ? 0 : anchor->e0 + 1;
        row.target = -dot(tangent, x - (xb[anchor->e0] * (1.0 - anchor->s) + xb[a1] * anchor->s));
      } else {
        const Vec2 edge_motion =
            (xb[row.e0] - pb[row.e0]) * (1.0 - row.s) + (xb[row.e1] - pb[row.e1]) * row.s;
        row.target = -dot(tangent, (x - ta.particles.x_prev[row.particle]) - edge_motion);
      }
    }
    rows_[kept++] = row;
  }
  rows_.resize(kept);
  if (rows_.empty()) return;
  if (!add_surface_rows(tires, members)) ++work_.overflows;
  ++work_.solves;
  work_.rows += rows_.size();
  index_rows_by_tire(members.size());
  // Each row's response on its two tires, w = K̂⁻¹ Jᵀ.
  std::size_t total = 0;
  for (Row& r : rows_) {
    r.wa = total;
    total += CyclicBlockCholesky::kBlock * tires[r.a].n;
    r.wb = total;
    if (!r.surface) total += CyclicBlockCholesky::kBlock * tires[r.b].n;
  }
  w_.assign(total, 0.0);
  for_range(pool, rows_.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const Row& r = rows_[k];
      double* wa = w_.data() + r.wa;
      spread(r, true, 1.0, wa, tires[r.a].n);
      solvers_[per_tire_[r.a].slot]->respond(wa);
      if (r.surface) continue;
      double* wb = w_.data() + r.wb;
      spread(r, false, 1.0, wb, tires[r.b].n);
      solvers_[per_tire_[r.b].slot]->respond(wb);
    }
  });
  if (!assemble(tires)) {  // more entries than reserved: the tires stay as their solves left them
    ++work_.overflows;
    return;
  }
  // The active set: a normal starts in while it is applied or pressed in. Each row starts from its
  // last multiplier (a surface row from what its tire's solve applied).
  for (Row& r : rows_) r.active = r.normal >= 0 ? !r.kinetic : r.target > 0.0 || r.applied > 0.0;
  // c + D applied: what the rows ask of the multipliers' totals.
  for (std::size_t r = 0; r < rows_.size(); ++r) rows_[r].rhs = rows_[r].target + d_times(r, &Row::applied);
  const double alpha_tilde = ctx.config->rigid_compliance / (ctx.h * ctx.h);
  live_.resize(rows_.size());
  bool solved = false, settled = false;
  for (int pass = 0; pass < kPasses; ++pass) {
    ++work_.passes;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      const Row& row = rows_[r];
      live_[r] = row.active && (row.normal < 0 || rows_[static_cast<std::size_t>(row.normal)].active);
    }
    solved = solve_active(alpha_tilde);
    if (!solved) break;
    bool changed = false;
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      Row& row = rows_[r];
      if (row.normal < 0) {
        if (row.active && row.lambda < 0.0) {  // it would pull: let go
          row.active = false;
          changed = true;
        } else if (!row.active) {  // back in if the solve pushes it into the other tire
          if (row.rhs - d_times(r, &Row::lambda) > ctx.config->contact_slop) {
            row.active = true;
            changed = true;
          }
        }
      } else if (row.active && live_[r]) {  // Coulomb: static while |λ_t| ≤ μ λ_n
        if (std::abs(row.lambda) > coulomb_bound(row)) {
          row.active = false;  // sliding, from now on this substep: kinetic friction below
          row.lambda = 0.0;
          changed = true;
        }
      }
    }
    if (!changed) {
      settled = true;
      break;
    }
  }
  if (!solved) {  // the tires stay as their solves left them
    ++work_.failures;
    for (Row& r : rows_) r.lambda = r.applied;
  }
  // When the passes ran out with the active set still changing, the multipliers are made feasible
  // (λ_n ≥ 0, |λ_t| ≤ μ λ_n) and polished by projected Gauss–Seidel sweeps on (D + α̃) λ = rhs over
  // all rows: each sweep lowers the problem's quadratic energy, so what the passes left is not
  // handed on half-solved.
  if (solved && !settled) {
    ++work_.unsettled;
    const auto project = [&](std::size_t r) {
      Row& row = rows_[r];
      if (row.normal < 0) {
        row.lambda = std::max(row.lambda, 0.0);
      } else {
        const double bound = std::max(coulomb_bound(row), 0.0);
        row.lambda = std::clamp(row.lambda, -bound, bound);
      }
    };
    for (std::size_t r = 0; r < rows_.size(); ++r) project(r);
    for (int sweep = 0; sweep < kPolishSweeps; ++sweep)
      for (std::size_t r = 0; r < rows_.size(); ++r) {
        rows_[r].lambda = relaxed(r, alpha_tilde);
        project(r);
      }
    for (Row& r : rows_) r.active = r.normal < 0 ? r.lambda > 0.0 : true;
  }
  // Kinetic friction at the contacts that slide (Coulomb, μ_k = μ between tires): what stops the
  // slip the solve left them, through both tires' response, at most μ λ_n, one sweep in row order.
  // In the solve, not the velocity pass: there, handed to the neighbour as a push for its next
  // prediction, it passed a velocity between two tires at rest back and forth for ever.
  if (solved) {
    for (std::size_t r = 0; r < rows_.size(); ++r) {
      Row& row = rows_[r];
      if (row.normal < 0 || row.active) continue;
      if (row.bound < 0.0) {
        const Row& n = rows_[static_cast<std::size_t>(row.normal)];
        if (!n.active || !(n.lambda > 0.0)) continue;
      }
      const double bound = coulomb_bound(row);
      row.lambda = std::clamp(relaxed(r, alpha_tilde), -bound, bound);
    }
  }
  // Δx_t = Σ_r K̂₀_t⁻¹ J_{r,t}ᵀ (λ_r − applied_r), part of the substep's linearised step: a tire it
  // turns far asks for the refinement as its own solve would (a blow at 10 m/s at one substep,
  // corrected in one linear step, ended with the pair's energy up by half). Each tire sums over its
  // own rows in row order (rows_of_tire_), so its sum is the same on any thread.
  correction_.assign(dof_begin_.back(), 0.0);
  for_range(pool, members.size(), [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      if (!ready_[k]) continue;
      const std::uint32_t tire = members[k];
      Tire& t = tires[tire];
      double* dx = correction_.data() + dof_begin_[k];
      for (std::uint32_t j = rows_of_tire_begin_[k]; j < rows_of_tire_begin_[k + 1]; ++j) {
        const Row& r = rows_[rows_of_tire_[j]];
        const double change = r.lambda - r.applied;
        if (change == 0.0) continue;
        const double* w = w_.data() + (r.a == tire ? r.wa : r.wb);
        for (std::size_t i = 0; i < CyclicBlockCholesky::kBlock * t.n; ++i) dx[i] += w[i] * change;
      }
      t.newton_turn = std::max(t.newton_turn, solvers_[k]->largest_turn(t, dx));
      for (std::uint32_t i = 0; i < 2 * t.n; ++i) {
        const std::size_t d = GlobalSolver::dof(i, t.n);
        t.particles.x[i] += Vec2{dx[d], dx[d + 1]};
      }
    }
  });
  write_records(tires, ctx);
  // The rows between tires: their multipliers (the next loads, held()), and their anchors. A surface
  // row starts from what its tire's solve applied, and keeps nothing.
  next_h_ = ctx.h;
  for (const Row& r : rows_) {
    if (r.surface) continue;
    const std::uint64_t k = key(r);
    next_lambda_.push_back({lambda_key(r), r.lambda});
    // A held contact's friction anchor: kept while its friction holds, else laid where the
    // particle is now along the edge.
    if (r.normal < 0 || !(rows_[static_cast<std::size_t>(r.normal)].lambda > 0.0)) continue;
    const Anchor* anchor = anchor_of(k);
    if (anchor != nullptr && r.active) {
      next_anchors_.push_back(*anchor);
      continue;
    }
    const Vec2* xb = tires[r.b].particles.x.data();
    const Vec2 e = xb[r.e1] - xb[r.e0];
    const double e2 = length_squared(e);
    if (e2 > 0.0)
      next_anchors_.push_back({k, r.e0, dot(tires[r.a].particles.x[r.particle] - xb[r.e0], e) / e2});
  }
}

// The particle's contact record, as the velocity pass (kinetic friction against the neighbour's
// tread) and the rest of the engine (grounded, on_tire) read them; λ as distances (contact.h). The
// surface rows first: a contact the island held again gets a record, one its tire's solve holds
// the island's friction; a particle held by a surface keeps that record.
void IslandContacts::write_records(std::vector<Tire>& tires, const SubstepContext& ctx) const {
  const double g = ctx.config->ground_normal_y;
  const auto friction_of = [&](std::size_t r) {
    return r + 1 < rows_.size() && rows_[r + 1].normal == static_cast<std::int32_t>(r) ? &rows_[r + 1]
                                                                                       : nullptr;
  };
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const Row& row = rows_[r];
    if (!row.surface) continue;
    Tire& ta = tires[row.a];
    const double w = ta.particles.w[row.particle];
    if (row.bound >= 0.0) {  // the friction of a contact the tire's solve holds, in its record
      ContactRecord& rec = ta.contacts[row.particle];
      rec.lambda_t = w * row.lambda;
      rec.stuck = true;  // static or kinetic, the island's: not the velocity pass's
      continue;
    }
    if (row.normal >= 0 || !(row.lambda > 0.0)) continue;
    const Row* friction = friction_of(r);
    ContactRecord& rec = ta.touch_contact(row.particle);
    rec = ContactRecord{};
    rec.normal = row.d;
    rec.surface_velocity = row.surface_motion * (1.0 / ctx.h);
    rec.lambda_n = w * row.lambda;
    rec.lambda_t = friction ? w * friction->lambda : 0.0;
    rec.mu_static = rec.mu_kinetic = row.mu;
    rec.prop = row.prop;
    rec.plane = row.plane;
    rec.active = true;
    rec.stuck = true;  // its friction, static or kinetic, is the solve's: not the velocity pass's
  }
  for (std::size_t r = 0; r < rows_.size(); ++r) {
    const Row& row = rows_[r];
    if (row.surface || row.normal >= 0 || !(row.lambda > 0.0)) continue;
    Tire& ta = tires[row.a];
    if (ta.contacts[row.particle].active && ta.contacts[row.particle].tire < 0) continue;
    Tire& tb = tires[row.b];
    const Row* friction = friction_of(r);
    const double w = ta.particles.w[row.particle];
    const Vec2 m0 = tb.particles.x[row.e0] - tb.particles.x_prev[row.e0];
    const Vec2 m1 = tb.particles.x[row.e1] - tb.particles.x_prev[row.e1];
    ContactRecord& rec = ta.touch_contact(row.particle);
    rec = ContactRecord{};
    rec.normal = row.d;
    rec.surface_velocity = (m0 * (1.0 - row.s) + m1 * row.s) * (1.0 / ctx.h);
    rec.lambda_n = w * row.lambda;
    rec.lambda_t = friction ? w * friction->lambda : 0.0;
    rec.mu_static = rec.mu_kinetic = row.mu;
    rec.active = true;
    rec.stuck = true;  // its friction, static or kinetic, is the solve's: not the velocity pass's
    rec.tire = static_cast<std::int32_t>(row.b);
    rec.other_give_t = 1.0 / tb.total_mass();
    if (row.d.y >= g) ta.on_tire[row.particle] = 1;                  // resting on the neighbour
    if (row.d.y <= -g) tb.on_tire[row.e0] = tb.on_tire[row.e1] = 1;  // carrying it
  }
}

}  // namespace tire
