// Distance constraint C(x) = |x_b − x_a| − L0 (Macklin et al. 2016, "XPBD", Sec. 5; Müller et al.
// 2007, "Position Based Dynamics", Sec. 3.3), solved with XPBD compliance and accumulated λ, plus a
// dashpot in parallel (Kelvin–Voigt) applied to velocities. Its gradient is ∇_{x_b}C = n =
// (x_b − x_a)/|x_b − x_a| = −∇_{x_a}C; when the two particles coincide it is undefined, taken as
// zero: λ still accumulates, nothing moves. (tests/test_distance_constraint.cpp reads the gradient
// the solver used off one projection and compares it with finite differences of C.)
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "tire/math/prefetch.h"
#include "tire/math/vec2.h"

namespace tire {

struct DistanceConstraint {
  std::uint32_t a = 0;
  std::uint32_t b = 0;
  double rest_length = 0.0;  // L0 (m)
  double compliance = 0.0;   // α (m/N): inverse stiffness; 0 is rigid
};

// A set of distance constraints laid out for the solver: in their Gauss–Seidel order, cut into
// batches of up to four that share no particle, stored lane by lane. Constraints in a batch are
// independent, so solving them together is exactly solving them one after the other, and one
// vector instruction serves all four (AVX where the CPU has it; otherwise the same arithmetic lane
// by lane, which gives the same bits: IEEE sqrt and division are correctly rounded either way).
class DistanceConstraintSet {
 public:
  static constexpr int kLanes = 4;

  DistanceConstraintSet() = default;
  explicit DistanceConstraintSet(std::vector<DistanceConstraint> constraints);

  const std::vector<DistanceConstraint>& constraints() const { return constraints_; }
  // Changes the compliance of constraints [first, first + count) (live tuning); takes effect at
  // the next prepare().
  void set_compliance(std::size_t first, std::size_t count, double compliance);
  std::size_t size() const { return constraints_.size(); }
  std::size_t batch_count() const { return batches_.size(); }

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
    tire::prefetch(batches_);
    tire::prefetch(params_of_);
  }

  enum class Kernel { automatic, scalar };  // scalar: force the portable path (tests compare them)
  void set_kernel(Kernel kernel) { kernel_ = kernel; }

 private:
  // What one sweep reads and writes for four constraints, 96 bytes: in a scene of a thousand tires
  // the batches are most of what streams from memory every substep. A batch that is not full
  // repeats its first lane (see build_batches).
  struct alignas(32) Batch {
    static constexpr std::uint32_t kLanes = DistanceConstraintSet::kLanes;
    std::uint32_t a[kLanes];
    std::uint32_t b[kLanes];
    double rest_length[kLanes];
    double lambda[kLanes];
  };
  static_assert(sizeof(Batch) == 24 * kLanes);
  // What the four lanes of a batch share: the lanes of a batch are built to have one compliance and
  // one pair of inverse masses, so these are a few per set (one per kind of constraint), not four
  // per batch.
  struct Params {
    double compliance = 0.0;       // α
    double w_a = 0.0;
    double w_b = 0.0;
    double alpha_tilde = 0.0;      // α̃ = α/h²
    double inv_denominator = 0.0;  // 1 / (w_a + w_b + α̃); 0 for a pinned pair
    double damping = 0.0;          // τh / (α + τh(w_a + w_b)): dashpot impulse per unit of dC/dt
  };
  // Cuts the constraints, in order, into batches whose lanes share no particle and share Params
  // under inverse masses `w` (null: all equal).
  void build_batches(const double* w);

  std::vector<DistanceConstraint> constraints_;
  std::vector<Batch> batches_;
  std::vector<std::uint32_t> params_of_;  // per batch: its entry in params_
  std::vector<Params> params_;
  std::vector<std::uint32_t> slot_;  // constraint k is lane slot_[k] % kLanes of batch slot_[k] / kLanes
  std::size_t particle_count_ = 0;   // 1 + the highest particle index any constraint names
  std::vector<double> w_built_;      // the inverse masses the batches were built for (empty: none yet)
  bool rebuild_ = false;             // a compliance changed: build again at the next prepare()
  Kernel kernel_ = Kernel::automatic;
};

}  // namespace tire
