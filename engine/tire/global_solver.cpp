#include "tire/tire/global_solver.h"

#include <algorithm>
#include <cmath>

#include "tire/math/check.h"
#include "tire/tire/tire_solver.h"
#include "tire/xpbd/contact.h"

namespace tire {

namespace {

// The unknowns, block by block: block i holds tread particle i (x, y) then rim particle i (x, y),
// so every constraint of the tire couples a block to itself or to a neighbouring block.
std::uint32_t block_of(std::uint32_t particle, std::uint32_t n) { return particle < n ? particle : particle - n; }
std::size_t offset_of(std::uint32_t particle, std::uint32_t n) { return particle < n ? 0 : 2; }
std::size_t dof_of(std::uint32_t particle, std::uint32_t n) {
  return CyclicBlockCholesky::kBlock * block_of(particle, n) + offset_of(particle, n);
}

// m[ro.., co..] += s n nᵀ: a 2×2 outer product into a 4×4 block, at particle offsets ro and co.
void add_outer(Block4& m, std::size_t ro, std::size_t co, Vec2 n, double s) {
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  m[ro * B + co] += s * n.x * n.x;
  m[ro * B + co + 1] += s * n.x * n.y;
  m[(ro + 1) * B + co] += s * n.y * n.x;
  m[(ro + 1) * B + co + 1] += s * n.y * n.y;
}

double dot_n(const double* a, const double* b, std::size_t n) {
  double s = 0.0;
  for (std::size_t i = 0; i < n; ++i) s += a[i] * b[i];
  return s;
}

Vec2 at(const double* v, std::size_t dof) { return {v[dof], v[dof + 1]}; }

}  // namespace

void GlobalSolver::reserve(std::uint32_t segments) {
  if (segments <= segments_) return;
  segments_ = segments;
  max_rows_ = 3 + 2 * kMaxContacts;
  stride_ = CyclicBlockCholesky::kBlock * segments;
  k_.reserve(segments);
  f_.assign(stride_, 0.0);
  dx_.assign(stride_, 0.0);
  work_.assign(stride_, 0.0);
  rows_.reserve(max_rows_);
  y_.assign(max_rows_ * stride_, 0.0);
  gram_.assign(std::size_t{max_rows_} * max_rows_, 0.0);
  s_.assign(std::size_t{max_rows_} * max_rows_, 0.0);
  rhs_.assign(max_rows_, 0.0);
  active_.reserve(max_rows_);
  contacts_.reserve(kMaxContacts);
  depth_.assign(kMaxContacts, 0.0);
  contact_of_.assign(2 * std::size_t{segments}, -1);
  gradient_.assign(segments, Vec2{});
}

// K = M + (1 + γ) Jᵀ α̃⁻¹ J and f = −M (x − x̃) − Jᵀ α̃⁻¹ (C + γ J (x − xₙ)) over the distance
// constraints (XPBD eq. 9–10 and 26 in the primal form, see the header); then f ← L⁻¹ f.
void GlobalSolver::assemble(const Tire& t, const SubstepContext& ctx, double gamma) {
  const std::uint32_t n = t.n;
  const Particles& p = t.particles;
  const double h = ctx.h;
  constexpr std::size_t B = CyclicBlockCholesky::kBlock;
  k_.reset(n);
  for (std::uint32_t i = 0; i < 2 * n; ++i) {
    TIRE_ASSERT(p.w[i] > 0.0, "the global method needs every particle of a tire to have a finite mass");
    const double m = 1.0 / p.w[i];
    const std::size_t o = offset_of(i, n);
    Block4& d = k_.diagonal(block_of(i, n));
    d[o * B + o] += m;
    d[(o + 1) * B + o + 1] += m;
    const Vec2 predicted = p.x_prev[i] + p.v[i] * h;  // x̃ (predict_positions made x exactly this)
    const Vec2 r = (p.x[i] - predicted) * -m;
    const std::size_t k = dof_of(i, n);
    f_[k] = r.x;
    f_[k + 1] = r.y;
  }
  const double min_compliance = ctx.config->global_min_compliance;
  for (const DistanceConstraint& c : t.distance.constraints()) {
    const Vec2 d = p.x[c.b] - p.x[c.a];
    const double len = length(d);
    if (!(len > 0.0)) continue;  // coincident particles: no gradient (as in the Gauss–Seidel kernel)
    const Vec2 nrm = d / len;    // ∇_b C = n = −∇_a C
    const double inv_alpha_tilde = h * h / std::max(c.compliance, min_compliance);
    const double rate = dot(nrm, (p.x[c.b] - p.x_prev[c.b]) - (p.x[c.a] - p.x_prev[c.a]));  // ∇C·(x − xₙ)
    const double e = (len - c.rest_length + gamma * rate) * inv_alpha_tilde;
    const std::size_t ka = dof_of(c.a, n), kb = dof_of(c.b, n);
    f_[ka] += nrm.x * e;
    f_[ka + 1] += nrm.y * e;
    f_[kb] -= nrm.x * e;
    f_[kb + 1] -= nrm.y * e;
    const double s = (1.0 + gamma) * inv_alpha_tilde;
    const std::uint32_t ba = block_of(c.a, n), bb = block_of(c.b, n);
    const std::size_t oa = offset_of(c.a, n), ob = offset_of(c.b, n);
    add_outer(k_.diagonal(ba), oa, oa, nrm, s);
    add_outer(k_.diagonal(bb), ob, ob, nrm, s);
    if (ba == bb) {
      add_outer(k_.diagonal(ba), oa, ob, nrm, -s);
      add_outer(k_.diagonal(ba), ob, oa, nrm, -s);
    } else if (bb == (ba + 1) % n) {
      add_outer(k_.coupling(ba), ob, oa, nrm, -s);  // block row bb, column ba
    } else {
      TIRE_ASSERT(ba == (bb + 1) % n, "a tire constraint joins segments that are not neighbours");
      add_outer(k_.coupling(bb), oa, ob, nrm, -s);
    }
  }
}

std::uint32_t GlobalSolver::add_row(const Tire& t, const Row& row, const double* gradient) {
  const std::size_t size = CyclicBlockCholesky::kBlock * t.n;
  const auto r = static_cast<std::uint32_t>(rows_.size());
  rows_.push_back(row);
  double* y = y_.data() + r * stride_;
  std::copy(gradient, gradient + size, y);
  k_.forward(y);  // y = L⁻¹ g
  rows_[r].yf = dot_n(y, f_.data(), size);
  for (std::uint32_t s = 0; s <= r; ++s) {
    const double g = dot_n(y, y_.data() + s * stride_, size);
    gram_[r * max_rows_ + s] = g;
    gram_[s * max_rows_ + r] = g;
  }
  ++counts_.rows;
  return r;
}

// An area constraint C = A(x) − p A₀ with compliance α, damped as the distance constraints are:
// (g K⁻¹ gᵀ + α̃/(1 + γ)) μ = −(C + γ g·(x − xₙ))/(1 + γ) − g K⁻¹ f (XPBD eq. 26 divided by 1 + γ).
void GlobalSolver::add_ring_area_row(const Tire& t, const SubstepContext& ctx, RowKind kind, double gamma) {
  const AreaConstraint& c = kind == RowKind::tread_area ? t.area_constraint : t.rim_area_constraint;
  if (c.count < 3) return;  // no polygon (tests build chains from a tire's particles)
  const Particles& p = t.particles;
  polygon_area_gradient(p.x.data() + c.first, c.count, gradient_.data());
  const std::size_t size = CyclicBlockCholesky::kBlock * t.n;
  std::fill(work_.begin(), work_.begin() + static_cast<std::ptrdiff_t>(size), 0.0);
  double rate = 0.0;
  for (std::uint32_t k = 0; k < c.count; ++k) {
    const std::uint32_t i = c.first + k;
    const std::size_t d = dof_of(i, t.n);
    work_[d] = gradient_[k].x;
    work_[d + 1] = gradient_[k].y;
    rate += dot(gradient_[k], p.x[i] - p.x_prev[i]);
  }
  const double value = polygon_area(p.x.data() + c.first, c.count) - c.pressure * c.rest_area;
  Row row(kind);
  row.alpha_tilde = c.compliance / (ctx.h * ctx.h) / (1.0 + gamma);
  row.b = -(value + gamma * rate) / (1.0 + gamma);
  add_row(t, row, work_.data());
}

void GlobalSolver::add_contact_rows(const Tire& t, std::int32_t index, bool friction) {
  Contact& c = contacts_[static_cast<std::size_t>(index)];
  const std::uint32_t i = c.particle;
  const std::size_t size = CyclicBlockCholesky::kBlock * t.n;
  const std::size_t d = dof_of(i, t.n);
  const Vec2 x = t.particles.x[i];
  std::fill(work_.begin(), work_.begin() + static_cast<std::ptrdiff_t>(size), 0.0);
  // Normal: C = n·x − plane ≥ 0 with α = 0 (Müller 2020 eq. 24), so n·Δx = −C.
  Row normal(RowKind::normal);
  normal.particle = i;
  normal.contact = index;
  normal.direction = c.normal;
  normal.b = c.plane - dot(c.normal, x);
  work_[d] = c.normal.x;
  work_[d + 1] = c.normal.y;
  c.normal_row = static_cast<std::int32_t>(add_row(t, normal, work_.data()));
  if (!friction) return;
  // Static friction: no tangential motion relative to the surface over the substep (Müller 2020
  // eq. 27–28 as an equality), t·(x + Δx − xₙ − surface displacement) = 0.
  const Vec2 tangent = perp(c.normal);
  Row row(RowKind::friction);
  row.particle = i;
  row.contact = index;
  row.direction = tangent;
  row.b = -dot(tangent, x - t.particles.x_prev[i] - c.surface_displacement);
  work_[d] = tangent.x;
  work_[d + 1] = tangent.y;
  c.friction_row = static_cast<std::int32_t>(add_row(t, row, work_.data()));
}

bool GlobalSolver::find_contacts(const Tire& t, const SubstepContext& ctx, const double* dx) {
  const Particles& p = t.particles;
  const RigidWorld& rigid = *ctx.rigid;
  const double t_end = ctx.time + ctx.h;
  const std::size_t first_new = contacts_.size();
  std::vector<double>& depth = depth_;
  for (const ContactPair& pair : t.pairs) {
    const std::uint32_t i = pair.particle;
    const std::int32_t existing = contact_of_[i];
    if (existing >= 0 && static_cast<std::size_t>(existing) < first_new) continue;
    Vec2 x = p.x[i];
    if (dx) x += at(dx, dof_of(i, t.n));
    std::optional<SurfaceContact> hit;
    Contact c;
    c.particle = i;
    c.mu_static = pair.mu_static;
    c.mu_kinetic = pair.mu_kinetic;
    if (!pair.is_prop) {
      hit = swept_box_contact(p.x_prev[i], x, rigid.obstacles()[pair.index].box);
      if (hit) c.normal = hit->normal;
    } else {
      const PropFrame& frame = t.prop_frames[pair.index];
      const Prop& prop = rigid.props()[frame.prop];
      hit = local_contact(prop.geometry, frame.start.to_local(p.x_prev[i]), frame.end.to_local(x));
      if (hit) {
        c.normal = frame.end.rotate(hit->normal);
        c.prop = static_cast<std::int32_t>(frame.prop);
        c.surface_velocity = prop.point_velocity(x, t_end);
        c.surface_displacement = c.surface_velocity * ctx.h;
      }
    }
    if (!hit || !(hit->depth > ctx.config->contact_slop)) continue;
    c.plane = dot(c.normal, x) + hit->depth;
    if (existing >= 0) {  // found by an earlier pair in this search: keep the deeper
      if (hit->depth > depth[static_cast<std::size_t>(existing)]) {
        contacts_[static_cast<std::size_t>(existing)] = c;
        depth[static_cast<std::size_t>(existing)] = hit->depth;
      }
      continue;
    }
    if (contacts_.size() >= kMaxContacts) continue;
    contact_of_[i] = static_cast<std::int32_t>(contacts_.size());
    depth[contacts_.size()] = hit->depth;
    contacts_.push_back(c);
  }
  for (std::size_t k = first_new; k < contacts_.size(); ++k) {
    Contact& c = contacts_[k];
    if (c.prop >= 0) {
      const Prop& prop = rigid.props()[static_cast<std::size_t>(c.prop)];
      if (prop.is_dynamic()) {
        // Rounding can take 1 − (n·s)² a few 1e-9 below zero (see resolve_contact): clamp.
        c.arm = t.particles.x[c.particle] - prop.center_at(t_end);
        c.mobility_n = std::max(0.0, prop.mobility(-c.normal));
        c.mobility_t = std::max(0.0, std::min(prop.mobility(perp(c.normal)), prop.mobility(-perp(c.normal))));
        c.inverse_mass = prop.inverse_mass;
        c.inverse_inertia = prop.inverse_inertia;
      }
    }
    if (rows_.size() + 2 <= max_rows_) add_contact_rows(t, static_cast<std::int32_t>(k), c.mu_static > 0.0);
  }
  return contacts_.size() > first_new;
}

// What a dynamic prop gives way along two rows on it: g_aᵀ W_prop g_b with W_prop its generalised
// inverse mass at the two contact points (Müller 2020 eq. 2–3), each side scaled by the square root
// of its mobility (0 when the prop is pushed into what holds it up).
double GlobalSolver::row_coupling(const Row& a, const Row& b) const {
  if (a.contact < 0 || b.contact < 0) return 0.0;
  const Contact& ca = contacts_[static_cast<std::size_t>(a.contact)];
  const Contact& cb = contacts_[static_cast<std::size_t>(b.contact)];
  if (ca.prop < 0 || ca.prop != cb.prop || ca.inverse_mass <= 0.0) return 0.0;
  const double sa = std::sqrt(a.kind == RowKind::normal ? ca.mobility_n : ca.mobility_t);
  const double sb = std::sqrt(b.kind == RowKind::normal ? cb.mobility_n : cb.mobility_t);
  return sa * sb *
         (ca.inverse_mass * dot(a.direction, b.direction) +
          ca.inverse_inertia * cross(ca.arm, a.direction) * cross(cb.arm, b.direction));
}

// (G K⁻¹ Gᵀ + α̃ + D) μ = b − G K⁻¹ f over the active rows, by a dense Cholesky (a handful of rows;
// G K⁻¹ Gᵀ is the Gram matrix of the columns L⁻¹ gᵀ). A row whose pivot vanishes (it repeats
// others) is dropped and the rest solved again. Then Δx = L⁻ᵀ (L⁻¹ f + Σ μ_r L⁻¹ g_r).
void GlobalSolver::solve_active(const Tire& t) {
  const std::size_t size = CyclicBlockCholesky::kBlock * t.n;
  for (;;) {
    active_.clear();
    for (std::uint32_t r = 0; r < rows_.size(); ++r) {
      rows_[r].mu = 0.0;
      if (rows_[r].active) active_.push_back(r);
    }
    const std::size_t m = active_.size();
    bool singular = false;
    for (std::size_t a = 0; a < m && !singular; ++a) {
      const Row& ra = rows_[active_[a]];
      for (std::size_t b = 0; b <= a; ++b) {
        const Row& rb = rows_[active_[b]];
        double s = gram_[active_[a] * max_rows_ + active_[b]] + row_coupling(ra, rb);
        if (a == b) s += ra.alpha_tilde;
        s_[a * m + b] = s;
      }
      rhs_[a] = ra.b - ra.yf;
      // Row a of the Cholesky factor, in place (rows above are done).
      for (std::size_t b = 0; b <= a; ++b) {
        double s = s_[a * m + b];
        for (std::size_t k = 0; k < b; ++k) s -= s_[a * m + k] * s_[b * m + k];
        if (b < a) {
          s_[a * m + b] = s / s_[b * m + b];
        } else {
          const double scale = gram_[active_[a] * max_rows_ + active_[a]] + ra.alpha_tilde;
          if (!(s > 1e-12 * scale)) {
            rows_[active_[a]].active = false;  // linearly dependent on the rows before it
            singular = true;
            break;
          }
          s_[a * m + a] = std::sqrt(s);
        }
      }
    }
    if (singular) continue;
    for (std::size_t a = 0; a < m; ++a) {  // forward
      double s = rhs_[a];
      for (std::size_t k = 0; k < a; ++k) s -= s_[a * m + k] * rhs_[k];
      rhs_[a] = s / s_[a * m + a];
    }
    for (std::size_t a = m; a-- > 0;) {  // backward
      double s = rhs_[a];
      for (std::size_t k = a + 1; k < m; ++k) s -= s_[k * m + a] * rhs_[k];
      rhs_[a] = s / s_[a * m + a];
    }
    std::copy(f_.begin(), f_.begin() + static_cast<std::ptrdiff_t>(size), dx_.begin());
    for (std::size_t a = 0; a < m; ++a) {
      rows_[active_[a]].mu = rhs_[a];
      const double* y = y_.data() + active_[a] * stride_;
      for (std::size_t k = 0; k < size; ++k) dx_[k] += rhs_[a] * y[k];
    }
    k_.backward(dx_.data());
    return;
  }
}

void GlobalSolver::solve(Tire& t, const SubstepContext& ctx) {
  TIRE_ASSERT(t.n <= segments_, "a global solver too small for the tire: reserve() it first");
  const std::uint32_t n = t.n;
  const double gamma = t.spec.material_damping / ctx.h;  // γ = α̃β̃/h with β = τ/α (XPBD eq. 26)
  counts_ = {};
  rows_.clear();
  contacts_.clear();
  std::fill(contact_of_.begin(), contact_of_.begin() + 2 * std::ptrdiff_t{n}, -1);
  assemble(t, ctx, gamma);
  if (!k_.factor()) return;  // not finite (a NaN put in from outside): the divergence guard resets it
  k_.forward(f_.data());
  add_ring_area_row(t, ctx, RowKind::tread_area, gamma);
  add_ring_area_row(t, ctx, RowKind::rim_area, gamma);
  if (t.grabbed) {
    const Vec2 d = t.particles.x[t.grab_particle] - t.grab_target;
    const double len = length(d);
    if (len > 0.0) {
      std::fill(work_.begin(), work_.begin() + 4 * std::ptrdiff_t{n}, 0.0);
      Row row(RowKind::grab);
      row.particle = t.grab_particle;
      row.direction = d / len;
      row.alpha_tilde = t.grab_compliance / (ctx.h * ctx.h);
      row.b = -len;
      const std::size_t k = dof_of(t.grab_particle, n);
      work_[k] = row.direction.x;
      work_[k + 1] = row.direction.y;
      add_row(t, row, work_.data());
    }
  }
  // Contacts held at the end of the substep's previous iteration stay in (their plane and whether
  // they stuck), so a resting tire does not lose its support between iterations.
  t.for_each_contact([&](std::uint32_t i) {
    const ContactRecord& rec = t.contacts[i];
    if (!rec.active || contacts_.size() >= kMaxContacts || rows_.size() + 2 > max_rows_) return;
    Contact c;
    c.particle = i;
    c.normal = rec.normal;
    c.plane = rec.plane;
    c.surface_velocity = rec.surface_velocity;
    c.surface_displacement = rec.surface_velocity * ctx.h;
    c.prop = rec.prop;
    c.mu_static = rec.mu_static;
    c.mu_kinetic = rec.mu_kinetic;
    if (c.prop >= 0) {
      const Prop& prop = ctx.rigid->props()[static_cast<std::size_t>(c.prop)];
      if (prop.is_dynamic()) {
        c.arm = t.particles.x[i] - prop.center_at(ctx.time + ctx.h);
        c.mobility_n = std::max(0.0, prop.mobility(-c.normal));
        c.mobility_t = std::max(0.0, std::min(prop.mobility(perp(c.normal)), prop.mobility(-perp(c.normal))));
        c.inverse_mass = prop.inverse_mass;
        c.inverse_inertia = prop.inverse_inertia;
      }
    }
    contact_of_[i] = static_cast<std::int32_t>(contacts_.size());
    contacts_.push_back(c);
    add_contact_rows(t, contact_of_[i], rec.stuck);
  });
  find_contacts(t, ctx, nullptr);
  // Active-set passes: drop contacts that pull and friction that cannot hold, add particles that
  // the step would push into a surface, until nothing changes.
  const int passes = std::max(1, ctx.config->contact_passes);
  for (int pass = 0; pass < passes; ++pass) {
    ++counts_.passes;
    solve_active(t);
    bool changed = false;
    for (Row& row : rows_) {
      if (!row.active || row.contact < 0) continue;
      const Contact& c = contacts_[static_cast<std::size_t>(row.contact)];
      if (row.kind == RowKind::normal && row.mu < 0.0) {  // the surface would pull: let go
        row.active = false;
        if (c.friction_row >= 0) rows_[static_cast<std::size_t>(c.friction_row)].active = false;
        changed = true;
      } else if (row.kind == RowKind::friction) {  // Coulomb: stick while |μ_t| ≤ μ_s μ_n
        const double mu_n = rows_[static_cast<std::size_t>(c.normal_row)].mu;
        if (std::abs(row.mu) > c.mu_static * std::max(mu_n, 0.0)) {
          row.active = false;
          changed = true;
        }
      }
    }
    // A released contact that the step would push back into its surface comes back in.
    for (Row& row : rows_) {
      if (row.active || row.kind != RowKind::normal) continue;
      const Contact& c = contacts_[static_cast<std::size_t>(row.contact)];
      const Vec2 x = t.particles.x[c.particle] + at(dx_.data(), dof_of(c.particle, n));
      if (c.plane - dot(c.normal, x) > ctx.config->contact_slop) {
        row.active = true;
        changed = true;
      }
    }
    if (find_contacts(t, ctx, dx_.data())) changed = true;
    if (!changed) break;
    if (pass + 1 == passes) solve_active(t);  // the last pass's changes still get solved
  }
  for (std::uint32_t i = 0; i < 2 * n; ++i) t.particles.x[i] += at(dx_.data(), dof_of(i, n));
  write_back(t, ctx);
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
    t.prop_impulses.push_back({static_cast<std::uint32_t>(rec.prop), impulse, t.particles.x[i], t_end});
  };
  // Records of the last iteration that this one no longer holds: give back what they owed.
  t.for_each_contact([&](std::uint32_t i) {
    ContactRecord& rec = t.contacts[i];
    const std::int32_t k = contact_of_[i];
    const bool held = k >= 0 && contacts_[static_cast<std::size_t>(k)].normal_row >= 0 &&
                      rows_[static_cast<std::size_t>(contacts_[static_cast<std::size_t>(k)].normal_row)].active;
    if (rec.active && !held) {
      owe(rec, i, -rec.lambda_n, -rec.lambda_t);
      rec = ContactRecord{};
    }
  });
  for (const Contact& c : contacts_) {
    if (c.normal_row < 0) continue;
    const Row& normal = rows_[static_cast<std::size_t>(c.normal_row)];
    if (!normal.active) continue;
    const bool stuck = c.friction_row >= 0 && rows_[static_cast<std::size_t>(c.friction_row)].active;
    const double w = t.particles.w[c.particle];
    const double lambda_n = w * normal.mu;
    const double lambda_t = stuck ? w * rows_[static_cast<std::size_t>(c.friction_row)].mu : 0.0;
    ContactRecord& rec = t.touch_contact(c.particle);
    const ContactRecord before = rec.active ? rec : ContactRecord{};
    rec.normal = c.normal;
    rec.surface_velocity = c.surface_velocity;
    rec.lambda_n = lambda_n;
    rec.lambda_t = lambda_t;
    rec.mu_static = c.mu_static;
    rec.mu_kinetic = c.mu_kinetic;
    rec.prop = c.prop;
    rec.active = true;
    rec.stuck = stuck;
    rec.plane = c.plane;
    owe(rec, c.particle, lambda_n - before.lambda_n, lambda_t - before.lambda_t);
    ++counts_.contacts;
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
  TIRE_ASSERT(!solvers_.empty(), "the global method's solvers were never reserved");
  for (;;)
    for (std::size_t k = 0; k < solvers_.size(); ++k) {
      bool expected = false;
      if (busy_[k].compare_exchange_strong(expected, true, std::memory_order_acquire)) return Lease(*this, k);
    }
}

}  // namespace tire
