#include "tire/xpbd/distance_constraint.h"

#include <algorithm>
#include <cmath>

#include "tire/math/check.h"

#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
#include <immintrin.h>
#define TIRE_HAVE_AVX_PATH 1
#endif

namespace tire {

DistanceLayout::DistanceLayout(std::vector<Pair> pairs, std::vector<std::uint32_t> group, const double* w)
    : pairs_(std::move(pairs)), group_(std::move(group)) {
  TIRE_ASSERT(group_.size() == pairs_.size(), "a distance constraint without a compliance group");
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    TIRE_ASSERT(pairs_[k].a != pairs_[k].b, "a distance constraint joins a particle to itself");
    particle_count_ =
        std::max<std::size_t>(particle_count_, std::max(pairs_[k].a, pairs_[k].b) + std::size_t{1});
    group_count_ = std::max<std::size_t>(group_count_, group_[k] + std::size_t{1});
  }
  slot_.assign(pairs_.size(), 0);
  // A class is a group and a pair of inverse masses; without masses, a group.
  const auto same_class = [&](const Class& p, const Class& q) {
    return p.group == q.group && (!w || (w[p.a] == w[q.a] && w[p.b] == w[q.b]));
  };
  const auto class_index = [&](const Class& q) {
    for (std::size_t i = 0; i < classes_.size(); ++i)
      if (same_class(classes_[i], q)) return static_cast<std::uint32_t>(i);
    classes_.push_back(q);
    return static_cast<std::uint32_t>(classes_.size() - 1);
  };
  // Greedy, in order: a constraint joins the open batch unless it shares a particle with it or is
  // of another class. The order of the constraints is kept whatever the cut, and the lanes of a
  // batch are independent, so the cut never changes a result.
  Lanes open{};
  Class open_class;
  std::uint32_t count = 0;
  const auto close = [&] {
    if (count == 0) return;
    TIRE_ASSERT(count <= kLanes, "a batch has more lanes than the vector");
    // The lanes are independent (what makes the batch one Gauss-Seidel sweep), which also keeps a
    // real lane from looking like a copy of lane 0 to the scalar path (is_copy).
    for (std::uint32_t l = 1; l < count; ++l)
      for (std::uint32_t m = 0; m < l; ++m)
        TIRE_ASSERT(open.a[l] != open.a[m] && open.a[l] != open.b[m] && open.b[l] != open.a[m] &&
                        open.b[l] != open.b[m],
                    "two lanes of a batch share a particle");
    // A batch that is not full repeats its first lane: the copy computes and writes exactly what
    // lane 0 does, so the vector path needs no lane count (the scalar path skips copies).
    for (std::uint32_t l = count; l < kLanes; ++l) {
      open.a[l] = open.a[0];
      open.b[l] = open.b[0];
    }
    batches_.push_back(open);
    class_of_.push_back(class_index(open_class));
    open = Lanes{};
    count = 0;
  };
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const Pair c = pairs_[k];
    const Class q{group_[k], c.a, c.b};
    bool fits = count > 0 && same_class(q, open_class);
    for (std::uint32_t l = 0; l < count; ++l)
      fits &= open.a[l] != c.a && open.a[l] != c.b && open.b[l] != c.a && open.b[l] != c.b;
    if (!fits) close();
    if (count == 0) open_class = q;
    const std::uint32_t l = count++;
    slot_[k] = static_cast<std::uint32_t>(batches_.size() * kLanes + l);
    open.a[l] = c.a;
    open.b[l] = c.b;
    if (count == kLanes) close();
  }
  close();
}

bool DistanceLayout::fits(const double* w) const {
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const Class& q = classes_[class_of_[slot_[k] / kLanes]];
    if (w[pairs_[k].a] != w[q.a] || w[pairs_[k].b] != w[q.b]) return false;
  }
  return true;
}

namespace {
// The group of compliance α among `groups` (one per distinct compliance, in order of first use),
// added when new.
std::uint32_t compliance_group(std::vector<double>& groups, double alpha) {
  const auto it = std::find(groups.begin(), groups.end(), alpha);
  if (it != groups.end()) return static_cast<std::uint32_t>(it - groups.begin());
  groups.push_back(alpha);
  return static_cast<std::uint32_t>(groups.size() - 1);
}
}  // namespace

DistanceConstraintSet::Slots DistanceConstraintSet::plan(BlockLayout& block_layout,
                                                         const DistanceLayout& layout) {
  return {block_layout.add<LaneState>(layout.batch_count()),
          block_layout.add<Params>(layout.classes().size()), block_layout.add<double>(layout.group_count()),
          block_layout.add<double>(layout.particle_count())};
}

DistanceConstraintSet::DistanceConstraintSet(const std::vector<DistanceConstraint>& constraints) {
  std::vector<DistanceLayout::Pair> pairs;
  std::vector<std::uint32_t> group;
  std::vector<double> compliance;  // per group
  pairs.reserve(constraints.size());
  group.reserve(constraints.size());
  for (const DistanceConstraint& c : constraints) {
    TIRE_ASSERT(c.rest_length >= 0.0 && std::isfinite(c.rest_length),
                "a rest length is negative, NaN or infinite");
    TIRE_ASSERT(c.compliance >= 0.0 && std::isfinite(c.compliance),
                "a compliance is negative, NaN or infinite");
    group.push_back(compliance_group(compliance, c.compliance));
    pairs.push_back({c.a, c.b});
  }
  adopt(std::make_shared<const DistanceLayout>(std::move(pairs), std::move(group)), compliance);
  for (std::size_t k = 0; k < constraints.size(); ++k) set_rest_length(k, constraints[k].rest_length);
}

DistanceConstraintSet::DistanceConstraintSet(std::shared_ptr<const DistanceLayout> layout,
                                             std::span<const Vec2> x, std::span<const double> compliance,
                                             ArrayBlock& block, const Slots& slots) {
  TIRE_ASSERT(layout && compliance.size() == layout->group_count(), "a compliance per group of the layout");
  TIRE_ASSERT(x.size() >= layout->particle_count(), "a constraint names a particle that is not there");
  for (double c : compliance)
    TIRE_ASSERT(c >= 0.0 && std::isfinite(c), "a compliance is negative, NaN or infinite");
  adopt(std::move(layout), compliance, block, slots);
  const std::vector<DistanceLayout::Pair>& pairs = layout_->pairs();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const double rest_length = length(x[pairs[k].b] - x[pairs[k].a]);
    TIRE_ASSERT(std::isfinite(rest_length), "a rest length is NaN or infinite");
    set_rest_length(k, rest_length);
  }
}

void DistanceConstraintSet::adopt(std::shared_ptr<const DistanceLayout> layout,
                                  std::span<const double> compliance, ArrayBlock& block, const Slots& slots) {
  TIRE_ASSERT(slots.state.count == layout->batch_count() && slots.params.count == layout->classes().size() &&
                  slots.compliance.count == layout->group_count() &&
                  slots.w_built.count == layout->particle_count() &&
                  compliance.size() == layout->group_count(),
              "arrays not of the layout's sizes");
  layout_ = std::move(layout);
  state_ = block.construct(slots.state);
  params_ = block.construct(slots.params);
  compliance_ = block.construct(slots.compliance);
  w_built_ = block.construct(slots.w_built);
  std::copy(compliance.begin(), compliance.end(), compliance_.begin());
  prepared_ = false;
}

void DistanceConstraintSet::adopt(std::shared_ptr<const DistanceLayout> layout,
                                  std::span<const double> compliance) {
  BlockLayout block_layout;
  const Slots slots = plan(block_layout, *layout);
  ArrayBlock block(block_layout);
  adopt(std::move(layout), compliance, block, slots);
  own_ = std::move(block);  // frees the old one (if any) once nothing points into it
}

void DistanceConstraintSet::set_rest_length(std::size_t k, double rest_length) {
  const std::uint32_t s = layout_->slot()[k];
  LaneState& state = state_[s / kLanes];
  state.rest_length[s % kLanes] = rest_length;
  // A lane that repeats lane 0 repeats its rest length too (is_copy).
  const DistanceLayout::Lanes& batch = layout_->batches()[s / kLanes];
  if (s % kLanes == 0)
    for (std::uint32_t l = 1; l < kLanes; ++l)
      if (batch.a[l] == batch.a[0]) state.rest_length[l] = rest_length;
}

void DistanceConstraintSet::set_compliance(std::size_t first, std::size_t count, double compliance) {
  TIRE_ASSERT(compliance >= 0.0 && std::isfinite(compliance), "a compliance is negative, NaN or infinite");
  if (pending_.empty())
    for (std::size_t k = 0; k < size(); ++k) pending_.push_back(compliance_[layout_->group()[k]]);
  for (std::size_t k = first; k < first + count && k < size(); ++k) pending_[k] = compliance;
}

void DistanceConstraintSet::set_group_compliance(std::size_t g, double compliance) {
  TIRE_ASSERT(compliance >= 0.0 && std::isfinite(compliance), "a compliance is negative, NaN or infinite");
  TIRE_ASSERT(g < compliance_.size() && pending_.empty(),
              "no such group, or compliances set by range and not yet prepared");
  compliance_[g] = compliance;
}

void DistanceConstraintSet::prepare(const double* w, double h, double tau) {
  TIRE_ASSERT(h > 0.0 && std::isfinite(h), "the substep is not a positive length of time");
  TIRE_ASSERT(tau >= 0.0 && std::isfinite(tau), "the damping time is negative, NaN or infinite");
  const std::size_t particle_count = layout_->particle_count();
  TIRE_ASSERT(std::all_of(w, w + particle_count, [](double wi) { return wi >= 0.0 && std::isfinite(wi); }),
              "an inverse mass is negative, NaN or infinite");
  // The shared layout serves while every batch's lanes have its class's masses (a tire's particles
  // all weigh the same) and compliances are set by group. Otherwise the set is cut again, on a
  // layout of its own (the cut never changes a result, see DistanceLayout).
  const bool regroup = !pending_.empty();
  if (regroup || !prepared_ || !std::equal(w_built_.begin(), w_built_.end(), w)) {
    if (regroup || !layout_->fits(w)) {
      std::vector<double> rest_length(size()), per_constraint(size());
      for (std::size_t k = 0; k < size(); ++k) {
        const DistanceConstraint c = constraint(k);
        rest_length[k] = c.rest_length;
        per_constraint[k] = c.compliance;
      }
      pending_.clear();
      std::vector<double> compliance;  // per group
      std::vector<std::uint32_t> group(size());
      for (std::size_t k = 0; k < size(); ++k) {
        group[k] = compliance_group(compliance, per_constraint[k]);
      }
      adopt(std::make_shared<const DistanceLayout>(layout_->pairs(), std::move(group), w), compliance);
      for (std::size_t k = 0; k < rest_length.size(); ++k) set_rest_length(k, rest_length[k]);
    }
    TIRE_ASSERT(w_built_.size() == particle_count, "a layout of another particle count");
    std::copy(w, w + particle_count, w_built_.begin());
    prepared_ = true;
  }
  const double inv_h2 = 1.0 / (h * h);
  const std::vector<DistanceLayout::Class>& classes = layout_->classes();
  for (std::size_t i = 0; i < params_.size(); ++i) {
    Params& q = params_[i];
    q.compliance = compliance_[classes[i].group];
    q.w_a = w[classes[i].a];
    q.w_b = w[classes[i].b];
    q.alpha_tilde = q.compliance * inv_h2;  // α̃ = α/h²  (XPBD eq. 4)
    // ∇C M⁻¹ ∇Cᵀ + α̃ with |∇C| = 1 at each end
    const double denominator = q.w_a + q.w_b + q.alpha_tilde;
    q.inv_denominator = denominator > 0.0 ? 1.0 / denominator : 0.0;
    // The dashpot's impulse per unit rate: rate·removed/W with removed = chW/(1 + chW), c = τ/α,
    // simplifies to τh/(α + τhW), which also covers α = 0 (all of the rate removed).
    const double tau_h = tau * h, w_sum = q.w_a + q.w_b;
    const double damping_denominator = q.compliance + tau_h * w_sum;
    q.damping = tau_h > 0.0 && w_sum > 0.0 ? tau_h / damping_denominator : 0.0;
  }
}

void DistanceConstraintSet::reset_lambda() {
  for (LaneState& s : state_) std::fill(std::begin(s.lambda), std::end(s.lambda), 0.0);
}

double DistanceConstraintSet::lambda(std::size_t k) const {
  if (!layout_ || k >= layout_->size()) return 0.0;
  const std::uint32_t s = layout_->slot()[k];
  return state_[s / kLanes].lambda[s % kLanes];
}

namespace {

// The projection of one lane, written so that the vector path below performs the very same
// operations in the same order:
//   n = (x_b − x_a)/|x_b − x_a|, C = |x_b − x_a| − L0,
//   Δλ = (−C − α̃λ) / (w_a + w_b + α̃)   (XPBD eq. 18),
//   x_a −= w_a Δλ n,  x_b += w_b Δλ n  (XPBD eq. 17).
// A zero length (coincident particles) gets n = 0: λ still accumulates, nothing moves.
// Lane l > 0 is a copy of lane 0 (a batch that is not full): the scalar path does that work once.
template <typename B>
bool is_copy(const B& batch, std::uint32_t l) {
  return l > 0 && batch.a[l] == batch.a[0];
}

template <typename B, typename S, typename P>
void solve_scalar(const B& batch, S& s, const P& q, Vec2* x) {
  for (std::uint32_t l = 0; l < B::kLanes && !is_copy(batch, l); ++l) {
    const Vec2 xa = x[batch.a[l]], xb = x[batch.b[l]];
    const double dx = xb.x - xa.x, dy = xb.y - xa.y;
    const double len = std::sqrt(dx * dx + dy * dy);
    const double inv_len = len > 0.0 ? 1.0 / len : 0.0;
    const double delta_lambda = ((s.rest_length[l] - len) - q.alpha_tilde * s.lambda[l]) * q.inv_denominator;
    s.lambda[l] += delta_lambda;
    const double nx = dx * inv_len, ny = dy * inv_len;
    const double sa = q.w_a * delta_lambda, sb = q.w_b * delta_lambda;
    x[batch.a[l]] = {xa.x - nx * sa, xa.y - ny * sa};
    x[batch.b[l]] = {xb.x + nx * sb, xb.y + ny * sb};
  }
}

// The dashpot of one lane, in the same operations and order as the vector path below:
// n as in solve_scalar, dC/dt = n·(v_b − v_a), p = dC/dt · damping, v_a += w_a p n, v_b −= w_b p n.
template <typename B, typename P>
void damp_scalar(const B& batch, const P& q, const Vec2* x, Vec2* v) {
  for (std::uint32_t l = 0; l < B::kLanes && !is_copy(batch, l); ++l) {
    const Vec2 xa = x[batch.a[l]], xb = x[batch.b[l]];
    const Vec2 va = v[batch.a[l]], vb = v[batch.b[l]];
    const double dx = xb.x - xa.x, dy = xb.y - xa.y;
    const double len = std::sqrt(dx * dx + dy * dy);
    const double inv_len = len > 0.0 ? 1.0 / len : 0.0;
    const double nx = dx * inv_len, ny = dy * inv_len;
    const double rate = nx * (vb.x - va.x) + ny * (vb.y - va.y);
    const double impulse = rate * q.damping;
    const double sa = q.w_a * impulse, sb = q.w_b * impulse;
    v[batch.a[l]] = {va.x + nx * sa, va.y + ny * sa};
    v[batch.b[l]] = {vb.x - nx * sb, vb.y - ny * sb};
  }
}

#ifdef TIRE_HAVE_AVX_PATH
// Four particles' (x, y) → (x0 x1 x2 x3), (y0 y1 y2 y3).
__attribute__((target("avx"))) inline void gather(const Vec2* x, const std::uint32_t* idx, __m256d& px,
                                                  __m256d& py) {
  const __m128d p0 = _mm_loadu_pd(&x[idx[0]].x), p1 = _mm_loadu_pd(&x[idx[1]].x);
  const __m128d p2 = _mm_loadu_pd(&x[idx[2]].x), p3 = _mm_loadu_pd(&x[idx[3]].x);
  const __m256d t02 = _mm256_insertf128_pd(_mm256_castpd128_pd256(p0), p2, 1);  // x0 y0 x2 y2
  const __m256d t13 = _mm256_insertf128_pd(_mm256_castpd128_pd256(p1), p3, 1);  // x1 y1 x3 y3
  px = _mm256_unpacklo_pd(t02, t13);
  py = _mm256_unpackhi_pd(t02, t13);
}

// Writes lane l's (px, py) to x[idx[l]]. A copy of lane 0 writes what lane 0 wrote.
__attribute__((target("avx"))) inline void scatter(Vec2* x, const std::uint32_t* idx, __m256d px,
                                                   __m256d py) {
  const __m256d t02 = _mm256_unpacklo_pd(px, py);  // x0 y0 x2 y2
  const __m256d t13 = _mm256_unpackhi_pd(px, py);  // x1 y1 x3 y3
  _mm_storeu_pd(&x[idx[0]].x, _mm256_castpd256_pd128(t02));
  _mm_storeu_pd(&x[idx[1]].x, _mm256_castpd256_pd128(t13));
  _mm_storeu_pd(&x[idx[2]].x, _mm256_extractf128_pd(t02, 1));
  _mm_storeu_pd(&x[idx[3]].x, _mm256_extractf128_pd(t13, 1));
}

template <typename B, typename S, typename P>
__attribute__((target("avx"))) void solve_avx(const B* batches, S* states, const std::uint32_t* params_of,
                                              const P* params, std::size_t n, Vec2* x) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  for (std::size_t k = 0; k < n; ++k) {
    const B& batch = batches[k];
    S& s = states[k];
    const P& q = params[params_of[k]];
    __m256d ax, ay, bx, by;
    gather(x, batch.a, ax, ay);
    gather(x, batch.b, bx, by);
    const __m256d dx = _mm256_sub_pd(bx, ax), dy = _mm256_sub_pd(by, ay);
    const __m256d len = _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
    const __m256d inv_len = _mm256_and_pd(_mm256_div_pd(one, len), _mm256_cmp_pd(len, zero, _CMP_GT_OQ));
    const __m256d lambda = _mm256_load_pd(s.lambda);
    const __m256d delta_lambda =
        _mm256_mul_pd(_mm256_sub_pd(_mm256_sub_pd(_mm256_load_pd(s.rest_length), len),
                                    _mm256_mul_pd(_mm256_set1_pd(q.alpha_tilde), lambda)),
                      _mm256_set1_pd(q.inv_denominator));
    _mm256_store_pd(s.lambda, _mm256_add_pd(lambda, delta_lambda));
    const __m256d nx = _mm256_mul_pd(dx, inv_len), ny = _mm256_mul_pd(dy, inv_len);
    const __m256d sa = _mm256_mul_pd(_mm256_set1_pd(q.w_a), delta_lambda);
    const __m256d sb = _mm256_mul_pd(_mm256_set1_pd(q.w_b), delta_lambda);
    scatter(x, batch.a, _mm256_sub_pd(ax, _mm256_mul_pd(nx, sa)), _mm256_sub_pd(ay, _mm256_mul_pd(ny, sa)));
    scatter(x, batch.b, _mm256_add_pd(bx, _mm256_mul_pd(nx, sb)), _mm256_add_pd(by, _mm256_mul_pd(ny, sb)));
  }
}

template <typename B, typename P>
__attribute__((target("avx"))) void damp_avx(const B* batches, const std::uint32_t* params_of,
                                             const P* params, std::size_t n, const Vec2* x, Vec2* v) {
  const __m256d zero = _mm256_setzero_pd(), one = _mm256_set1_pd(1.0);
  for (std::size_t k = 0; k < n; ++k) {
    const B& batch = batches[k];
    const P& q = params[params_of[k]];
    __m256d ax, ay, bx, by, vax, vay, vbx, vby;
    gather(x, batch.a, ax, ay);
    gather(x, batch.b, bx, by);
    gather(v, batch.a, vax, vay);
    gather(v, batch.b, vbx, vby);
    const __m256d dx = _mm256_sub_pd(bx, ax), dy = _mm256_sub_pd(by, ay);
    const __m256d len = _mm256_sqrt_pd(_mm256_add_pd(_mm256_mul_pd(dx, dx), _mm256_mul_pd(dy, dy)));
    const __m256d inv_len = _mm256_and_pd(_mm256_div_pd(one, len), _mm256_cmp_pd(len, zero, _CMP_GT_OQ));
    const __m256d nx = _mm256_mul_pd(dx, inv_len), ny = _mm256_mul_pd(dy, inv_len);
    const __m256d rate =
        _mm256_add_pd(_mm256_mul_pd(nx, _mm256_sub_pd(vbx, vax)), _mm256_mul_pd(ny, _mm256_sub_pd(vby, vay)));
    const __m256d impulse = _mm256_mul_pd(rate, _mm256_set1_pd(q.damping));
    const __m256d sa = _mm256_mul_pd(_mm256_set1_pd(q.w_a), impulse);
    const __m256d sb = _mm256_mul_pd(_mm256_set1_pd(q.w_b), impulse);
    scatter(v, batch.a, _mm256_add_pd(vax, _mm256_mul_pd(nx, sa)), _mm256_add_pd(vay, _mm256_mul_pd(ny, sa)));
    scatter(v, batch.b, _mm256_sub_pd(vbx, _mm256_mul_pd(nx, sb)), _mm256_sub_pd(vby, _mm256_mul_pd(ny, sb)));
  }
}

const bool kCpuHasAvx = __builtin_cpu_supports("avx");
#endif

}  // namespace

void DistanceConstraintSet::solve(Vec2* x) {
  TIRE_ASSERT(pending_.empty() && prepared_, "solve() before prepare(), or after a change it has not seen");
  const DistanceLayout& layout = *layout_;
  const std::size_t n = layout.batch_count();
  const DistanceLayout::Lanes* batches = layout.batches().data();
  const std::uint32_t* class_of = layout.class_of().data();
#ifndef NDEBUG
  const bool finite_before = std::all_of(x, x + layout.particle_count(), [](Vec2 p) { return is_finite(p); });
#endif
#ifdef TIRE_HAVE_AVX_PATH
  if (kCpuHasAvx && kernel_ == Kernel::automatic)
    solve_avx(batches, state_.data(), class_of, params_.data(), n, x);
  else
#endif
    for (std::size_t k = 0; k < n; ++k) solve_scalar(batches[k], state_[k], params_[class_of[k]], x);
#ifndef NDEBUG
  TIRE_ASSERT(!finite_before || std::all_of(state_.begin(), state_.end(),
                                            [](const LaneState& s) {
                                              return std::all_of(std::begin(s.lambda), std::end(s.lambda),
                                                                 [](double l) { return std::isfinite(l); });
                                            }),
              "a sweep from finite positions left a multiplier NaN or infinite");
#endif
}

void DistanceConstraintSet::damp(const Vec2* x, Vec2* v) {
  TIRE_ASSERT(pending_.empty() && prepared_, "damp() before prepare(), or after a change it has not seen");
  const DistanceLayout& layout = *layout_;
  const std::size_t n = layout.batch_count();
  const DistanceLayout::Lanes* batches = layout.batches().data();
  const std::uint32_t* class_of = layout.class_of().data();
#ifdef TIRE_HAVE_AVX_PATH
  if (kCpuHasAvx && kernel_ == Kernel::automatic) return damp_avx(batches, class_of, params_.data(), n, x, v);
#endif
  for (std::size_t k = 0; k < n; ++k) damp_scalar(batches[k], params_[class_of[k]], x, v);
}

}  // namespace tire
