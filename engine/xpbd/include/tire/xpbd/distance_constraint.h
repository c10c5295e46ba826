// Distance constraint C(x) = |x_b − x_a| − L0 (Macklin et al. 2016, "XPBD", Sec. 5; Müller et al.
// 2007, "Position Based Dynamics", Sec. 3.3), solved with XPBD compliance and accumulated λ, plus a
// dashpot in parallel (Kelvin–Voigt) applied to velocities. Its gradient is ∇_{x_b}C = n =
// (x_b − x_a)/|x_b − x_a| = −∇_{x_a}C; when the two particles coincide it is undefined, taken as
// zero: λ still accumulates, nothing moves. (tests/test_distance_constraint.cpp reads the gradient
// the solver used off one projection and compares it with finite differences of C.)
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "tire/math/array_block.h"
#include "tire/math/geometry.h"
#include "tire/math/prefetch.h"

namespace tire {

struct DistanceConstraint {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  double rest_length = 0.0;  // L0 (m)
  double compliance = 0.0;   // α (m/N): inverse stiffness; 0 is rigid
};

// What sets of distance constraints of one shape share (Jolt's shared settings): which particles
// each constraint joins, the compliance group it takes its α from, and the cut of the constraints,
// in their Gauss–Seidel order, into batches of up to four that share no particle and one set of
// Params (one group, one pair of inverse masses). Immutable once built: held by std::shared_ptr
// by every set that uses it. What changes per set (rest lengths, λ, the groups' compliances, the
// inverse masses) lives in the set.
class DistanceLayout {
 public:
  static constexpr int kLanes = 4;

  // The particles of four lanes, 32 bytes. A batch that is not full repeats its first lane.
  struct alignas(32) Lanes {
    static constexpr std::uint32_t kLanes = DistanceLayout::kLanes;
    std::uint32_t a[kLanes];
    std::uint32_t b[kLanes];
  };
  static_assert(sizeof(Lanes) == 8 * kLanes);
  // The lanes of a batch share one group and one pair of inverse masses: those of particles a and b.
  struct Class {
    std::uint32_t group = 0;
    std::uint32_t a = 0;
    std::uint32_t b = 0;
  };
  struct Pair {
    std::uint32_t a = 0;
    std::uint32_t b = 0;
  };

  // `group[k]` is constraint k's compliance group. With inverse masses `w` the cut also splits at a
  // change of (w_a, w_b); without (null), it splits by group only, and fits() tells whether some
  // masses agree with it.
  DistanceLayout(std::vector<Pair> pairs, std::vector<std::uint32_t> group, const double* w = nullptr);

  std::size_t size() const { return pairs_.size(); }
  std::size_t batch_count() const { return batches_.size(); }
  std::size_t group_count() const { return group_count_; }
  std::size_t particle_count() const { return particle_count_; }  // 1 + the highest particle index named
  const std::vector<Pair>& pairs() const { return pairs_; }
  const std::vector<std::uint32_t>& group() const { return group_; }
  const std::vector<Lanes>& batches() const { return batches_; }
  const std::vector<std::uint32_t>& class_of() const { return class_of_; }  // per batch
  const std::vector<Class>& classes() const { return classes_; }
  // Constraint k is lane slot()[k] % kLanes of batch slot()[k] / kLanes.
  const std::vector<std::uint32_t>& slot() const { return slot_; }
  // Whether every batch's lanes have the inverse masses of its class under `w`.
  bool fits(const double* w) const;

 private:
  std::vector<Pair> pairs_;
  std::vector<std::uint32_t> group_;
  std::vector<Lanes> batches_;
  std::vector<std::uint32_t> class_of_;
  std::vector<Class> classes_;
  std::vector<std::uint32_t> slot_;
  std::size_t group_count_ = 0;
  std::size_t particle_count_ = 0;
};

// A set of distance constraints laid out for the solver: a shared DistanceLayout and this set's own
// rest lengths, multipliers and compliances, stored lane by lane. Constraints in a batch are
// independent, so solving them together is exactly solving them one after the other, and one
// vector instruction serves all four (AVX where the CPU has it; otherwise the same arithmetic lane
// by lane, which gives the same bits: IEEE sqrt and division are correctly rounded either way).
//
// The set's own arrays are fixed by its layout. A tire places them in its one block (plan(), then
// the constructor from a block); a set built from a list of constraints has a block of its own, and
// so does a set that prepare() has to cut again (different masses or compliances set by range: a
// layout of its own, whose counts may differ). Move-only, as the arrays are views into a block.
class DistanceConstraintSet {
  // What a sweep reads and writes of this set's own for four constraints, 64 bytes: in a scene of a
  // thousand tires these are most of what streams from memory every substep (the shared Lanes of
  // a shape stay in cache). A batch that is not full repeats its first lane. The SIMD kernels load
  // and store its lanes aligned.
  struct alignas(32) LaneState {
    double rest_length[DistanceLayout::kLanes];
    double lambda[DistanceLayout::kLanes];
  };
  static_assert(sizeof(LaneState) == 16 * DistanceLayout::kLanes);
  // What the four lanes of a batch share, one per class of the layout.
  struct Params {
    double compliance = 0.0;  // α
    double w_a = 0.0;
    double w_b = 0.0;
    double alpha_tilde = 0.0;      // α̃ = α/h²
    double inv_denominator = 0.0;  // 1 / (w_a + w_b + α̃); 0 for a pinned pair
    double damping = 0.0;          // τh / (α + τhW): dashpot impulse per unit of dC/dt
  };

 public:
  static constexpr int kLanes = DistanceLayout::kLanes;

  // The constraints, read one by one (a, b, rest length and the compliance of its group), by value.
  class ConstraintView {
   public:
    class iterator {
     public:
      using value_type = DistanceConstraint;
      using difference_type = std::ptrdiff_t;
      iterator() = default;
      iterator(const DistanceConstraintSet* set, std::size_t k) : set_(set), k_(k) {}
      DistanceConstraint operator*() const { return set_->constraint(k_); }
      iterator& operator++() {
        ++k_;
        return *this;
      }
      iterator operator++(int) {
        iterator old = *this;
        ++k_;
        return old;
      }
      bool operator==(const iterator& o) const { return k_ == o.k_; }

     private:
      const DistanceConstraintSet* set_ = nullptr;
      std::size_t k_ = 0;
    };
    explicit ConstraintView(const DistanceConstraintSet* set) : set_(set) {}
    iterator begin() const { return {set_, 0}; }
    iterator end() const { return {set_, size()}; }
    std::size_t size() const { return set_->size(); }
    bool empty() const { return size() == 0; }
    DistanceConstraint operator[](std::size_t k) const { return set_->constraint(k); }

   private:
    const DistanceConstraintSet* set_;
  };

  // Where the arrays of a set on `layout` go in a block.
  struct Slots {
    BlockSlot<LaneState> state;    // per batch
    BlockSlot<Params> params;      // per class
    BlockSlot<double> compliance;  // per group
    BlockSlot<double> w_built;     // per particle
  };
  static Slots plan(BlockLayout& block_layout, const DistanceLayout& layout);

  DistanceConstraintSet() = default;
  // A set of its own, in a block of its own: one compliance group per distinct compliance.
  explicit DistanceConstraintSet(const std::vector<DistanceConstraint>& constraints);
  // A set on a shared layout, at rest where the particles `x` are (each rest length is the distance
  // between its particles there), with `compliance` per group; its arrays at `slots` in `block`,
  // which the caller keeps (a tire: its one block).
  DistanceConstraintSet(std::shared_ptr<const DistanceLayout> layout, std::span<const Vec2> x,
                        std::span<const double> compliance, ArrayBlock& block, const Slots& slots);

  ConstraintView constraints() const { return ConstraintView(this); }
  DistanceConstraint constraint(std::size_t k) const;
  const std::shared_ptr<const DistanceLayout>& layout() const { return layout_; }
  // Changes the compliance of constraints [first, first + count) (live tuning); takes effect at
  // the next prepare(). A range that is not whole groups gives this set a layout of its own.
  void set_compliance(std::size_t first, std::size_t count, double compliance);
  // Changes the compliance of group g (live tuning, never a new layout); takes effect at prepare().
  void set_group_compliance(std::size_t g, double compliance);
  double group_compliance(std::size_t g) const { return compliance_[g]; }
  std::size_t size() const { return layout_ ? layout_->size() : 0; }
  std::size_t batch_count() const { return layout_ ? layout_->batch_count() : 0; }

  // Derives, for substep h and damping time τ, α̃ = α/h² (XPBD eq. 4), the inverse masses,
  // 1/(w_a + w_b + α̃) and the dashpot factor of damp(). Call whenever h, τ, a mass or a compliance
  // changes (the tire does, every tick).
  void prepare(const double* w, double h, double tau = 0.0);
  void reset_lambda();
  double lambda(std::size_t k) const;  // constraint k's accumulated multiplier this substep

  // One Gauss–Seidel sweep, always in the same order: the sweep's unconverged residual must look
  // the same every substep, or v = (x − x_prev)/h turns its change into energy.
  void solve(Vec2* x);

  // Kelvin–Voigt damping in the velocity pass (as Müller et al. 2020, Sec. 3.6, damp in theirs): a
  // dashpot c = τ/α in parallel with each constraint's spring (stiffness-proportional, Rayleigh)
  // acts on the rate dC/dt = ∇C·v. Integrated implicitly over h, the rate decays by the factor
  // 1/(1 + c·h·(w_a + w_b)), so it is stable for any c; a rigid constraint (α = 0) loses all of
  // it. At rest there is no rate: the static solution is untouched. Uses the τ and h of prepare().
  void damp(const Vec2* x, Vec2* v);

  // Asks the CPU to start loading the batches (a hint; changes nothing).
  void prefetch() const {
    tire::prefetch(state_);
    if (layout_) tire::prefetch(layout_->batches());
  }

  enum class Kernel { automatic, scalar };  // scalar: force the portable path (tests compare them)
  void set_kernel(Kernel kernel) { kernel_ = kernel; }

 private:
  // Puts this set on `layout` with `compliance` per group, its arrays at `slots` in `block`; rest
  // lengths and λ 0, not prepared.
  void adopt(std::shared_ptr<const DistanceLayout> layout, std::span<const double> compliance,
             ArrayBlock& block, const Slots& slots);
  // The same, in a block of its own.
  void adopt(std::shared_ptr<const DistanceLayout> layout, std::span<const double> compliance);
  // Constraint k's rest length, in its lane and in the lanes that repeat it (a batch not full).
  void set_rest_length(std::size_t k, double rest_length);

  std::shared_ptr<const DistanceLayout> layout_;
  ArrayView<LaneState> state_;    // per batch of the layout
  ArrayView<Params> params_;      // per class of the layout
  ArrayView<double> compliance_;  // per group
  ArrayView<double> w_built_;     // the inverse masses the params were derived for (when prepared_)
  bool prepared_ = false;         // prepare() has run since the layout was adopted
  std::vector<double> pending_;   // per constraint: compliances set by range, not yet grouped (tuning)
  Kernel kernel_ = Kernel::automatic;
  ArrayBlock own_;  // the arrays' block when they have one of their own; empty in a tire's
};

// Inline: the global method's assembly reads every constraint of a tire each solve.
inline DistanceConstraint DistanceConstraintSet::constraint(std::size_t k) const {
  const std::uint32_t s = layout_->slot()[k];
  const DistanceLayout::Pair p = layout_->pairs()[k];
  const double compliance = pending_.empty() ? compliance_[layout_->group()[k]] : pending_[k];
  return {p.a, p.b, state_[s / kLanes].rest_length[s % kLanes], compliance};
}

}  // namespace tire
