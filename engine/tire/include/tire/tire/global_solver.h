// The global method (issue 13): each iteration of a substep solves all of one tire's constraints
// and its contacts with obstacles and props as one linear system, so a load reaches every part of
// the tire at once and the tire's stiffness is its compliances' at any substep count.
//
// The system is XPBD's linearised step (Macklin et al. 2016, eq. 9–10) for all constraints at once.
// Its distance constraints (α > 0) are taken in the primal form, which the Woodbury identity makes
// equal to the dual form (J W Jᵀ + α̃) Δλ = −C − α̃ λ:
//     K Δx = f + Gᵀ μ,   K = M + (1 + γ) Jᵀ α̃⁻¹ J,   f = −M (x − x̃) − Jᵀ α̃⁻¹ (C + γ J (x − xₙ)),
// with x̃ the predicted positions, xₙ those at the substep's start and γ = α̃ β̃ / h = τ / h the
// constraint damping of XPBD eq. 26 for the tire's Kelvin–Voigt time τ (material_damping). K is
// the mass matrix plus the stiffness of every distance constraint: with the unknowns ordered
// segment by segment it is block tridiagonal with a cyclic wrap (CyclicBlockCholesky).
// The other constraints keep their multipliers μ as unknowns (a small dense "capacitance" system,
// one row each): the two area constraints (their gradients are dense over a ring), the mouse grab,
// and each contact's normal (α = 0, μ ≥ 0) and static-friction row (α = 0, |μ_t| ≤ μ_s μ_n, as in
// Müller et al. 2020, Sec. 3.5; kinetic friction stays in the velocity pass, Sec. 3.6):
//     (G K⁻¹ Gᵀ + α̃_G/(1 + γ) + D) μ = b − G K⁻¹ f,
// D being what a dynamic prop gives way (its generalised inverse mass, Müller 2020 eq. 2–3).
// Which contacts are in the system is found by active-set passes. Each iteration solves for the
// multipliers' totals, not increments, so nothing is carried from one iteration to the next but x.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "tire/tire/tire.h"
#include "tire/xpbd/cyclic_block_cholesky.h"

namespace tire {

struct SubstepContext;

// Scratch for solving one tire, reused tire after tire: sized by reserve(), never allocated in a step.
class GlobalSolver {
 public:
  // Contacts (particles touching an obstacle or a prop) a tire may have in one substep's system;
  // further penetrating particles wait for the next substep (a crushed tire of 64 segments has all
  // of its tread down).
  static constexpr std::uint32_t kMaxContacts = 64;

  // Room for tires of up to `segments` segments (allocates).
  void reserve(std::uint32_t segments);
  std::uint32_t capacity() const { return segments_; }

  // One iteration of the substep for `tire` (called where Gauss–Seidel would sweep once): solves the
  // system, moves the particles, and leaves the contact records (and the impulses owed to props)
  // as the Gauss–Seidel contacts would.
  void solve(Tire& tire, const SubstepContext& ctx);

  // Work done by the last solve(), for tests and the bench.
  struct Counts {
    std::uint32_t rows = 0;      // dense rows made (areas, grab, contact normals and friction)
    std::uint32_t passes = 0;    // active-set passes
    std::uint32_t contacts = 0;  // contacts in the system at the end
  };
  const Counts& counts() const { return counts_; }

 private:
  enum class RowKind : std::uint8_t { tread_area, rim_area, grab, normal, friction };
  struct Row {
    explicit Row(RowKind k) : kind(k) {}
    RowKind kind;
    bool active = true;
    std::uint32_t particle = 0;  // grab, normal, friction
    std::int32_t contact = -1;   // normal, friction: index into contacts_
    Vec2 direction;              // normal, friction, grab: the gradient at the particle
    double alpha_tilde = 0.0;    // α̃/(1 + γ)
    double b = 0.0;              // the row's right-hand side: −C (and its damping term)
    double yf = 0.0;             // (L⁻¹ g)·(L⁻¹ f)
    double mu = 0.0;             // its multiplier, from the last pass
  };
  struct Contact {
    std::uint32_t particle = 0;
    Vec2 normal;                // unit, out of the surface
    double plane = 0.0;         // C(x) = normal·x − plane
    Vec2 surface_displacement;  // of the surface point over the substep (moving props)
    Vec2 surface_velocity;
    std::int32_t prop = -1;     // the prop, or −1 for an obstacle
    double mu_static = 0.0;
    double mu_kinetic = 0.0;
    // For a dynamic prop: the arm from its centre of mass and its mobility along ±n and ±t.
    Vec2 arm;
    double mobility_n = 0.0;
    double mobility_t = 0.0;
    double inverse_mass = 0.0;
    double inverse_inertia = 0.0;
    std::int32_t normal_row = -1;
    std::int32_t friction_row = -1;
  };

  void assemble(const Tire& t, const SubstepContext& ctx, double gamma);
  std::uint32_t add_row(const Tire& t, const Row& row, const double* gradient);
  void add_ring_area_row(const Tire& t, const SubstepContext& ctx, RowKind kind, double gamma);
  void add_contact_rows(const Tire& t, std::int32_t contact, bool friction);
  // Finds the particles of `t` that penetrate a surface at positions x + dx (dx may be null) and
  // have no contact yet; adds a contact and its rows for each. True when any was added.
  bool find_contacts(const Tire& t, const SubstepContext& ctx, const double* dx);
  // Solves the capacitance system on the active rows; sets each row's mu and dx_.
  void solve_active(const Tire& t);
  double row_coupling(const Row& a, const Row& b) const;  // D_ab
  void write_back(Tire& t, const SubstepContext& ctx);

  std::uint32_t segments_ = 0;
  std::uint32_t max_rows_ = 0;
  std::size_t stride_ = 0;  // 4 × capacity: the length of one y column
  CyclicBlockCholesky k_;
  std::vector<double> f_;   // f, then L⁻¹ f
  std::vector<double> dx_;  // the last pass's Δx, in block order
  std::vector<double> work_;
  std::vector<Row> rows_;
  std::vector<double> y_;     // column r: L⁻¹ g_r
  std::vector<double> gram_;  // (L⁻¹ g_a)·(L⁻¹ g_b), max_rows_ × max_rows_
  std::vector<double> s_;     // the active rows' capacitance matrix, then its Cholesky factor
  std::vector<double> rhs_;
  std::vector<std::uint32_t> active_;
  std::vector<Contact> contacts_;
  std::vector<double> depth_;             // find_contacts: the depth of each new contact
  std::vector<std::int32_t> contact_of_;  // per particle: its contact, or −1
  std::vector<Vec2> gradient_;            // a ring's area gradient
  Counts counts_;
};

// One GlobalSolver per thread that may solve tires at once: lend() hands out one no other thread
// holds (tires are solved in parallel, and a solver is only scratch, so which one a tire gets never
// changes a result).
class GlobalSolverPool {
 public:
  GlobalSolverPool() = default;
  GlobalSolverPool(GlobalSolverPool&&) noexcept = default;
  GlobalSolverPool& operator=(GlobalSolverPool&&) noexcept = default;

  // `slots` solvers with room for `segments` segments (allocates; call outside the step).
  void reserve(unsigned slots, std::uint32_t segments);
  bool empty() const { return solvers_.empty(); }

  class Lease {
   public:
    Lease(GlobalSolverPool& pool, std::size_t slot) : pool_(&pool), slot_(slot) {}
    Lease(const Lease&) = delete;
    Lease& operator=(const Lease&) = delete;
    ~Lease() { pool_->busy_[slot_].store(false, std::memory_order_release); }
    GlobalSolver& operator*() const { return *pool_->solvers_[slot_]; }
    GlobalSolver* operator->() const { return pool_->solvers_[slot_].get(); }

   private:
    GlobalSolverPool* pool_;
    std::size_t slot_;
  };
  Lease lend();

 private:
  std::vector<std::unique_ptr<GlobalSolver>> solvers_;
  std::unique_ptr<std::atomic<bool>[]> busy_;
};

}  // namespace tire
