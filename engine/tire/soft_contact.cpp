#include "tire/tire/soft_contact.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "tire/math/trig.h"
#include "tire/xpbd/area_constraint.h"

namespace tire {

template <typename F>
void TirePairFinder::sweep(F&& fn) const {
  const auto n = static_cast<std::uint32_t>(order_.size());
  for (std::uint32_t s = 0; s < n; ++s) {
    const Aabb& a = bounds_[order_[s].index];
    for (std::uint32_t k = s + 1; k < n && order_[k].min_x <= a.max.x; ++k) {
      const std::uint32_t i = order_[s].index, j = order_[k].index;
      if (a.overlaps(bounds_[j])) fn(i, j);
    }
  }
}

void TirePairFinder::find(const std::vector<Tire>& tires, std::span<const std::uint32_t> which, double dt,
                          double gravity, std::uint32_t max_neighbours, std::vector<TirePair>& out) {
  out.clear();
  const auto n = static_cast<std::uint32_t>(which.size());
  bounds_.resize(tires.size());
  order_.resize(n);
  for (std::uint32_t w = 0; w < n; ++w) {
    const std::uint32_t i = which[w];
    const ArrayView<Vec2>& x = tires[i].particles.x;
    const ArrayView<Vec2>& v = tires[i].particles.v;
    Aabb b{x.front(), x.front()};
    double speed2 = 0.0;
    for (std::uint32_t k = 0; k < tires[i].n; ++k) {  // the tread bounds the tire
      b.include(x[k]);
      speed2 = std::max(speed2, length_squared(v[k]));
    }
    // Both tires of a pair are expanded, so each covers its own travel.
    bounds_[i] = b.expanded(std::sqrt(speed2) * dt + 0.5 * gravity * dt * dt + kTirePairSkin);
    order_[w] = {bounds_[i].min.x, i};
  }
  std::sort(order_.begin(), order_.end(), [](const Entry& l, const Entry& r) {
    return l.min_x < r.min_x || (l.min_x == r.min_x && l.index < r.index);
  });
  // Every candidate a pair, while no tire has more than max_neighbours of them (a pile, a crowd):
  // one sweep.
  count_.assign(tires.size(), 0);
  capped_ = false;
  sweep([&](std::uint32_t i, std::uint32_t j) {
    ++count_[i];
    ++count_[j];
    if (count_[i] > max_neighbours || count_[j] > max_neighbours) capped_ = true;
    if (!capped_) out.push_back({std::min(i, j), std::max(i, j)});
  });
  if (!capped_) return;
  keep_nearest_pairs(which, max_neighbours, out);
}

TirePairFinder::Near TirePairFinder::nearness(std::uint32_t i, std::uint32_t j) const {
  const Aabb &a = bounds_[i], &b = bounds_[j];
  const Vec2 half_a = (a.max - a.min) * 0.5, half_b = (b.max - b.min) * 0.5;
  const double reach = std::max(half_a.x, half_a.y) + std::max(half_b.x, half_b.y);
  const double apart = length((a.min + half_a) - (b.min + half_b)) / reach;
  // Not a number (bounds out at infinity) sorts last, so that the order stays an order.
  return {std::isnan(apart) ? std::numeric_limits<double>::infinity() : apart, i > j ? i - j : j - i,
          std::min(i, j), std::max(i, j)};
}

// Some tire has more candidates than it may keep: it is crowded. A pair of tires that are not is
// kept as it is. The others are chosen greedily, nearest first, each taken while neither of its
// crowded tires has max_neighbours yet, among a bounded set: a crowded tire's pairs with tires that
// are not (those have at most max_neighbours candidates each), and between two crowded tires, those
// where one is among the other's max_neighbours nearest. A tire that choice leaves with none then
// takes its nearest candidate; if that one has max_neighbours, it gives up its farthest partner
// that keeps another. Then a last sweep lists the pairs kept in the sweep's order.
void TirePairFinder::keep_nearest_pairs(std::span<const std::uint32_t> which, std::uint32_t max_neighbours,
                                        std::vector<TirePair>& out) {
  out.clear();
  const std::size_t k = max_neighbours;
  constexpr Near kFar{std::numeric_limits<double>::infinity(), 0, 0, 0};
  std::uint32_t crowded = 0;
  slot_.resize(bounds_.size());
  degree_.resize(bounds_.size());
  best_.resize(bounds_.size());
  for (const std::uint32_t i : which) {
    slot_[i] = count_[i] > max_neighbours ? crowded++ : kNotCrowded;
    degree_[i] = 0;
    best_[i] = kFar;
  }
  nearest_.resize(crowded * k);
  nearest_size_.assign(crowded, 0);
  candidates_.clear();
  sweep([&](std::uint32_t i, std::uint32_t j) {
    if (slot_[i] == kNotCrowded && slot_[j] == kNotCrowded) {
      ++degree_[i];
      ++degree_[j];
      return;
    }
    const Near near = nearness(i, j);
    best_[i] = std::min(best_[i], near);
    best_[j] = std::min(best_[j], near);
    if (slot_[i] == kNotCrowded || slot_[j] == kNotCrowded) {
      candidates_.push_back(near);
      return;
    }
    offer(slot_[i], near, k);
    offer(slot_[j], near, k);
  });
  // Between two crowded tires: each pair in either's nearest, once.
  const auto nearest_of = [&](std::uint32_t slot) {
    return std::span<Near>(&nearest_[slot * k], nearest_size_[slot]);
  };
  const auto by_other = [](std::uint32_t self) {
    return [self](const Near& l, const Near& r) { return l.other(self) < r.other(self); };
  };
  for (const std::uint32_t i : which)
    if (slot_[i] != kNotCrowded) {
      const std::span<Near> nearest = nearest_of(slot_[i]);
      std::sort(nearest.begin(), nearest.end(), by_other(i));
    }
  for (const std::uint32_t i : which) {
    if (slot_[i] == kNotCrowded) continue;
    for (const Near& near : nearest_of(slot_[i])) {
      const std::uint32_t j = near.other(i);
      const std::span<Near> theirs = nearest_of(slot_[j]);
      if (i < j || !std::binary_search(theirs.begin(), theirs.end(), near, by_other(j)))
        candidates_.push_back(near);
    }
  }
  std::sort(candidates_.begin(), candidates_.end());
  kept_.resize(crowded * k);
  kept_size_.assign(crowded, 0);
  const auto full = [&](std::uint32_t i) { return slot_[i] != kNotCrowded && kept_size_[slot_[i]] == k; };
  const auto keep = [&](std::uint32_t i, std::uint32_t j) {
    ++degree_[i];
    ++degree_[j];
    if (slot_[i] != kNotCrowded) kept_[slot_[i] * k + kept_size_[slot_[i]]++] = j;
    if (slot_[j] != kNotCrowded) kept_[slot_[j] * k + kept_size_[slot_[j]]++] = i;
  };
  for (const Near& c : candidates_)
    if (!full(c.a) && !full(c.b)) keep(c.a, c.b);
  for (const std::uint32_t i : which) {
    if (degree_[i] > 0 || best_[i].apart == kFar.apart) continue;
    const std::uint32_t j = best_[i].other(i);
    if (full(j) && !give_up_farthest(j, k)) continue;
    keep(i, j);
  }
  for (const std::uint32_t i : which)
    if (slot_[i] != kNotCrowded) std::sort(&kept_[slot_[i] * k], &kept_[slot_[i] * k] + kept_size_[slot_[i]]);
  const auto kept = [&](std::uint32_t i, std::uint32_t j) {
    const std::uint32_t* first = &kept_[slot_[i] * k];
    return std::binary_search(first, first + kept_size_[slot_[i]], j);
  };
  sweep([&](std::uint32_t i, std::uint32_t j) {
    const bool keep_pair = slot_[i] != kNotCrowded ? kept(i, j) : slot_[j] == kNotCrowded || kept(j, i);
    if (keep_pair) out.push_back({std::min(i, j), std::max(i, j)});
  });
}

// Crowded tire j, full, drops its farthest partner that keeps another pair; false when each of its
// partners has j alone.
bool TirePairFinder::give_up_farthest(std::uint32_t j, std::size_t k) {
  std::uint32_t* partners = &kept_[slot_[j] * k];
  std::uint32_t& size = kept_size_[slot_[j]];
  std::size_t farthest = size;
  for (std::size_t p = 0; p < size; ++p)
    if (degree_[partners[p]] >= 2 &&
        (farthest == size || nearness(j, partners[farthest]) < nearness(j, partners[p])))
      farthest = p;
  if (farthest == size) return false;
  const std::uint32_t m = partners[farthest];
  --size;
  partners[farthest] = partners[size];
  if (slot_[m] != kNotCrowded) {
    std::uint32_t* theirs = &kept_[slot_[m] * k];
    std::uint32_t& their_size = kept_size_[slot_[m]];
    std::uint32_t* mine = std::find(theirs, theirs + their_size, j);
    --their_size;
    *mine = theirs[their_size];
  }
  --degree_[j];
  --degree_[m];
  return true;
}

// A crowded tire's nearest so far: a max-heap of at most k, the farthest on top.
void TirePairFinder::offer(std::uint32_t slot, const Near& near, std::size_t k) {
  Near* heap = nearest_.data() + slot * k;
  std::uint32_t& size = nearest_size_[slot];
  if (size < k) {
    heap[size++] = near;
    std::push_heap(heap, heap + size);
  } else if (near < heap[0]) {
    std::pop_heap(heap, heap + size);
    heap[size - 1] = near;
    std::push_heap(heap, heap + size);
  }
}

namespace {

// A monotone stand-in for the angle of (x, y), in quarter turns [0, 4): exact on the axes and the
// diagonals, within 0.05 of a quarter turn elsewhere, and far cheaper than atan2.
double pseudo_angle(double x, double y) {
  const double sum = std::abs(x) + std::abs(y);
  if (sum <= 0.0) return 0.0;
  const double p = y / sum;  // in [−1, 1]
  return x >= 0.0 ? (y >= 0.0 ? p : 4.0 + p) : 2.0 - p;
}

// How wedge_edge guesses its first edge: from the exact angle, or from pseudo_angle. A ring that
// holds its shape is star-shaped, the walk finds its one edge from either guess, and the cheap one
// will do; a tread crushed around its rim may not be, and which edge the walk settles on then
// depends on where it starts: the exact angle starts it at the edge the particle faces.
enum class Guess { exact_angle, pseudo_angle };

// Index k of the tread edge (x_k, x_k+1) whose wedge from `hub` contains direction d. The tread
// stays star-shaped about its hub, so the edge is guessed from the angle of d relative to particle
// 0, then confirmed by walking at most a few edges either way (the guess is within a segment or so).
std::uint32_t wedge_edge(const Vec2* x, std::uint32_t n, Vec2 hub, Vec2 d, Guess guess) {
  const Vec2 r0 = x[0] - hub;
  double turn;
  if (guess == Guess::pseudo_angle) {
    turn = pseudo_angle(dot(r0, d), cross(r0, d)) / 4.0;
  } else {
    double angle = tire::atan2(cross(r0, d), dot(r0, d));
    if (angle < 0.0) angle += 2.0 * std::numbers::pi;
    turn = angle / (2.0 * std::numbers::pi);
  }
  auto k = static_cast<std::uint32_t>(turn * n) % n;
  for (std::uint32_t step = 0; step < n; ++step) {
    const Vec2 a = x[k] - hub, b = x[(k + 1) % n] - hub;
    if (cross(a, d) < 0.0)
      k = (k + n - 1) % n;  // d is before edge k: step back
    else if (cross(d, b) < 0.0)
      k = (k + 1) % n;  // d is past edge k: step on
    else
      return k;
  }
  return k;
}

// A ring of particles that others must stay outside of: a tire's tread, or its own rim.
struct Ring {
  Vec2* x;
  const Vec2* x_prev;
  const double* w;
  std::uint32_t n;
  Vec2 hub;
  double reach;
  std::uint8_t* on_tire;  // per ring particle: something rests on it (null: not tracked)
  Guess guess;            // a tread holds its shape; a rim's tread may be crushed around it
};

// Particles of `a`'s tread against the edges of `ring`. `mu` is the friction between them;
// `soft_lambda` accumulates the normal λ per tread particle for that friction (null: frictionless).
// `max_depth` (m): deeper is not a contact but a ring that lost its shape; leave it.
void push_out(Tire& a, const Ring& ring, double mu, double* soft_lambda, double ground_normal_y,
              double max_depth = 1e300) {
  const std::uint32_t nb = ring.n;
  Vec2* xb = ring.x;
  const double* wb = ring.w;
  const double reach2 = ring.reach * ring.reach;
  for (std::uint32_t i = 0; i < a.n; ++i) {
    Vec2& p = a.particles.x[i];
    const Vec2 d = p - ring.hub;
    if (length_squared(d) >= reach2) continue;  // outside the ring's bounding circle
    const std::uint32_t k = wedge_edge(xb, nb, ring.hub, d, ring.guess);
    const std::uint32_t k1 = (k + 1) % nb;
    const Vec2 e = xb[k1] - xb[k];
    const double e2 = length_squared(e);
    if (e2 <= 0.0) continue;
    const Vec2 n = Vec2{e.y, -e.x} * (1.0 / std::sqrt(e2));  // outward: rings are counter-clockwise
    const double C = dot(n, p - xb[k]);
    if (C >= 0.0 || -C > max_depth) continue;
    const double t = std::clamp(dot(p - xb[k], e) / e2, 0.0, 1.0);
    const double w0 = wb[k] * (1.0 - t) * (1.0 - t), w1 = wb[k1] * t * t, wp = a.particles.w[i];
    const double w_sum = wp + w0 + w1;
    if (w_sum <= 0.0) continue;
    // Normal: Δλ = −C / Σ w|∇C|²  (XPBD eq. 18, α = 0)
    const double dl = -C / w_sum;
    p += n * (wp * dl);
    xb[k] -= n * (wb[k] * (1.0 - t) * dl);
    xb[k1] -= n * (wb[k1] * t * dl);
    if (ring.on_tire) {
      if (n.y <= -ground_normal_y) ring.on_tire[k] = ring.on_tire[k1] = 1;  // the ring's tire rests on a
      if (n.y >= ground_normal_y) a.on_tire[i] = 1;                         // a rests on the ring's tire
    }
    if (!soft_lambda) continue;
    soft_lambda[i] += dl;
    // Static friction on the motion of p relative to the edge point this substep.
    const Vec2 edge_motion = (xb[k] - ring.x_prev[k]) * (1.0 - t) + (xb[k1] - ring.x_prev[k1]) * t;
    const Vec2 dp = (p - a.particles.x_prev[i]) - edge_motion;
    const Vec2 dp_t = dp - n * dot(dp, n);
    const double lt = length(dp_t) / w_sum;  // |Δλ_t| that would stop it
    if (lt <= 0.0 || lt >= mu * soft_lambda[i]) continue;
    const Vec2 g = dp_t * (1.0 / w_sum);
    p -= g * wp;
    xb[k] += g * (wb[k] * (1.0 - t));
    xb[k1] += g * (wb[k1] * t);
  }
}

Ring tread_of(Tire& t) {
  return {t.particles.x.data(), t.particles.x_prev.data(), t.particles.w.data(), t.n, t.tread_hub,
          t.tread_reach,        t.on_tire.data(),          Guess::pseudo_angle};
}

}  // namespace

std::uint32_t tread_edge_towards(const Vec2* x, std::uint32_t n, Vec2 hub, Vec2 d) {
  return wedge_edge(x, n, hub, d, Guess::pseudo_angle);
}

void solve_tire_contact(Tire& a, Tire& b, double ground_normal_y) {
  // Bounding circles apart: nothing to do.
  const double reach = a.tread_reach + b.tread_reach;
  if (length_squared(a.tread_hub - b.tread_hub) >= reach * reach) return;
  const double mu = std::sqrt(a.spec.friction * b.spec.friction);
  push_out(a, tread_of(b), mu, a.soft_lambda.data(), ground_normal_y);
  push_out(b, tread_of(a), mu, b.soft_lambda.data(), ground_normal_y);
}

namespace {

// Rim particles of `t` kept inside its tread polygon: the other half of the tread–rim contact (a
// rim particle can poke out between two tread particles without any tread particle entering the
// rim).
void keep_rim_inside_tread(Tire& t) {
  const std::uint32_t n = t.n;
  Vec2* x = t.particles.x.data();
  const double* w = t.particles.w.data();
  // Nearer the rim's hub than the tread's inradius (a lower bound on how far the tread's edges are:
  // its nearest particle times cos(π/N)) is surely inside: the usual case, skipped cheaply.
  double nearest2 = 1e300;
  for (std::uint32_t i = 0; i < n; ++i) nearest2 = std::min(nearest2, length_squared(x[i] - t.rim_hub));
  const double cos_half = cos_sin(std::numbers::pi / n).cos;
  const double inside2 = nearest2 * cos_half * cos_half;
  for (std::uint32_t j = n; j < 2 * n; ++j) {
    Vec2& p = x[j];
    if (length_squared(p - t.rim_hub) < inside2) continue;
    // The tread wraps the rim, so it is star-shaped about the rim's hub even when crushed flat.
    const std::uint32_t k = wedge_edge(x, n, t.rim_hub, p - t.rim_hub, Guess::exact_angle);
    const std::uint32_t k1 = (k + 1) % n;
    const Vec2 e = x[k1] - x[k];
    const double e2 = length_squared(e);
    if (e2 <= 0.0) continue;
    const Vec2 normal = Vec2{e.y, -e.x} * (1.0 / std::sqrt(e2));  // outward
    const double C = -dot(normal, p - x[k]);                      // ≥ 0 inside
    if (C >= 0.0 || -C > 2.0 * t.segment_length) continue;        // deeper: lost shape, not a contact
    const double s = std::clamp(dot(p - x[k], e) / e2, 0.0, 1.0);
    const double w_sum = w[j] + w[k] * (1.0 - s) * (1.0 - s) + w[k1] * s * s;
    if (w_sum <= 0.0) continue;
    const double dl = -C / w_sum;  // XPBD eq. 18, α = 0, with ∇_p C = −n
    p -= normal * (w[j] * dl);
    x[k] += normal * (w[k] * (1.0 - s) * dl);
    x[k1] += normal * (w[k1] * s * dl);
  }
}

}  // namespace

bool rim_can_hold_tread(const Tire& t) {
  // This is the contact of a rim that holds its shape: edges are found by angle about the rim's
  // hub, and the tread, wrapped around it, is star-shaped about it too. A rubbery rim (compliance
  // above kRigidRimCompliance, far softer than any real wheel) or one collapsed below a fifth of its
  // area is not one, and the contact would only throw particles across a shapeless tangle.
  constexpr double kRigidRimCompliance = 1e-4;  // m/N
  constexpr double kMinRimAreaRatio = 0.2;
  return t.spec.compliance.inner <= kRigidRimCompliance &&
         polygon_area(t.particles.x.data() + t.n, t.n) >= kMinRimAreaRatio * t.rim_area_constraint.rest_area;
}

void keep_tread_outside_rim(Tire& t) {
  const std::uint32_t n = t.n;
  const Ring rim{t.particles.x.data() + n,
                 t.particles.x_prev.data() + n,
                 t.particles.w.data() + n,
                 n,
                 t.rim_hub,
                 t.rim_reach,
                 nullptr,
                 Guess::exact_angle};
  // Within one substep a particle gets about a segment inside (the anti-tunneling clamp); much
  // deeper is a ring that lost its shape, not a contact.
  push_out(t, rim, 0.0, nullptr, 0.0, 2.0 * t.segment_length);
  keep_rim_inside_tread(t);
}

}  // namespace tire
