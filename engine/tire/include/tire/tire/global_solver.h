// The global method (issue 13): each iteration of a substep solves all of one tire's constraints
// and its contacts with obstacles and props as one linear system, so a load reaches every part of
// the tire at once and the tire's stiffness is its compliances' at any substep count.
//
// The system is XPBD's linearised step (Macklin et al. 2016, eq. 9–10) for all constraints at once.
// Its distance constraints (α > 0) are taken in the primal form, which the Woodbury identity makes
// equal to the dual form (J W Jᵀ + α̃) Δλ = −C − α̃ λ:
//     K Δx = f + Gᵀ μ,   K = M + (1 + γ) Jᵀ α̃⁻¹ J,   f = −M (x − x̃) − Jᵀ α̃⁻¹ (C + γ ΔC),
// with x̃ the predicted positions, xₙ those at the substep's start and γ = α̃ β̃ / h = τ / h the
// constraint damping of XPBD eq. 26 for the tire's Kelvin–Voigt time τ (material_damping), its
// rate ∇C·(x − xₙ) taken as ΔC = C(x) − C(xₙ) (equal to first order; zero for a rigid turn). K is
// the mass matrix plus the stiffness of every distance constraint: with the unknowns ordered
// segment by segment it is block tridiagonal with a cyclic wrap (CyclicBlockCholesky).
// Contacts are rows of one particle each, constraints of compliance SolverConfig::rigid_compliance
// (10 nm under a tire's weight): the normal C = n·x − plane with μ_n ≥ 0, and static friction
// t·(x − xₙ − surface motion) = 0 while |μ_t| ≤ μ_s μ_n (Müller et al. 2020, Sec. 3.5; kinetic
// friction stays in the velocity pass, Sec. 3.6). The normals go into K, which keeps its shape. The
// first few frictions are rows of the capacitance system below instead, since they are what the
// active-set passes change most (a tire driven flat out spins its wheels, and 39 % of its solves
// let a contact's friction go after the first pass): a pass that only lets frictions go, or takes
// in new contacts, solves on the factor it has, dropping those rows or adding some (Woodbury), and
// refactors K only when a normal in K lets go or a free prop's contact changes.
//
// A free dynamic prop (one Box2D holds on nothing: it moves within the tick as it is pushed) is a
// rigid body in the system: its displacement q = (u, θ) over the substep is three more unknowns,
// with its mass and inertia as their M and each of its contacts a constraint C = d·x − plane − a·q,
// a = (d, r × d) (Müller 2020 eq. 2–3), so that all its contacts with the tire move it together, by
// what they push in total. (Each contact taking the prop's give alone, its generalised inverse mass,
// as the Gauss–Seidel contacts do, lets every contact move it as if the others were not there, and
// the prop then moves by their sum: a 6 kg crate lying on a tire at 2 substeps bounced on it by
// 1.3 cm for ever.) A prop resting on something stays on its course within the tick
// (rigid_world.h): its contacts keep that give, scaled by its mobility. Which contacts are in is
// found by active-set passes.
//
// The two area constraints (their gradients are dense over a ring), the mouse grab and those
// contact rows keep their multipliers μ as unknowns, a small dense "capacitance" system:
//     (G K⁻¹ Gᵀ + α̃_G/(1 + γ)) μ = b − G K⁻¹ f,   then Δx = K⁻¹ (f + Gᵀ μ).
// The free props' displacements join them as a border of three columns each, B = ∂²E/∂x∂q:
//     [ S_GG + α̃    −Y_Gᵀ Y_B      ] [ μ  ]   [ b − Y_Gᵀ L⁻¹ f  ]
//     [ Y_Bᵀ Y_G     K_qq − Y_Bᵀ Y_B ] [ Δq ] = [ f_q − Y_Bᵀ L⁻¹ f ],   Y = L⁻¹ [Gᵀ B],
// then Δx = K⁻¹ (f + Gᵀ μ − B Δq); K_qq = diag(M, M, I) + Σ k a aᵀ over the prop's contacts.
// Each iteration solves for the multipliers' totals, not increments, so nothing is carried from one
// iteration to the next but x and which contacts hold.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "tire/tire/tire.h"
#include "tire/xpbd/cyclic_block_cholesky.h"

namespace tire {

struct SubstepContext;
struct Prop;

// Scratch for solving one tire, reused tire after tire: sized by reserve(), never allocated in a step.
class GlobalSolver {
 public:
  // Room for tires of up to `segments` segments (allocates).
  void reserve(std::uint32_t segments);
  std::uint32_t capacity() const { return segments_; }

  // One iteration of the substep for `tire` (called where Gauss–Seidel would sweep once): solves the
  // system, moves the particles, and leaves the contact records (and the impulses owed to props)
  // as the Gauss–Seidel contacts would.
  void solve(Tire& tire, const SubstepContext& ctx);

  // The tire's response to a load, after solve(): w = K̂₀⁻¹ r, the displacement a force r (kg·m,
  // force × h², in block order: dof()) adds to the solve's Δx. K̂₀ is the solve's last system with
  // the normals of the contacts it holds, but without the static frictions of its contacts with
  // fixed surfaces (obstacles, static and kinematic props): an island's solve takes those as rows
  // of its own, with their Coulomb limit (island_contacts.h). Held in K̂₀ as equalities, they let
  // the island push a tire as if glued to the ground. Its areas and grab are held as constraints,
  // the Schur complement
  //     w = L₀⁻ᵀ (u + Y₀ δμ),  u = L₀⁻¹ r,  (Y₀ᵀ Y₀ + α̃) δμ = −Y₀ᵀ u.
  // prepare_response() factors K₀ and the rows' system once (one factorisation); false when the
  // tire's system holds a free prop (its border is not symmetric) or a factor fails. respond()
  // works in place on r. With `hold_fixed_friction`, K̂₀ holds the static frictions of the contacts
  // with fixed surfaces too (as equalities): a vehicle's axle pushing its wheel rolls it about its
  // contact patch (vehicle_joints.h).
  bool prepare_response(bool hold_fixed_friction = false);
  // The same with every friction held, from the last solve's own system instead of a factorisation
  // of its own: that solve's factor of K and its live rows (its frictions and contacts taken in as
  // rows among them), the system its Δx solved, which holds the normals and the static frictions of
  // its contacts (a vehicle's wheel: vehicle_joints.h). False when it holds a free prop.
  bool prepare_solve_response();
  void respond(double* r) const { respond(&r, 1); }
  // The same for `count` loads at once (at most CyclicBlockCholesky::kMaxRightHandSides): one sweep
  // down the factor for all of them.
  void respond(double* const* rs, std::size_t count) const;
  // respond() in its two halves, for loads whose responses are wanted only combined: the first
  // leaves each r as its half-response ŵ = u + Y₀ δμ (respond's before its sweep up the factor)
  // and, when `gram` is given, gram[i][j] = rᵢ · K̂₀⁻¹ rⱼ = uᵢ·uⱼ + (Y₀ᵀuᵢ)·δμⱼ (symmetric);
  // respond_backward(Σ cᵢ ŵᵢ) is then K̂₀⁻¹ Σ cᵢ rᵢ, one sweep up for the combination.
  using Gram = double[CyclicBlockCholesky::kMaxRightHandSides][CyclicBlockCholesky::kMaxRightHandSides];
  void respond_forward(double* const* rs, std::size_t count, Gram* gram = nullptr) const;
  void respond_backward(double* r) const;
  // A load on the next solve only: a force r (kg·m, force × h², in block order: dof()) added to its
  // f, as the tire's neighbours push it (an island's last multipliers, island_contacts.h). The
  // solve reads it and forgets it; r must live until then.
  void load_next_solve(const double* r) { load_ = r; }
  // The last solve's contacts with fixed surfaces, held or let go: f(particle, normal, plane,
  // surface displacement over the substep, the point static friction holds the particle to (slip),
  // static friction, prop or −1, held, μ_n, μ_t), the multipliers (kg·m) its Δx holds of them (0 for
  // what it did not hold). respond() holds the normals of those held, and none of their frictions.
  template <class F>
  void for_each_fixed_contact(const Particles& p, F&& f) const {
    for (const Contact& c : contacts_)
      if (c.fixed)
        f(c.particle, c.normal, c.plane, c.surface_displacement,
          c.anchored ? c.anchor : p.x_prev[c.particle] + c.surface_displacement, c.mu_static, c.prop,
          c.normal_active, c.mu_n, c.mu_t);
  }
  // The largest angle (rad) by which a displacement dx (in block order: dof()) of the tire's
  // particles from where they are turns one of its distance constraints, as assembled by the last
  // solve: past SolverConfig::refine_turn the linearised step no longer holds.
  double largest_turn(const Tire& t, const double* dx) const;
  // Where particle i's (x, y) sit in a vector of the tire's unknowns (respond's r and w).
  // Block k holds tread particle k (x, y) and then rim particle k + n (n segments), so that every
  // constraint of the tire couples a block to itself or to a neighbouring block.
  static std::uint32_t block(std::uint32_t particle, std::uint32_t segments) {
    return particle < segments ? particle : particle - segments;
  }
  static std::size_t offset(std::uint32_t particle, std::uint32_t segments) {
    return particle < segments ? 0 : 2;
  }
  static std::size_t dof(std::uint32_t particle, std::uint32_t segments) {
    return CyclicBlockCholesky::kBlock * block(particle, segments) + offset(particle, segments);
  }
  std::size_t unknowns() const { return k_.size(); }

 private:
  // A row of the capacitance system, g·Δx + α̃ μ = b with K Δx = f + g μ: an area constraint, the
  // grab, or a contact's friction or normal (g the direction d at its particle, b its target
  // displacement along d, α̃ its compliance: μ is then its force × h²).
  struct Row {
    double alpha_tilde = 0.0;  // α̃/(1 + γ)
    double b = 0.0;            // the right-hand side: −(C + γ ΔC)/(1 + γ)
    double yf = 0.0;           // (L⁻¹ g)·(L⁻¹ f)
    double mu = 0.0;           // its multiplier, from the last pass
    std::size_t first = 1;     // the first block of the chain where L⁻¹ g is not zero (forward())
    bool live = true;          // false once its contact has let it go
  };
  // A particle against an obstacle or a prop. Its normal (and static friction) are constraints of
  // compliance rigid_compliance, plus what a dynamic prop gives way: in K (each touches one
  // particle, so K keeps its shape) or rows (row_n, row_t; see the file's comment).
  struct Contact {
    std::uint32_t particle = 0;
    Vec2 normal;                // unit, out of the surface
    double plane = 0.0;         // C(x) = normal·x − plane
    Vec2 surface_displacement;  // of the surface point over the substep (moving props)
    Vec2 surface_velocity;
    // On a dynamic prop, stuck since an earlier substep: where it stuck, as the prop will stand at
    // the substep's end (Tire::friction_anchor); static friction holds the particle there.
    bool anchored = false;
    Vec2 anchor;
    std::int32_t prop = -1;  // the prop, or −1 for an obstacle
    std::int32_t body = -1;  // the prop's slot in bodies_ when it is in the system, else −1
    Vec2 arm;                // from the prop's centre to the particle (a body's contacts)
    std::int32_t tire = -1;  // or the other tire (tire_neighbours.h), against its tread edge at point
    std::uint32_t edge = 0;
    Vec2 point;
    double mu_static = 0.0;
    double mu_kinetic = 0.0;
    double stiffness_n = 0.0;  // 1/(α̃ + D): D a dynamic prop's generalised inverse mass along n
    double stiffness_t = 0.0;  // the same along the tangent
    double give_t = 0.0;       // a neighbour tire's give along the tangent (tire_neighbours.h)
    bool fixed = false;        // against an obstacle or a prop that is not dynamic: it gives nothing
    bool normal_active = true;
    bool friction_active = true;
    bool normal_in_k = false;  // what K holds of it since it was last factored
    bool friction_in_k = false;
    std::int32_t row_n = -1;  // its rows, or −1
    std::int32_t row_t = -1;
    double mu_n = 0.0;  // multipliers from the last pass (kg·m: force × h²)
    double mu_t = 0.0;
  };

  // What static friction takes back of a contact's particle at x: its slip over the substep against
  // the surface's motion, or since it stuck when it is anchored.
  static Vec2 slip(const Contact& c, Vec2 x, const Particles& p) {
    return c.anchored ? x - c.anchor : x - p.x_prev[c.particle] - c.surface_displacement;
  }

  // A free dynamic prop in the system: its three unknowns q = (u.x, u.y, θ).
  struct Body {
    std::uint32_t prop = 0;
    double mass = 0.0;
    double inertia = 0.0;
    double kqq[3][3] = {};  // K_qq
    double fq[3] = {};      // f_q
    double dq[3] = {};      // the last pass's Δq
  };
  // The prop's slot in bodies_, added if there is room (kMaxBodies), or −1.
  std::int32_t body_of(std::uint32_t prop, const Prop& body);
  // Along d at a body's contact with arm r: a = (d, r × d), what q moves the prop's point along d.
  static double along(const Body& b, Vec2 d, Vec2 r) {
    return d.x * b.dq[0] + d.y * b.dq[1] + cross(r, d) * b.dq[2];
  }
  // The small dense system of the rows and the bodies (at most kMaxUnknowns), by Gaussian
  // elimination with partial pivoting: false when it is singular or not finite.
  bool solve_border(std::size_t size);

  void assemble(const Tire& t, const SubstepContext& ctx, double gamma);
  void add_ring_area_row(const Tire& t, const SubstepContext& ctx, bool rim, double gamma);
  double* gradient_of(std::size_t row) { return g_.data() + row * stride_; }
  Contact make_contact(const Tire& t, const SubstepContext& ctx, std::uint32_t particle, Vec2 normal,
                       double plane, const ContactPair& pair, std::int32_t prop, Vec2 surface_velocity);
  // The roll held by rolling resistance (Tire::rolling_held): a row C(x) = Σ g_i·(x_i − xₙ_i) = 0,
  // the tire's turn over the substep about its centroid, linearised at the substep's start,
  // g_i = m_i perp(r_i) / Σ m_j |r_j|² with r_i = xₙ_i − cₙ (the translation drops out: Σ m_i r_i = 0).
  // Its multiplier is the moment that holds it times h²; update_active_set lets it go past
  // C_rr·N·R (N from the contacts' multipliers), as Coulomb's law lets a friction go.
  void add_rolling_row(const Tire& t);
  // Finds the particles of `t` that penetrate a surface (an obstacle, a prop or a neighbour's tread)
  // at x + dx (dx null: at x) and have no contact yet, and adds a contact for each, the deepest
  // where a particle meets several. True when any was added.
  bool find_contacts(const Tire& t, const SubstepContext& ctx, const double* dx);
  // find_contacts' share for the neighbours' treads: a tread particle inside one, against the edge
  // it crossed; `first_new` as there.
  void find_tire_contacts(const Tire& t, const SubstepContext& ctx, const double* dx, std::size_t first_new);
  // Puts c in the system, in place of the particle's contact if it has one; `depth` its penetration.
  void offer(const Contact& c, double depth);
  // One active-set pass: K with the active contacts' normals (and frictions beyond
  // kMaxFrictionRows, and a free prop's), factored; the other frictions as rows. False when K could
  // not be factored (not finite).
  bool solve_pass(const Tire& t);
  // An active-set pass on the factor the last solve_pass left: frictions that let go drop their
  // rows, contacts K does not hold come in as rows. False when the changes need K refactored (a
  // normal in K let go, a free prop's contact changed, no room for the rows) or it failed.
  bool solve_changes(const Tire& t);
  // Appends a contact's row along d (at most kMaxRows), its L⁻¹ g still to compute; its index, or −1.
  std::int32_t add_contact_row(const Tire& t, const Contact& c, Vec2 d, double target, double stiffness);
  // L⁻¹ g of rows [first, rows_.size()) (in y_), four at a time, f_ first when with_f.
  void forward_rows(std::size_t first, bool with_f);
  // The capacitance system of the live rows and the bodies, then Δx and each contact's multipliers.
  bool solve_system(const Tire& t);
  // Drops contacts that pull and friction that cannot hold; takes back released contacts that Δx
  // would push into their surface. True when anything changed.
  bool update_active_set(const Tire& t, const SubstepContext& ctx);
  void write_back(Tire& t, const SubstepContext& ctx);

  static constexpr std::size_t kBaseRows = 4;         // the two areas, the grab and the roll
  static constexpr std::size_t kMaxFrictionRows = 4;  // frictions as rows after a factorisation
  static constexpr std::size_t kMaxChangeRows = 4;    // and contacts taken in on its factor
  static constexpr std::size_t kMaxRows = kBaseRows + kMaxFrictionRows + kMaxChangeRows;
  static constexpr std::size_t kMaxBodies = 2;  // free props in one tire's system; more keep their give
  static constexpr std::size_t kMaxUnknowns = kMaxRows + 3 * kMaxBodies;

  std::uint32_t segments_ = 0;
  std::size_t stride_ = 0;  // 4 × capacity: the length of one column
  CyclicBlockCholesky k_;
  std::vector<Block4> base_diagonal_;  // K without the contacts
  std::vector<Block4> base_coupling_;
  std::vector<double> base_f_;    // f without the contacts
  const double* load_ = nullptr;  // load_next_solve's, until the solve adds it to base_f_
  std::vector<double> f_;         // f with them, then L⁻¹ f
  std::vector<double> dx_;        // the last pass's Δx, in block order
  std::vector<Row> rows_;
  std::size_t base_rows_ = 0;      // the areas', the grab's and the roll's, first in rows_
  std::int32_t rolling_row_ = -1;  // the roll's row in rows_ (add_rolling_row), or −1
  std::vector<double> g_;          // column r: the gradient g_r
  std::vector<double> y_;          // column r: L⁻¹ g_r
  std::vector<double> yb_;         // column 3j + c: L⁻¹ of body j's column c of B
  std::vector<Body> bodies_;
  double border_[kMaxUnknowns][kMaxUnknowns + 1] = {};  // the border system, its right side last
  std::vector<Contact> contacts_;
  std::vector<std::int32_t> contact_of_;  // per particle: its contact, or −1
  std::vector<double> depth_;             // find_contacts: the depth of each contact found
  std::vector<Vec2> gradient_;            // a ring's area gradient, or the tire's turn's
  // The tire's distance constraints as assemble() found them: their particles and unknowns, and
  // their gradient n = ∇_b C, force term (C + γ ΔC)/α̃ and stiffness (1 + γ)/α̃ (0: no gradient).
  struct Link {
    std::uint32_t a = 0, b = 0;
    std::size_t dof_a = 0, dof_b = 0;
    Vec2 normal;
    double force = 0.0;
    double stiffness = 0.0;
    double transverse = 0.0;  // geometric stiffness across the link, max(0, force)/length
  };
  static constexpr std::size_t kMaxLinksPerSegment = 8;  // a tire has 3 (radial spokes) or 5 (cross)
  std::vector<Link> links_;
  double rigid_alpha_tilde_ = 0.0;  // rigid_compliance / h²
  Tire::GlobalWork work_;           // the current solve's, added to the tire's at its end
  // prepare_response's: K₀ factored, the live base rows, their Y₀ = L₀⁻¹ g and the Cholesky factor
  // of their Y₀ᵀ Y₀ + α̃ (lower triangle).
  CyclicBlockCholesky k0_;
  std::vector<double> y0_;  // column q: L₀⁻¹ g of the q-th live base row
  std::size_t response_live_[kMaxRows] = {};
  std::size_t response_rows_ = 0;
  double response_s_[kMaxRows][kMaxRows] = {};
  bool response_from_solve_ = false;  // prepare_solve_response's: k_ and y_ rather than k0_ and y0_
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
