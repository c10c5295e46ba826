#include "tire/tire/global_solver.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "tire/math/check.h"
#include "tire/math/dense_solve.h"
#include "tire/math/trig.h"
#include "tire/math/turn.h"
#include "tire/tire/tire_solver.h"
#include "tire/xpbd/contact.h"

namespace tire {

namespace {

// A friction anchor further than this (m) from where the substep's slip alone would hold
// the particle is laid again: what it would take back is no longer a creep the friction let
// through but a slide. (Kept at any distance, the anchor on a small ball spun under a tire at one
// substep, 0.5 rad round it a substep, dragged the tread after it and threw the ball at 70 m/s.)
constexpr double kAnchorReach = 1e-3;

// Whether an anchor still holds: within kAnchorReach of where the substep's slip alone would hold
// the particle, its start moved with the surface under it.
bool within_reach(Vec2 anchor, Vec2 x_prev, Vec2 surface_displacement) {
  return length_squared(anchor - x_prev - surface_displacement) < kAnchorReach * kAnchorReach;
}

// The block after block k round the ring (without a division: an integer one cost as much as the
// rest of a constraint's assembly).
std::uint32_t next_block(std::uint32_t k, std::uint32_t n) { return k + 1 == n ? 0 : k + 1; }

// s n nᵀ, a 2×2 symmetric outer product: its three distinct entries.
struct Outer {
  double xx, xy, yy;
  Outer operator-() const { return {-xx, -xy, -yy}; }
  Outer operator+(const Outer& o) const { return {xx + o.xx, xy + o.xy, yy + o.yy}; }
};
Outer outer(Vec2 n, double s) { return {s * n.x * n.x, s * n.x * n.y, s * n.y * n.y}; }

// m[ro.., co..] += o: a 2×2 outer product into a 4×4 block, at particle offsets ro and co.
void add_outer(Block4& m, std::size_t ro, std::size_t co, const Outer& o) {
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  m[ro * B + co] += o.xx;
  m[ro * B + co + 1] += o.xy;
  m[(ro + 1) * B + co] += o.xy;
  m[(ro + 1) * B + co + 1] += o.yy;
}

// a·b over n entries, n whole blocks of 4: four partial sums, one per place in a block, added at
// the end. Their chains of additions overlap, where one sum's would wait on each add in turn (the
// capacitance system's dot products were a tenth of a solve).
double dot_n(const double* a, const double* b, std::size_t n) {
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  TIRE_ASSERT(n % B == 0, "a dot product over part of a block");
  double s[B] = {0.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < n; i += B)
    for (std::size_t l = 0; l < B; ++l) s[l] += a[i + l] * b[i + l];
  return (s[0] + s[1]) + (s[2] + s[3]);
}

Vec2 at(const double* v, std::size_t dof) { return {v[dof], v[dof + 1]}; }

// S = L Lᵀ in place, for the m × m symmetric positive definite S in the lower triangle of s: false
// when a pivot is not positive.
template <std::size_t N>
bool cholesky(double (&s)[N][N], std::size_t m) {
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t q = 0; q <= r; ++q) {
      double v = s[r][q];
      for (std::size_t k = 0; k < q; ++k) v -= s[r][k] * s[q][k];
      if (q < r)
        s[r][q] = v / s[q][q];
      else if (v > 0.0)
        s[r][r] = std::sqrt(v);
      else
        return false;
    }
  }
  return true;
}

// z ← S⁻¹ z with cholesky's factor: L y = z, then Lᵀ z = y.
template <std::size_t N>
void cholesky_solve(const double (&s)[N][N], std::size_t m, double* z) {
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t k = 0; k < r; ++k) z[r] -= s[r][k] * z[k];
    z[r] /= s[r][r];
  }
  for (std::size_t r = m; r-- > 0;) {
    for (std::size_t k = r + 1; k < m; ++k) z[r] -= s[k][r] * z[k];
    z[r] /= s[r][r];
  }
}

}  // namespace

void GlobalSolver::reserve(std::uint32_t segments) {
  if (segments <= segments_) return;
  segments_ = segments;
  stride_ = CyclicBlockCholesky::kBlock * segments;
  k_.reserve(segments);
  k0_.reserve(segments);
  y0_.assign(kBaseRows * stride_, 0.0);
  base_diagonal_.resize(segments);
  base_coupling_.resize(segments);
  base_f_.assign(stride_, 0.0);
  f_.assign(stride_, 0.0);
  dx_.assign(stride_, 0.0);
  rows_.reserve(kMaxRows);
  g_.assign(kMaxRows * stride_, 0.0);
  y_.assign(kMaxRows * stride_, 0.0);
  yb_.assign(3 * kMaxBodies * stride_, 0.0);
  bodies_.reserve(kMaxBodies);
  contacts_.reserve(2 * std::size_t{segments});
  contact_of_.assign(2 * std::size_t{segments}, -1);
  depth_.assign(2 * std::size_t{segments}, 0.0);
  gradient_.assign(2 * std::size_t{segments}, Vec2{});  // a ring's area, or the whole tire's turn
  links_.reserve(kMaxLinksPerSegment * std::size_t{segments});
}

// K = M + (1 + γ) Jᵀ α̃⁻¹ J and f = −M (x − x̃) − Jᵀ α̃⁻¹ (C + γ ΔC) over the distance
// constraints (XPBD eq. 9–10 and 26 in the primal form, see the header), without the contacts.
void GlobalSolver::assemble(const Tire& t, const SubstepContext& ctx, double gamma) {
  const std::uint32_t n = t.n;
  const Particles& p = t.particles;
  const double h = ctx.h;
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  for (std::uint32_t k = 0; k < n; ++k) {
    base_diagonal_[k].fill(0.0);
    base_coupling_[k].fill(0.0);
  }
  for (std::uint32_t i = 0; i < 2 * n; ++i) {
    TIRE_ASSERT(p.w[i] > 0.0, "the global method needs every particle of a tire to have a finite mass");
    const double m = 1.0 / p.w[i];
    const std::size_t o = GlobalSolver::offset(i, n);
    Block4& d = base_diagonal_[GlobalSolver::block(i, n)];
    d[o * B + o] += m;
    d[(o + 1) * B + o + 1] += m;
    const Vec2 predicted = p.x_prev[i] + p.v[i] * h;  // x̃ (predict_positions made x exactly this)
    const Vec2 r = (p.x[i] - predicted) * -m;
    const std::size_t k = GlobalSolver::dof(i, n);
    base_f_[k] = r.x;
    base_f_[k + 1] = r.y;
  }
  const double min_compliance = ctx.config->rigid_compliance;
  const double h2 = h * h;
  double last_compliance = -1.0, inv_alpha_tilde = 0.0;  // the groups' few compliances, in runs
  links_.clear();
  const auto constraints = t.distance.constraints();
  TIRE_ASSERT(constraints.size() <= links_.capacity(),
              "a tire with more constraints than the global solver has room for");
  // Each constraint's gradient and its terms of K and f, kept in links_ (largest_turn reads the
  // particles and unknowns again), then summed into the blocks.
  for (const DistanceConstraint& c : constraints) {
    Link l;
    l.a = c.a;
    l.b = c.b;
    l.dof_a = GlobalSolver::dof(c.a, n);
    l.dof_b = GlobalSolver::dof(c.b, n);
    const Vec2 d = p.x[c.b] - p.x[c.a];
    const double len = length(d);
    if (len > 0.0) {               // coincident particles: no gradient (as in the Gauss–Seidel kernel)
      l.normal = d * (1.0 / len);  // ∇_b C = n = −∇_a C
      if (c.compliance != last_compliance) {
        last_compliance = c.compliance;
        inv_alpha_tilde = h2 / std::max(c.compliance, min_compliance);
      }
      // The constraint's change over the substep, C(x) − C(xₙ): eq. 26's ∇C·(x − xₙ) to first
      // order, but zero for a rigid turn, where the linearisation reads a turn by θ as a shortening
      // by L(1 − cos θ), and damping then squeezed a fast-spinning tire (its area 96 % at 30 rad/s
      // and 2 substeps). Its derivative is ∇C, as K's (1 + γ) factor has it.
      const double rate = len - length(p.x_prev[c.b] - p.x_prev[c.a]);
      l.force = (len - c.rest_length + gamma * rate) * inv_alpha_tilde;
      l.stiffness = (1.0 + gamma) * inv_alpha_tilde;
      // The Hessian's other term, force · ∇²C = (force/len)(I − nnᵀ): a stretched link resists
      // turning as a string under tension does. Gauss–Newton leaves it out, which treats that
      // stiffness explicitly: a soft tire under a few times its weight, whose spokes hang the hub
      // under tension, then gained energy every substep at 2 substeps and rang for ever. Kept where
      // it is positive (tension), dropped under compression, so K stays positive definite
      // (projected Newton; Teran et al. 2005, "Robust quasistatic finite elements", Sec. 4).
      l.transverse = std::max(0.0, l.force) / len;
    }
    links_.push_back(l);
  }
  for (const Link& l : links_) {
    if (l.stiffness == 0.0) continue;
    const Vec2 nrm = l.normal;
    base_f_[l.dof_a] += nrm.x * l.force;
    base_f_[l.dof_a + 1] += nrm.y * l.force;
    base_f_[l.dof_b] -= nrm.x * l.force;
    base_f_[l.dof_b + 1] -= nrm.y * l.force;
    const double s = l.stiffness;
    const std::uint32_t ba = GlobalSolver::block(l.a, n), bb = GlobalSolver::block(l.b, n);
    const std::size_t oa = l.dof_a - B * ba, ob = l.dof_b - B * bb;
    const Outer o = outer(nrm, s) + outer(perp(nrm), l.transverse);
    add_outer(base_diagonal_[ba], oa, oa, o);
    add_outer(base_diagonal_[bb], ob, ob, o);
    if (ba == bb) {
      add_outer(base_diagonal_[ba], oa, ob, -o);
      add_outer(base_diagonal_[ba], ob, oa, -o);
    } else if (bb == next_block(ba, n)) {
      add_outer(base_coupling_[ba], ob, oa, -o);  // block row bb, column ba
    } else {
      TIRE_ASSERT(ba == next_block(bb, n), "a tire constraint joins segments that are not neighbours");
      add_outer(base_coupling_[bb], oa, ob, -o);
    }
  }
}

// An area constraint C = A(x) − p A₀ with compliance α, damped as the distance constraints are:
// (g K⁻¹ gᵀ + α̃/(1 + γ)) μ = −(C + γ ΔC)/(1 + γ) − g K⁻¹ f (XPBD eq. 26 divided by 1 + γ, with
// ΔC = C(x) − C(xₙ) for its g·(x − xₙ): see assemble).
void GlobalSolver::add_ring_area_row(const Tire& t, const SubstepContext& ctx, bool rim, double gamma) {
  const AreaConstraint& c = rim ? t.rim_area_constraint : t.area_constraint;
  if (c.count < 3) return;  // no polygon (tests build chains from a tire's particles)
  const Particles& p = t.particles;
  polygon_area_gradient(p.x.data() + c.first, c.count, gradient_.data());
  double* g = gradient_of(rows_.size());
  std::fill(g, g + CyclicBlockCholesky::kBlock * t.n, 0.0);
  for (std::uint32_t k = 0; k < c.count; ++k) {
    const std::size_t d = GlobalSolver::dof(c.first + k, t.n);
    g[d] = gradient_[k].x;
    g[d + 1] = gradient_[k].y;
  }
  const double area = polygon_area(p.x.data() + c.first, c.count);
  const double value = area - c.pressure * c.rest_area;
  const double rate = area - polygon_area(p.x_prev.data() + c.first, c.count);  // C(x) − C(xₙ), as above
  Row row;
  row.alpha_tilde = c.compliance / (ctx.h * ctx.h) / (1.0 + gamma);
  row.b = -(value + gamma * rate) / (1.0 + gamma);
  rows_.push_back(row);
}

void GlobalSolver::add_rolling_row(const Tire& t) {
  const Particles& p = t.particles;
  const std::uint32_t count = t.particle_count();
  const std::span<Vec2> turn(gradient_.data(), count);  // the particles weigh the same (Tire)
  if (!turn_gradient({p.x_prev.data(), count}, turn)) return;
  double* g = gradient_of(rows_.size());
  std::fill(g, g + CyclicBlockCholesky::kBlock * t.n, 0.0);
  double predicted = 0.0;  // C(x̃): the turn the prediction makes
  for (std::uint32_t i = 0; i < count; ++i) {
    const std::size_t d = GlobalSolver::dof(i, t.n);
    g[d] = turn[i].x;
    g[d + 1] = turn[i].y;
    predicted += dot(turn[i], p.x[i] - p.x_prev[i]);
  }
  Row row;
  // As stiff as a rigid contact at the tread: a turn δθ moves the tread by R δθ.
  const double radius = t.spec.outer_radius;
  row.alpha_tilde = rigid_alpha_tilde_ / (radius * radius);
  row.b = -predicted;
  rolling_row_ = static_cast<std::int32_t>(rows_.size());
  rows_.push_back(row);
}

GlobalSolver::Contact GlobalSolver::make_contact(const Tire& t, const SubstepContext& ctx,
                                                 std::uint32_t particle, Vec2 normal, double plane,
                                                 const ContactPair& pair, std::int32_t prop,
                                                 Vec2 surface_velocity) {
  Contact c;
  c.particle = particle;
  c.normal = normal;
  c.plane = plane;
  c.prop = prop;
  c.surface_velocity = surface_velocity;
  c.surface_displacement = surface_velocity * ctx.h;
  c.mu_static = pair.mu_static;
  c.mu_kinetic = pair.mu_kinetic;
  c.friction_active = c.mu_static > 0.0;
  c.fixed = true;
  // Stuck since an earlier substep: back to where it stuck, as the surface will stand at the
  // substep's end, so that what slid while the friction held is taken back too, not only this
  // substep's slip. Each substep's slip alone let what the one linear step leaves over build up:
  // a crate lying on a tire slid over it at a steady 0.03 mm/s with both its contacts stuck, and a
  // soft tire wedged against a wall by a pile slid down it at 0.17 mm/s (docs/at-rest.md).
  if (t.anchor_on[particle] == Tire::anchor_code(prop)) {
    const Vec2 stuck = t.friction_anchor[particle];
    c.anchor =
        prop >= 0
            ? ctx.rigid->props()[static_cast<std::size_t>(prop)].pose_at(ctx.time + ctx.h).to_world(stuck)
            : stuck;
    c.anchored = within_reach(c.anchor, t.particles.x_prev[particle], c.surface_displacement);
  }
  double give_n = 0.0, give_t = 0.0;
  if (prop >= 0) {
    const Prop& body = ctx.rigid->props()[static_cast<std::size_t>(prop)];
    c.fixed = !body.is_dynamic();
    if (body.is_dynamic() && body.support_count == 0 && body.inverse_inertia > 0.0) {
      c.body = body_of(static_cast<std::uint32_t>(prop), body);
      c.arm = t.particles.x[particle] - body.center_at(ctx.time + ctx.h);
    }
    if (body.is_dynamic() && c.body < 0) {
      // What the prop gives way at the contact, w = 1/M + (r × d)²/I along d (Müller 2020 eq. 2),
      // times its mobility along the push (0 into what holds it up; rounding can take 1 − (n·s)² a
      // few 1e-9 below zero, see resolve_contact: clamped).
      const Vec2 r = t.particles.x[particle] - body.center_at(ctx.time + ctx.h);
      const Vec2 tangent = perp(normal);
      const double mob_n = std::max(0.0, body.mobility(-normal));
      const double mob_t = std::max(0.0, std::min(body.mobility(tangent), body.mobility(-tangent)));
      give_n = mob_n * (body.inverse_mass + cross(r, normal) * cross(r, normal) * body.inverse_inertia);
      give_t = mob_t * (body.inverse_mass + cross(r, tangent) * cross(r, tangent) * body.inverse_inertia);
    }
  }
  c.stiffness_n = 1.0 / (rigid_alpha_tilde_ + give_n);
  c.stiffness_t = 1.0 / (rigid_alpha_tilde_ + give_t);
  return c;
}

std::int32_t GlobalSolver::body_of(std::uint32_t prop, const Prop& body) {
  for (std::size_t j = 0; j < bodies_.size(); ++j)
    if (bodies_[j].prop == prop) return static_cast<std::int32_t>(j);
  if (bodies_.size() == kMaxBodies) return -1;
  bodies_.emplace_back();
  bodies_.back().prop = prop;
  bodies_.back().mass = 1.0 / body.inverse_mass;
  bodies_.back().inertia = 1.0 / body.inverse_inertia;
  return static_cast<std::int32_t>(bodies_.size() - 1);
}

bool GlobalSolver::solve_border(std::size_t size) { return solve_augmented(border_, size); }

bool GlobalSolver::find_contacts(const Tire& t, const SubstepContext& ctx, const double* dx) {
  const Particles& p = t.particles;
  const RigidWorld& rigid = *ctx.rigid;
  const std::size_t first_new = contacts_.size();
  ++work_.searches;
  for (const ContactPair& pair : t.pairs) {
    const std::uint32_t i = pair.particle;
    const std::int32_t existing = contact_of_[i];
    if (existing >= 0 && static_cast<std::size_t>(existing) < first_new) continue;
    Vec2 x = p.x[i];
    if (dx) x += at(dx, GlobalSolver::dof(i, t.n));
    std::optional<SurfaceContact> hit;
    std::int32_t prop = -1;
    Vec2 surface_velocity;
    if (!pair.is_prop) {
      hit = swept_box_contact(p.x_prev[i], x, rigid.obstacles()[pair.index].box);
    } else {
      const PropFrame& frame = t.prop_frames[pair.index];
      const Prop& body = rigid.props()[frame.prop];
      hit =
          local_contact(body.geometry, frame.start_local(p.x_prev[i]), frame.end.to_local(x), t.was_held(i));
      if (hit) {
        hit->normal = frame.end.rotate(hit->normal);
        prop = static_cast<std::int32_t>(frame.prop);
        surface_velocity = body.point_velocity(x, ctx.time + ctx.h);
      }
    }
    if (!hit || !(hit->depth > ctx.config->contact_slop)) continue;
    if (existing >= 0 && !(hit->depth > depth_[static_cast<std::size_t>(existing)]))
      continue;  // keep the deeper
    // The plane the particle is held to: the surface's, or short of it by what the particle started
    // the substep inside it less contact_push_speed · h, so that an overlap it was handed is undone
    // at that speed and not in one substep (SolverConfig::contact_push_speed).
    const double plane = dot(hit->normal, x) + hit->depth;
    const double start_gap = dot(hit->normal, p.x_prev[i] + surface_velocity * ctx.h) - plane;
    const double allowed = std::max(0.0, -start_gap - ctx.config->contact_push_speed * ctx.h);
    offer(make_contact(t, ctx, i, hit->normal, plane - allowed, pair, prop, surface_velocity), hit->depth);
  }
  find_tire_contacts(t, ctx, dx, first_new);
  return contacts_.size() > first_new;
}

void GlobalSolver::offer(const Contact& c, double depth) {
  const std::int32_t existing = contact_of_[c.particle];
  if (existing >= 0) {
    contacts_[static_cast<std::size_t>(existing)] = c;
  } else {
    contact_of_[c.particle] = static_cast<std::int32_t>(contacts_.size());
    contacts_.push_back(c);
  }
  depth_[static_cast<std::size_t>(contact_of_[c.particle])] = depth;
}

// A tread particle p inside a neighbour's tread, against the edge (b₀, b₁) it crossed, at s along it:
// C = n·(p − (1−s) b₀ − s b₁) ≥ 0 with the edge as captured (a plane for this iteration), and the
// neighbour's give as a rigid body at that point in the row's compliance, so that p takes its share
// of the correction and the neighbour the rest (its reaction, tire_neighbours.h). Static friction
// against the edge's motion, with the tires' mixed friction.
void GlobalSolver::find_tire_contacts(const Tire& t, const SubstepContext& ctx, const double* dx,
                                      std::size_t first_new) {
  const TireNeighbours* neighbours = ctx.neighbours;
  if (!neighbours) return;
  const Particles& p = t.particles;
  for (const std::uint32_t other : neighbours->neighbours(neighbours->index_of(t))) {
    const TreadView tread = neighbours->tread(other);
    const double reach2 = tread.reach * tread.reach;
    const double mu = mix_friction(t.spec.friction, tread.tire->spec.friction);
    work_.tread_tests += t.n;
    for (std::uint32_t i = 0; i < t.n; ++i) {
      const std::int32_t existing = contact_of_[i];
      if (existing >= 0 && static_cast<std::size_t>(existing) < first_new) continue;
      Vec2 x = p.x[i];
      if (dx) x += at(dx, GlobalSolver::dof(i, t.n));
      const Vec2 d = x - tread.hub;
      if (length_squared(d) >= reach2) continue;  // outside the tread's bounding circle
      const std::uint32_t k = tread_edge_towards(tread.x, tread.n, tread.hub, d);
      const std::uint32_t k1 = (k + 1) % tread.n;
      const Vec2 e = tread.x[k1] - tread.x[k];
      const double e2 = length_squared(e);
      if (!(e2 > 0.0)) continue;
      const Vec2 normal = Vec2{e.y, -e.x} * (1.0 / std::sqrt(e2));  // outward: treads run counter-clockwise
      const double depth = -dot(normal, x - tread.x[k]);
      if (!(depth > ctx.config->contact_slop)) continue;
      if (existing >= 0 && !(depth > depth_[static_cast<std::size_t>(existing)]))
        continue;  // keep the deeper
      const double s = std::clamp(dot(x - tread.x[k], e) / e2, 0.0, 1.0);
      const Vec2 point = tread.x[k] * (1.0 - s) + tread.x[k1] * s;
      Contact c;
      c.particle = i;
      c.normal = normal;
      c.plane = dot(normal, tread.x[k]);
      c.surface_displacement = tread.motion[k] * (1.0 - s) + tread.motion[k1] * s;
      c.surface_velocity = c.surface_displacement * (1.0 / ctx.h);
      c.tire = static_cast<std::int32_t>(other);
      c.edge = k;
      c.point = point;
      // Stuck since an earlier substep: back to the point of the neighbour's tread where it stuck,
      // as for a surface (make_contact). Each substep's slip alone let a small tire resting on two
      // others in level 08's pile turn in place at 0.15 rad/s for ever, its contacts stuck.
      if (t.anchor_on[i] == Tire::anchor_code(-1, c.tire)) {
        const double u = t.friction_anchor[i].x;
        const auto ka = static_cast<std::uint32_t>(u);
        if (u >= 0.0 && ka < tread.n) {
          // The tread where its friction sees it: where it started the substep and its motion
          // since, less what its prediction took of its neighbours' pushes (TireNeighbours::capture).
          const auto held = [&](std::uint32_t j) {
            return tread.tire->particles.x_prev[j] + tread.motion[j];
          };
          const double sa = u - ka;
          c.anchor = held(ka) * (1.0 - sa) + held((ka + 1) % tread.n) * sa;
          c.anchored = within_reach(c.anchor, p.x_prev[i], c.surface_displacement);
        }
      }
      c.mu_static = c.mu_kinetic = mu;
      c.friction_active = mu > 0.0;
      c.stiffness_n = 1.0 / (rigid_alpha_tilde_ + tread.give(point, normal));
      c.give_t = tread.give(point, perp(normal));
      c.stiffness_t = 1.0 / (rigid_alpha_tilde_ + c.give_t);
      offer(c, depth);
    }
  }
}

bool GlobalSolver::solve_pass(const Tire& t) {
  const std::uint32_t n = t.n;
  const std::size_t size = CyclicBlockCholesky::kBlock * n;
  const Particles& p = t.particles;
  rows_.resize(base_rows_);  // the contacts' rows are made again below
  k_.reset(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    k_.diagonal(k) = base_diagonal_[k];
    k_.coupling(k) = base_coupling_[k];
  }
  std::copy(base_f_.begin(), base_f_.begin() + static_cast<std::ptrdiff_t>(size), f_.begin());
  // The free props' K_qq = diag(M, M, I) and f_q, and their columns of B, empty.
  const std::size_t nb = bodies_.size();
  for (Body& b : bodies_) {
    for (auto& row : b.kqq) std::fill(std::begin(row), std::end(row), 0.0);
    b.kqq[0][0] = b.kqq[1][1] = b.mass;
    b.kqq[2][2] = b.inertia;
    std::fill(std::begin(b.fq), std::end(b.fq), 0.0);
  }
  std::fill(yb_.begin(), yb_.begin() + static_cast<std::ptrdiff_t>(3 * nb * stride_), 0.0);
  // A constraint C = d·x − plane − a·q of stiffness k (a = 0 off a body): k d dᵀ into K and its
  // −k d C into f; on a body also −k d aᵀ into B, k a aᵀ into K_qq and k a C into f_q.
  const auto add_row = [&](const Contact& c, Vec2 d, double k, double force) {
    const std::uint32_t i = c.particle;
    const std::size_t dof = GlobalSolver::dof(i, n);
    add_outer(k_.diagonal(GlobalSolver::block(i, n)), GlobalSolver::offset(i, n), GlobalSolver::offset(i, n),
              outer(d, k));
    f_[dof] += d.x * force;
    f_[dof + 1] += d.y * force;
    if (c.body < 0) return;
    Body& b = bodies_[static_cast<std::size_t>(c.body)];
    const double a[3] = {d.x, d.y, cross(c.arm, d)};
    for (std::size_t r = 0; r < 3; ++r) {
      double* column = yb_.data() + (3 * static_cast<std::size_t>(c.body) + r) * stride_;
      column[dof] -= k * d.x * a[r];
      column[dof + 1] -= k * d.y * a[r];
      b.fq[r] -= force * a[r];
      for (std::size_t q = 0; q < 3; ++q) b.kqq[r][q] += k * a[r] * a[q];
    }
  };
  // Each active contact: its normal into K; its static friction while it holds, as a row while
  // there is room and it is not a free prop's, else into K.
  for (Contact& c : contacts_) {
    c.normal_in_k = c.normal_active;
    c.friction_in_k = false;
    c.row_n = c.row_t = -1;
    if (!c.normal_active) continue;
    const Vec2 x = p.x[c.particle];
    add_row(c, c.normal, c.stiffness_n, c.stiffness_n * (c.plane - dot(c.normal, x)));
    if (!c.friction_active) continue;
    const Vec2 tangent = perp(c.normal);
    const double target = -dot(tangent, slip(c, x, p));
    if (c.body < 0 && rows_.size() < base_rows_ + kMaxFrictionRows) {
      c.row_t = add_contact_row(t, c, tangent, target, c.stiffness_t);
    } else {
      add_row(c, tangent, c.stiffness_t, c.stiffness_t * target);
      c.friction_in_k = true;
    }
  }
  ++work_.factorisations;
  if (!k_.factor()) return false;
  // L⁻¹ f, the rows' y_r = L⁻¹ g_r (the areas' and the grab's from their gradients) and the bodies'
  // L⁻¹ B in forward sweeps.
  for (std::size_t r = 0; r < base_rows_; ++r) {
    const double* g = g_.data() + r * stride_;
    std::copy(g, g + size, y_.data() + r * stride_);
  }
  forward_rows(0, true);
  for (std::size_t j = 0; j < 3 * nb; j += CyclicBlockCholesky::kMaxRightHandSides) {
    double* columns[CyclicBlockCholesky::kMaxRightHandSides];
    const std::size_t count = std::min(CyclicBlockCholesky::kMaxRightHandSides, 3 * nb - j);
    for (std::size_t v = 0; v < count; ++v) columns[v] = yb_.data() + (j + v) * stride_;
    k_.forward(columns, count);
  }
  return solve_system(t);
}

std::int32_t GlobalSolver::add_contact_row(const Tire& t, const Contact& c, Vec2 d, double target,
                                           double stiffness) {
  // The roll's row has a place of its own: a tire without it has the room it always had.
  if (rows_.size() == kMaxRows - (rolling_row_ >= 0 ? 0 : 1)) return -1;
  const std::size_t r = rows_.size();
  double* y = y_.data() + r * stride_;
  std::fill(y, y + CyclicBlockCholesky::kBlock * t.n, 0.0);
  const std::size_t dof = GlobalSolver::dof(c.particle, t.n);
  y[dof] = d.x;
  y[dof + 1] = d.y;
  Row row;
  row.alpha_tilde = 1.0 / stiffness;
  row.b = target;
  const std::uint32_t block = GlobalSolver::block(c.particle, t.n);
  row.first = block == 0 ? t.n : block;  // block 0 is the chain's border, eliminated last
  rows_.push_back(row);
  return static_cast<std::int32_t>(r);
}

void GlobalSolver::forward_rows(std::size_t first, bool with_f) {
  constexpr std::size_t kSides = CyclicBlockCholesky::kMaxRightHandSides;
  std::size_t r = first;
  while (r < rows_.size() || with_f) {
    double* sides[kSides];
    std::size_t count = 0, start = k_.blocks();
    if (with_f) {
      sides[count++] = f_.data();
      start = 1;
      with_f = false;
    }
    for (; count < kSides && r < rows_.size(); ++r) {
      sides[count++] = y_.data() + r * stride_;
      start = std::min(start, rows_[r].first);
    }
    k_.forward(sides, count, start);
  }
}

bool GlobalSolver::solve_changes(const Tire& t) {
  const Particles& p = t.particles;
  const std::size_t first_new = rows_.size();
  for (Contact& c : contacts_) {
    const bool friction = c.normal_active && c.friction_active;
    if (c.normal_in_k) {
      if (!c.normal_active || c.friction_in_k != friction) return false;  // K itself changes
      if (c.row_t >= 0 && !friction) rows_[static_cast<std::size_t>(c.row_t)].live = false;
      continue;
    }
    if (!c.normal_active) {  // not in K and out: its rows too, if it had any
      if (c.row_n >= 0) rows_[static_cast<std::size_t>(c.row_n)].live = false;
      if (c.row_t >= 0) rows_[static_cast<std::size_t>(c.row_t)].live = false;
      continue;
    }
    if (c.body >= 0) return false;  // a free prop's contact is in its columns of B
    const Vec2 x = p.x[c.particle];
    const Vec2 tangent = perp(c.normal);
    if (c.row_n < 0 || !rows_[static_cast<std::size_t>(c.row_n)].live) {
      c.row_n = add_contact_row(t, c, c.normal, c.plane - dot(c.normal, x), c.stiffness_n);
      if (c.row_n < 0) return false;
    }
    if (friction && (c.row_t < 0 || !rows_[static_cast<std::size_t>(c.row_t)].live)) {
      c.row_t = add_contact_row(t, c, tangent, -dot(tangent, slip(c, x, p)), c.stiffness_t);
      if (c.row_t < 0) return false;
    } else if (!friction && c.row_t >= 0) {
      rows_[static_cast<std::size_t>(c.row_t)].live = false;
    }
  }
  forward_rows(first_new, false);
  ++work_.updates;
  return solve_system(t);
}

bool GlobalSolver::solve_system(const Tire& t) {
  const std::uint32_t n = t.n;
  const std::size_t size = CyclicBlockCholesky::kBlock * n;
  const Particles& p = t.particles;
  const std::size_t nb = bodies_.size();
  // The border system (header), at most kMaxUnknowns: by Cholesky when it is the rows' S = Yᵀ Y + α̃
  // alone (symmetric positive definite), else by elimination. Its unknowns: the live rows', then
  // the bodies'.
  std::size_t live[kMaxRows];
  std::size_t m = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r)
    if (rows_[r].live) live[m++] = r;
  const auto column = [&](std::size_t u) {  // unknown u's column of Y: a row's, then the bodies'
    return u < m ? y_.data() + live[u] * stride_ : yb_.data() + (u - m) * stride_;
  };
  const std::size_t unknowns = m + 3 * nb;
  double z[kMaxUnknowns] = {};
  for (std::size_t u = 0; u < m; ++u) rows_[live[u]].yf = dot_n(column(u), f_.data(), size);
  if (nb == 0) {
    double s[kMaxRows][kMaxRows] = {};
    for (std::size_t r = 0; r < m; ++r) {
      for (std::size_t q = 0; q <= r; ++q) s[r][q] = dot_n(column(r), column(q), size);
      s[r][r] += rows_[live[r]].alpha_tilde;
      z[r] = rows_[live[r]].b - rows_[live[r]].yf;
    }
    if (!cholesky(s, m)) return false;
    cholesky_solve(s, m, z);
  } else {
    for (std::size_t r = 0; r < unknowns; ++r) {
      const double* yr = column(r);
      for (std::size_t q = 0; q < unknowns; ++q) {
        const double yy = dot_n(yr, column(q), size);
        if (r < m)
          border_[r][q] = q < m ? yy + (q == r ? rows_[live[r]].alpha_tilde : 0.0) : -yy;
        else
          border_[r][q] = yy;
      }
      if (r < m) {
        border_[r][unknowns] = rows_[live[r]].b - rows_[live[r]].yf;
      } else {  // (K_qq − Y_Bᵀ Y_B) Δq + Y_Bᵀ Y_G μ = f_q − Y_Bᵀ L⁻¹ f
        const std::size_t j = (r - m) / 3, a = (r - m) % 3;
        for (std::size_t q = m; q < unknowns; ++q) border_[r][q] = -border_[r][q];
        for (std::size_t q = 0; q < 3; ++q) border_[r][m + 3 * j + q] += bodies_[j].kqq[a][q];
        border_[r][unknowns] = bodies_[j].fq[a] - dot_n(yr, f_.data(), size);
      }
    }
    if (!solve_border(unknowns)) return false;
    for (std::size_t u = 0; u < unknowns; ++u) z[u] = border_[u][unknowns];
  }
  for (std::size_t r = 0; r < m; ++r) rows_[live[r]].mu = z[r];
  for (std::size_t j = 0; j < nb; ++j)
    for (std::size_t a = 0; a < 3; ++a) bodies_[j].dq[a] = z[m + 3 * j + a];
  // Δx = L⁻ᵀ (L⁻¹ f + Y_G μ − Y_B Δq).
  std::copy(f_.begin(), f_.begin() + static_cast<std::ptrdiff_t>(size), dx_.begin());
  for (std::size_t u = 0; u < unknowns; ++u) {
    const double coefficient = u < m ? z[u] : -z[u];
    const double* y = column(u);
    for (std::size_t k = 0; k < size; ++k) dx_[k] += coefficient * y[k];
  }
  k_.backward(dx_.data());
  // The contacts' multipliers: a row's own, or at the new positions μ = −k C(x + Δx, Δq) for one
  // in K.
  const auto row_mu = [&](std::int32_t r) { return rows_[static_cast<std::size_t>(r)].mu; };
  for (Contact& c : contacts_) {
    c.mu_n = c.mu_t = 0.0;
    if (!c.normal_active) continue;
    const std::uint32_t i = c.particle;
    const Vec2 x = p.x[i] + at(dx_.data(), GlobalSolver::dof(i, n));
    const Vec2 tangent = perp(c.normal);
    double moved_n = 0.0, moved_t = 0.0;  // the prop's point along n and t, when it is a body
    if (c.body >= 0) {
      const Body& b = bodies_[static_cast<std::size_t>(c.body)];
      moved_n = along(b, c.normal, c.arm);
      moved_t = along(b, tangent, c.arm);
    }
    c.mu_n = c.normal_in_k ? c.stiffness_n * (c.plane + moved_n - dot(c.normal, x)) : row_mu(c.row_n);
    if (!c.friction_active) continue;
    c.mu_t = c.friction_in_k ? -c.stiffness_t * (dot(tangent, slip(c, x, p)) - moved_t) : row_mu(c.row_t);
  }
  return true;
}

bool GlobalSolver::update_active_set(const Tire& t, const SubstepContext& ctx) {
  bool changed = false;
  if (rolling_row_ >= 0 && rows_[static_cast<std::size_t>(rolling_row_)].live) {
    // Rolling resistance holds the roll up to C_rr·N·R (Coulomb's law for the roll): past it, the
    // row lets go and the velocity pass's moment slows the turn instead.
    double normal = 0.0;
    for (const Contact& c : contacts_)
      if (c.normal_active && c.mu_n > 0.0) normal += c.mu_n;
    // Its multiplier is the moment that holds the roll times h² (kg m²), a contact's μ_n its normal
    // force times h² (kg m): the bound C_rr N R h² is C_rr R Σ μ_n.
    Row& roll = rows_[static_cast<std::size_t>(rolling_row_)];
    if (std::abs(roll.mu) > t.spec.rolling_resistance * t.spec.outer_radius * normal) {
      roll.live = false;
      changed = true;
    }
  }
  for (Contact& c : contacts_) {
    if (c.normal_active) {
      if (c.mu_n < 0.0) {  // the surface would pull: let go
        c.normal_active = c.friction_active = false;
        changed = true;
      } else if (c.friction_active && std::abs(c.mu_t) > c.mu_static * c.mu_n) {  // Coulomb: slip
        c.friction_active = false;
        changed = true;
      }
    } else {  // released: back in if the step would push it into its surface
      const Vec2 x = t.particles.x[c.particle] + at(dx_.data(), GlobalSolver::dof(c.particle, t.n));
      const double moved =
          c.body >= 0 ? along(bodies_[static_cast<std::size_t>(c.body)], c.normal, c.arm) : 0.0;
      if (c.plane + moved - dot(c.normal, x) > ctx.config->contact_slop) {
        c.normal_active = true;
        changed = true;
      }
    }
  }
  return find_contacts(t, ctx, dx_.data()) || changed;
}

void GlobalSolver::solve(Tire& t, const SubstepContext& ctx) {
  TIRE_ASSERT(t.n <= segments_, "a global solver too small for the tire: reserve() it first");
  const std::uint32_t n = t.n;
  const double gamma = t.spec.material_damping / ctx.h;  // γ = α̃β̃/h with β = τ/α (XPBD eq. 26)
  work_ = {};
  work_.solves = 1;
  rows_.clear();
  contacts_.clear();
  bodies_.clear();
  std::fill(contact_of_.begin(), contact_of_.begin() + 2 * static_cast<std::ptrdiff_t>(n), -1);
  rigid_alpha_tilde_ = ctx.config->rigid_compliance / (ctx.h * ctx.h);
  assemble(t, ctx, gamma);
  if (load_ != nullptr) {
    for (std::size_t k = 0; k < CyclicBlockCholesky::kBlock * n; ++k) base_f_[k] += load_[k];
    load_ = nullptr;
  }
  add_ring_area_row(t, ctx, false, gamma);
  add_ring_area_row(t, ctx, true, gamma);
  if (t.grabbed) {
    const Vec2 d = t.particles.x[t.grab_particle] - t.grab_target;
    const double len = length(d);
    if (len > 0.0) {  // C = |x − target| with the grab's compliance, undamped
      double* g = gradient_of(rows_.size());
      std::fill(g, g + 4 * static_cast<std::ptrdiff_t>(n), 0.0);
      const std::size_t k = GlobalSolver::dof(t.grab_particle, n);
      g[k] = d.x / len;
      g[k + 1] = d.y / len;
      Row row;
      row.alpha_tilde = t.grab_compliance / (ctx.h * ctx.h);
      row.b = -len;
      rows_.push_back(row);
    }
  }
  // Only for a tire that touches no other tire this tick: an island moves its tires through their
  // responses to its contacts, which would hold the roll there with no bound, and block
  // Gauss–Seidel hands a tire pushes after its solve, which the bound never sees. A pile's tires keep
  // the velocity pass's rolling resistance alone (docs/at-rest.md, "Still open").
  rolling_row_ = -1;
  if (ctx.config->rolling_hold && t.rolling_held && t.spec.rolling_resistance > 0.0 && !t.grabbed &&
      t.control.steer == 0.0 && !t.driven && t.wheel < 0) {
    const bool alone =
        ctx.island == nullptr &&
        (ctx.neighbours == nullptr || ctx.neighbours->neighbours(ctx.neighbours->index_of(t)).empty());
    if (alone) add_rolling_row(t);
  }
  base_rows_ = rows_.size();
  // Contacts held at the end of the substep's previous iteration stay in (their plane and whether
  // they stuck), so a resting tire does not lose its support between iterations.
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& rec = t.contacts[i];
    if (!rec.active || rec.tire >= 0) return;  // a neighbour's tread moves: found again below
    const ContactPair pair{i, 0, rec.prop >= 0, rec.mu_static, rec.mu_kinetic};
    Contact c = make_contact(t, ctx, i, rec.normal, rec.plane, pair, rec.prop, rec.surface_velocity);
    c.friction_active = rec.stuck;
    contact_of_[i] = static_cast<std::int32_t>(contacts_.size());
    contacts_.push_back(c);
  });
  find_contacts(t, ctx, nullptr);
  // Active-set passes (each a factorisation), until nothing changes or the passes run out; the
  // last pass's changes are solved once more, so Δx always matches the contacts written back.
  // A pass whose changes K can take as rows solves on the factor it has (solve_changes).
  // A solve that is not finite (a NaN put in from outside) leaves the tire as it was and is counted:
  // World reports it, and its divergence guard resets the tire.
  const auto failed = [&] {
    ++work_.failed_solves;
    t.global_work += work_;
  };
  const int passes = std::max(1, ctx.config->contact_passes);
  if (!solve_pass(t)) return failed();
  for (int pass = 1; pass <= passes && update_active_set(t, ctx); ++pass)
    if (!(ctx.config->reuse_factor && solve_changes(t)) && !solve_pass(t)) return failed();
  t.newton_turn = std::max(t.newton_turn, largest_turn(t, dx_.data()));
  t.global_work += work_;
  for (std::uint32_t i = 0; i < 2 * n; ++i) t.particles.x[i] += at(dx_.data(), GlobalSolver::dof(i, n));
  write_back(t, ctx);
}

bool GlobalSolver::prepare_solve_response() {
  if (!bodies_.empty()) return false;
  response_from_solve_ = true;
  const std::size_t size = k_.size();
  std::size_t m = 0;
  for (std::size_t r = 0; r < rows_.size(); ++r)
    if (rows_[r].live) response_live_[m++] = r;
  response_rows_ = m;
  auto& s = response_s_;
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t q = 0; q <= r; ++q)
      s[r][q] = dot_n(y_.data() + response_live_[r] * stride_, y_.data() + response_live_[q] * stride_, size);
    s[r][r] += rows_[response_live_[r]].alpha_tilde;
  }
  return cholesky(s, m);
}

bool GlobalSolver::prepare_response(bool hold_fixed_friction) {
  if (!bodies_.empty()) return false;
  response_from_solve_ = false;
  const std::uint32_t n = static_cast<std::uint32_t>(k_.size() / CyclicBlockCholesky::kBlock);
  const std::size_t size = k_.size();
  // K₀: the base K (mass and links), the normals of the contacts held, and the static frictions
  // of those with dynamic props (their give in their stiffness), as solve_pass puts them in K.
  k0_.reset(n);
  for (std::uint32_t k = 0; k < n; ++k) {
    k0_.diagonal(k) = base_diagonal_[k];
    k0_.coupling(k) = base_coupling_[k];
  }
  for (const Contact& c : contacts_) {
    if (!c.normal_active) continue;
    Block4& block = k0_.diagonal(GlobalSolver::block(c.particle, n));
    const std::size_t o = GlobalSolver::offset(c.particle, n);
    add_outer(block, o, o, outer(c.normal, c.stiffness_n));
    if (c.friction_active && (hold_fixed_friction || !c.fixed))
      add_outer(block, o, o, outer(perp(c.normal), c.stiffness_t));
  }
  if (!k0_.factor()) return false;
  std::size_t m = 0;
  for (std::size_t r = 0; r < base_rows_; ++r) {
    if (!rows_[r].live) continue;
    double* y = y0_.data() + m * stride_;
    std::copy(g_.data() + r * stride_, g_.data() + r * stride_ + size, y);
    k0_.forward(y);
    response_live_[m++] = r;
  }
  response_rows_ = m;
  auto& s = response_s_;
  for (std::size_t r = 0; r < m; ++r) {
    for (std::size_t q = 0; q <= r; ++q)
      s[r][q] = dot_n(y0_.data() + r * stride_, y0_.data() + q * stride_, size);
    s[r][r] += rows_[response_live_[r]].alpha_tilde;
  }
  return cholesky(s, m);
}

void GlobalSolver::respond(double* const* rs, std::size_t count) const {
  respond_forward(rs, count);
  (response_from_solve_ ? k_ : k0_).backward(rs, count);
}

void GlobalSolver::respond_backward(double* r) const { (response_from_solve_ ? k_ : k0_).backward(r); }

void GlobalSolver::respond_forward(double* const* rs, std::size_t count, Gram* gram) const {
  const CyclicBlockCholesky& k = response_from_solve_ ? k_ : k0_;
  const std::size_t size = k.size();
  const std::size_t m = response_rows_;
  const auto column = [&](std::size_t q) {  // Y's column q: L⁻¹ g of the q-th live row
    return response_from_solve_ ? y_.data() + response_live_[q] * stride_ : y0_.data() + q * stride_;
  };
  // u = L₀⁻¹ r, from the first block after block 0 where a load is not zero (a contact's load is at
  // one to three particles: the sweep skips the blocks before it, which stay zero).
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  const std::size_t blocks = k.blocks();
  std::size_t first = blocks;
  for (std::size_t v = 0; v < count; ++v) {
    const double* r = rs[v];
    std::size_t f = 1;
    while (f < first && r[B * f] == 0.0 && r[B * f + 1] == 0.0 && r[B * f + 2] == 0.0 && r[B * f + 3] == 0.0)
      ++f;
    first = std::min(first, f);
  }
  k.forward(rs, count, first);
  // δμ = S⁻¹ (−Y₀ᵀ u) for each load, S = Y₀ᵀ Y₀ + α̃ (prepare_response's factor).
  constexpr std::size_t R = CyclicBlockCholesky::kMaxRightHandSides;
  double yu[R][kMaxRows] = {};
  double z[R][kMaxRows] = {};
  for (std::size_t v = 0; v < count; ++v) {
    for (std::size_t q = 0; q < m; ++q) {
      yu[v][q] = dot_n(column(q), rs[v], size);
      z[v][q] = -yu[v][q];
    }
    cholesky_solve(response_s_, m, z[v]);
  }
  if (gram)
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = 0; j <= i; ++j) {
        double g = dot_n(rs[i], rs[j], size);
        for (std::size_t q = 0; q < m; ++q) g += yu[i][q] * z[j][q];
        (*gram)[i][j] = (*gram)[j][i] = g;
      }
  for (std::size_t v = 0; v < count; ++v) {
    double* r = rs[v];
    for (std::size_t q = 0; q < m; ++q) {
      const double* y = column(q);
      for (std::size_t i = 0; i < size; ++i) r[i] += z[v][q] * y[i];
    }
  }
}

double GlobalSolver::largest_turn(const Tire& t, const double* dx) const {
  const Particles& p = t.particles;
  // The least cos θ between a constraint's d = x_b − x_a before the step and e = d + Δd after it,
  // kept as the fraction (d·e)|d·e| / (|d|²|e|²) = ±cos²θ, compared without dividing.
  double num = 1.0, den = 1.0;
  for (const Link& c : links_) {
    const Vec2 d = p.x[c.b] - p.x[c.a];
    const Vec2 e = d + at(dx, c.dof_b) - at(dx, c.dof_a);
    const double de = dot(d, e), lengths2 = length_squared(d) * length_squared(e);
    if (lengths2 > 0.0 && de * std::abs(de) * den < num * lengths2) {
      num = de * std::abs(de);
      den = lengths2;
    }
  }
  const double cos2 = std::clamp(num / den, -1.0, 1.0);
  const double c = std::copysign(std::sqrt(std::abs(cos2)), cos2);
  return tire::atan2(std::sqrt(1.0 - c * c), c);  // tire/math/trig.h: the same bits everywhere
}

// The contact records, as the velocity pass and the rest of the engine read them (λ as distances,
// see contact.h), and the impulses owed to dynamic props: the change of this iteration's total
// multipliers from the last iteration's, so that a substep of several iterations owes the total.
void GlobalSolver::write_back(Tire& t, const SubstepContext& ctx) {
  const double t_end = ctx.time + ctx.h;
  const auto owe = [&](const ContactRecord& rec, std::uint32_t i, double d_lambda_n, double d_lambda_t) {
    if (rec.prop < 0 || (d_lambda_n == 0.0 && d_lambda_t == 0.0)) return;
    if (!ctx.rigid->props()[static_cast<std::size_t>(rec.prop)].is_dynamic()) return;
    const double m = 1.0 / t.particles.w[i];  // λ as a distance is w μ: the impulse is μ/h
    const Vec2 impulse = (rec.normal * d_lambda_n + perp(rec.normal) * d_lambda_t) * (-m / ctx.h);
    t.prop_impulses.push_back(
        {static_cast<std::uint32_t>(rec.prop), impulse, t.particles.x[i], t_end, ctx.time});
  };
  // Records of the last iteration that this one no longer holds: give back what they owed.
  t.for_each_contact([&](std::uint32_t i) {
    ContactRecord& rec = t.contacts[i];
    const std::int32_t k = contact_of_[i];
    if (rec.active && (k < 0 || !contacts_[static_cast<std::size_t>(k)].normal_active)) {
      owe(rec, i, -rec.lambda_n, -rec.lambda_t);
      rec = ContactRecord{};
    }
  });
  for (const Contact& c : contacts_) {
    if (!c.normal_active) continue;
    const double w = t.particles.w[c.particle];
    ContactRecord& rec = t.touch_contact(c.particle);
    const ContactRecord before = rec.active ? rec : ContactRecord{};
    rec.normal = c.normal;
    rec.surface_velocity = c.surface_velocity;
    rec.lambda_n = w * c.mu_n;
    rec.lambda_t = w * c.mu_t;
    rec.mu_static = c.mu_static;
    rec.mu_kinetic = c.mu_kinetic;
    rec.prop = c.prop;
    rec.active = true;
    rec.stuck = c.friction_active;
    rec.plane = c.plane;
    rec.tire = c.tire;
    rec.other_give_t = c.give_t;
    if (c.tire >= 0) {
      // The neighbour's edge takes −μ: the whole of this iteration's, as its plane was taken where
      // the edge stood after the last one's.
      const double g = ctx.config->ground_normal_y;
      const Vec2 push = c.normal * c.mu_n + perp(c.normal) * c.mu_t;
      ctx.neighbours->reactions(ctx.neighbours->index_of(t))
          .push_back({static_cast<std::uint32_t>(c.tire), c.edge, c.point, push, c.normal.y <= -g});
      if (c.normal.y >= g) t.on_tire[c.particle] = 1;  // resting on the neighbour
    }
    owe(rec, c.particle, rec.lambda_n - before.lambda_n, rec.lambda_t - before.lambda_t);
    // A static friction that holds keeps its anchor, or lays one where the particle is now, in the
    // surface's frame (the world's for an obstacle).
    std::int32_t& anchored = t.anchor_on[c.particle];
    const Vec2 x = t.particles.x[c.particle];
    if (!c.friction_active) {
      anchored = Tire::kNoAnchor;
    } else if (anchored != Tire::anchor_code(c.prop, c.tire) || !c.anchored) {
      if (c.tire >= 0) {  // the point of the edge as captured nearest the particle
        const TreadView tread = ctx.neighbours->tread(static_cast<std::uint32_t>(c.tire));
        const Vec2 e = tread.x[(c.edge + 1) % tread.n] - tread.x[c.edge];
        const double e2 = length_squared(e);
        const double s = e2 > 0.0 ? std::clamp(dot(x - tread.x[c.edge], e) / e2, 0.0, 1.0) : 0.0;
        t.friction_anchor[c.particle] = {c.edge + s, 0.0};
      } else {
        t.friction_anchor[c.particle] =
            c.prop >= 0 ? ctx.rigid->props()[static_cast<std::size_t>(c.prop)].pose_at(t_end).to_local(x) : x;
      }
      anchored = Tire::anchor_code(c.prop, c.tire);
    }
  }
}

void GlobalSolverPool::reserve(unsigned slots, std::uint32_t segments) {
  if (slots > solvers_.size()) {
    std::vector<std::unique_ptr<GlobalSolver>> grown(slots);
    for (std::size_t k = 0; k < solvers_.size(); ++k) grown[k] = std::move(solvers_[k]);
    for (std::size_t k = solvers_.size(); k < slots; ++k) grown[k] = std::make_unique<GlobalSolver>();
    solvers_ = std::move(grown);
    busy_ = std::make_unique<std::atomic<bool>[]>(slots);
    for (std::size_t k = 0; k < slots; ++k) busy_[k].store(false);
  }
  for (auto& s : solvers_) s->reserve(segments);
}

GlobalSolverPool::Lease GlobalSolverPool::lend() {
  // reserve() gave one solver to each thread that may solve at once, so one is always free; none
  // free is a caller solving on more threads than it reserved for, stopped here, not spun on.
  for (std::size_t k = 0; k < solvers_.size(); ++k) {
    bool expected = false;
    if (busy_[k].compare_exchange_strong(expected, true, std::memory_order_acquire)) return Lease(*this, k);
  }
  std::fprintf(stderr, "tire: GlobalSolverPool::lend: all %zu solvers are in use (reserve one per thread)\n",
               solvers_.size());
  std::abort();
}

}  // namespace tire
