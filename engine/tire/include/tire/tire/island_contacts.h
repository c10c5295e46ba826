// The contacts between the tires of an island solved as one problem (issue 33, "one contact problem
// per island"; route B of the pile oracle, docs/at-rest.md). Block Gauss–Seidel (tire_neighbours.h)
// solves each tire against its neighbours held where a guess puts them, and a pile so solved creeps
// for ever: static friction between two tires anchors to where the other was captured, not to
// where it ends the substep.
//
// Here each tire of an island is first solved alone, with its own constraints and its contacts with
// the world (GlobalSolver), loaded with the island's last multipliers. The contacts between the
// island's tires, a tread particle p of tire a inside the tread of tire b against the edge (e₀, e₁)
// it crossed, at s along it, are then rows on both tires,
//     J_a = d at p,   J_b = −d (1 − s) at e₀ and −d s at e₁,
// a normal (d = n, the edge's outward normal) that takes back the gap, and a static friction
// (d = t) that takes back the particle's slip along the edge since its anchor was laid (Müller et
// al. 2020, Sec. 3.5, on the two tires' relative motion; the anchor, kept while the friction holds,
// makes it hold across substeps, as Box2D v3's friction anchors do). Each tire's contacts with
// fixed surfaces are rows on that tire alone: the static friction of those its solve holds (their
// normals stay in its response), the normal and friction of those it let go. The multipliers'
// totals solve
//     (D + α̃) λ = c + D λ_applied,   D = Σ_t J_t K̂₀_t⁻¹ J_tᵀ,
// λ_applied what the tires' solves hold already, D from each tire's exact response at its contact
// points without those frictions (GlobalSolver::respond), with one active set: a normal holds
// while λ_n ≥ 0, a friction while |λ_t| ≤ μ λ_n; a friction that lets go takes kinetic friction,
// what stops its slip up to μ λ_n, after the solve. The system is solved by conjugate gradients
// preconditioned by D's incomplete Cholesky factor, warm-started; if the active set still changes
// after its passes, projected Gauss–Seidel sweeps leave a feasible answer. Each tire moves by
// Δx_t = K̂₀_t⁻¹ J_tᵀ (λ − λ_applied): the solve alone plus this is the island's one linear system.
//
// An island of more tires than SolverConfig::island_tires, with two tires inside each other, or
// with more contacts than the room reserved, keeps block Gauss–Seidel; a contact on a tire whose
// own system holds a free prop is left out (its response is not symmetric).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <memory>
#include <span>
#include <utility>
#include <vector>

#include "tire/math/geometry.h"
#include "tire/tire/global_solver.h"
#include "tire/tire/soft_contact.h"
#include "tire/tire/tick_contacts.h"

namespace tire {

struct SubstepContext;
class RigidWorld;
class WorkerPool;

class IslandContacts {
 public:
  // Room for islands of up to `largest` tires of up to `segments` segments each, in a world of
  // `tires` tires (allocates; outside the step).
  void reserve(std::size_t largest, std::uint32_t segments, std::size_t tires);

  // Once a tick, after the broad phase: the awake tires in contact (`members`, joined by `pairs`)
  // sorted into islands; an island of at most `largest` tires is solved here, in groups that fit the
  // solvers reserved. An island with a tire near a dynamic prop keeps block Gauss–Seidel: the prop
  // is a body of that tire's own system, whose response is not symmetric, and the island's solve
  // left its contacts out; under a crate, a pile's tires sank into each other and threw it. So
  // does an island with two tires inside each other (hubs closer than half the larger radius).
  void set_islands(const std::vector<Tire>& tires, std::span<const std::uint32_t> members,
                   const std::vector<TirePair>& pairs, std::size_t largest, const RigidWorld& rigid);
  std::size_t groups() const { return group_begin_.empty() ? 0 : group_begin_.size() - 1; }
  // The tires of group g, in tire order within each island, islands in order of their first tire.
  std::span<const std::uint32_t> group_tires(std::size_t g) const {
    return {tires_.data() + group_begin_[g], tires_.data() + group_begin_[g + 1]};
  }
  // Whether tire i is solved here this iteration (false for a tire of an island that overflowed).
  bool solves(std::uint32_t tire) const {
    return tire < per_tire_.size() && per_tire_[tire].solves != 0 && overflow_[per_tire_[tire].group] == 0;
  }
  bool any() const { return !tires_.empty(); }

  // Each iteration, for each group: find() before its tires are solved (the candidates, where the
  // tires are predicted); each tire solved alone by solver_of(tire), with no neighbours; then solve(),
  // whose per-tire parts (the tires' responses, their moves) run on `pool` if one is given: each
  // sums what it sums in the same order on any thread, so the bits do not depend on it.
  void find(const std::vector<Tire>& tires, std::size_t group, double h);
  GlobalSolver& solver_of(const Tire& t) {
    return *solvers_[per_tire_[static_cast<std::size_t>(&t - first_)].slot];
  }
  void solve(std::vector<Tire>& tires, std::size_t group, const SubstepContext& ctx, WorkerPool* pool);

  // Counts since the start, for tests and `tirectl bench`.
  using Work = IslandWork;  // tick_contacts.h
  const Work& work() const { return work_; }

 private:
  struct Row {
    std::uint32_t a = 0, particle = 0;  // the particle of tire a
    std::uint32_t b = 0, e0 = 0, e1 = 0;
    double s = 0.0;  // along b's edge (e₀, e₁)
    Vec2 d;          // the normal (out of b) or the tangent
    double target = 0.0;
    double mu = 0.0;
    std::int32_t normal = -1;  // a friction row's normal row (itself when its normal is in K̂₀)
    double bound = -1.0;       // such a friction's Coulomb bound, μ μ_n of its tire's solve
    double lambda = 0.0;
    // What the tires' solves hold of the row: a tire row's last multiplier, put on the tires as a
    // load before their solves (find()); a surface row's μ from its tire's solve. The island's solve
    // adds K̂₀⁻¹ Jᵀ (λ − applied), and its right-hand side is c + D applied.
    double applied = 0.0;
    double rhs = 0.0;
    bool active = true;
    bool kinetic = false;  // a friction that starts sliding (its contact was let go)
    bool dropped = false;  // a twin left out (add_contacts)
    // Against a fixed surface of the world (an obstacle, a static or kinematic prop), held or let go
    // by tire a's solve: a row on tire a alone, its plane n·x = plane moving by surface_motion.
    bool surface = false;
    double plane = 0.0;
    Vec2 surface_motion;
    std::int32_t prop = -1;
    std::size_t wa = 0, wb = 0;  // the two tires' responses in w_
  };
  // What a friction row may hold: μ λ_n, or its fixed bound.
  double coulomb_bound(const Row& r) const {
    return r.bound >= 0.0 ? r.bound : r.mu * rows_[static_cast<std::size_t>(r.normal)].lambda;
  }
  // J_{row, side}·w: how far w moves the row's point of that tire along d.
  static double along(const Row& r, bool side_a, const double* w, std::uint32_t n);
  // v += J_{row, side}ᵀ scale: the row's force on that tire, in block order (GlobalSolver::dof).
  static void spread(const Row& r, bool side_a, double scale, double* v, std::uint32_t n);
  // The row's multiplier after one Gauss–Seidel step on (D + α̃) λ = rhs, the others held.
  double relaxed(std::size_t row, double alpha_tilde) const;
  // Σ over the row's entries of D times the other rows' `multiplier` (λ, or the applied loads).
  double d_times(std::size_t row, double Row::*multiplier) const;
  bool add_contacts(const Tire& ta, std::uint32_t a, const Tire& tb, std::uint32_t b,
                    std::size_t first_of_pair);
  void index_rows_by_tire(std::size_t tires_in_group);
  void load_tires(const std::vector<Tire>& tires, std::span<const std::uint32_t> members, double h);
  bool add_surface_rows(const std::vector<Tire>& tires, std::span<const std::uint32_t> members);
  bool assemble(const std::vector<Tire>& tires);
  bool incomplete_cholesky(double shift);
  bool solve_active(double alpha_tilde);
  void write_records(std::vector<Tire>& tires, const SubstepContext& ctx) const;

  // A row between tires' contact: the particle of tire a against tire b.
  static std::uint64_t key(const Row& r) { return key(r.a, r.particle, r.b); }
  static std::uint64_t key(std::uint32_t a, std::uint32_t particle, std::uint32_t b) {
    return (std::uint64_t{a} << 40) | (std::uint64_t{particle} << 24) | b;
  }
  // A row's multiplier's key in the lists of them: its contact's, × 2, + 1 for a friction.
  static std::uint64_t lambda_key(const Row& r) { return key(r) * 2 + (r.normal >= 0 ? 1 : 0); }
  // The multiplier of row key k (× 2, + 1 for a friction) in a list of them sorted, or 0.
  static double lambda_in(const std::vector<std::pair<std::uint64_t, double>>& list, std::uint64_t k) {
    const auto it =
        std::lower_bound(list.begin(), list.end(), std::pair<std::uint64_t, double>{k, -HUGE_VAL});
    return it != list.end() && it->first == k ? it->second : 0.0;
  }
  // Whether the normal of particle's contact on tire b held in the last iteration.
  bool held(std::uint32_t a, std::uint32_t particle, std::uint32_t b) const {
    return lambda_in(last_lambda_, key(a, particle, b) * 2) > 0.0;
  }

  const Tire* first_ = nullptr;  // the world's tires, as find() saw them
  std::size_t largest_ = 0;      // tires the solvers were reserved for
  std::size_t max_rows_ = 0;
  std::size_t max_entries_ = 0;
  std::vector<std::unique_ptr<GlobalSolver>> solvers_;
  // set_islands': per tire its island's root (union–find), the islands' tires grouped, the pairs
  // of each group, and per tire its solver's slot and whether it is solved here.
  struct Member {
    std::uint32_t root = 0;    // union–find's
    std::uint32_t size = 0;    // a root's: its island's tires
    std::uint32_t cursor = 0;  // a root's: where its island's next tire goes in tires_
    std::uint32_t slot = 0;    // its solver's, in its group
    std::uint32_t group = 0;
    std::uint8_t solves = 0;  // whether it is solved here
    bool near_prop = false;   // a root's: a tire of its island is near a dynamic prop
    bool tangled = false;     // a root's: two tires of its island are inside each other
  };
  std::vector<Member> per_tire_;
  std::vector<std::uint32_t> tires_;
  std::vector<std::uint32_t> group_begin_;
  std::vector<TirePair> pairs_;
  std::vector<std::uint32_t> pair_begin_;  // per group
  std::vector<std::uint8_t> overflow_;     // per group: this iteration's contacts did not fit
  // The group being solved.
  std::vector<Row> rows_;
  std::vector<std::uint32_t> rows_of_tire_begin_;  // per slot: its rows in rows_of_tire_
  std::vector<std::uint32_t> rows_of_tire_;
  std::vector<double> w_;
  // Per slot, from dof_begin_ (where its tire's unknowns start): Σ Jᵀ applied over its rows, and
  // the island's Δx of its tire.
  std::vector<std::size_t> dof_begin_;
  std::vector<double> load_;
  std::vector<double> correction_;
  std::vector<std::uint32_t> entry_begin_;  // D by rows: its columns and values
  std::vector<std::uint32_t> entry_column_;
  std::vector<double> entry_value_;
  std::vector<std::uint8_t> live_;  // per row: in this pass's system
  // The live rows' system, compacted for conjugate gradients: the rows, and D + α̃ on them by rows.
  std::vector<std::uint32_t> live_rows_;
  std::vector<std::uint32_t> live_slot_;  // per row: where it sits among the live rows, if live
  std::vector<std::uint32_t> live_begin_;
  std::vector<std::uint32_t> live_column_;
  std::vector<double> live_value_;
  std::vector<double> x_, r_, z_, p_, q_, diagonal_;           // per live row
  std::vector<double> ic_value_;                               // L of incomplete_cholesky, on live_'s pattern
  std::vector<std::uint32_t> ic_diagonal_;                     // per live row: where L_jj is in ic_value_
  std::vector<std::uint8_t> ready_;                            // per slot: its response is to be had
  std::vector<std::pair<std::uint64_t, double>> last_lambda_;  // by key × 2 + friction, sorted
  std::vector<std::pair<std::uint64_t, double>> older_lambda_;  // the iteration's before, sorted
  // The substep each list was solved at: one solved at another h (the refinement changed the
  // substeps between ticks) is rescaled as it is loaded (load_tires).
  double last_h_ = 0.0, older_h_ = 0.0, next_h_ = 0.0;
  // Where a stuck contact's particle was laid on the other tread: at s along b's edge (e0, e0 + 1).
  struct Anchor {
    std::uint64_t key = 0;
    std::uint32_t e0 = 0;
    double s = 0.0;
  };
  std::vector<Anchor> anchors_, next_anchors_;  // by key, the last iteration's sorted
  const Anchor* anchor_of(std::uint64_t k) const {
    const auto it = std::lower_bound(anchors_.begin(), anchors_.end(), k,
                                     [](const Anchor& a, std::uint64_t v) { return a.key < v; });
    return it != anchors_.end() && it->key == k ? &*it : nullptr;
  }
  std::vector<std::pair<std::uint64_t, double>> next_lambda_;
  Work work_;
};

}  // namespace tire
