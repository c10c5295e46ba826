// Every solver number a user can tune, in one place. The level's "solver" object fills the first
// block; the rest are engine defaults that a level may also override.
#pragma once

#include <cstdint>

namespace tire {

// How a substep solves each tire's constraints.
//  gauss_seidel: one sweep over the constraints per iteration, each projected on its own
//    (Macklin et al. 2016, Algorithm 1). Cheap per sweep, but a load travels one constraint a
//    sweep, so a stiff tire's stiffness depends on the substeps (docs/accuracy.md).
//  global: all of a tire's constraints and its contacts with obstacles and props as one linear
//    system per iteration (GlobalSolver, global_solver.h): the tire's stiffness is its compliances'
//    at any substep count.
enum class SolverMethod { gauss_seidel, global };

// As levels, the command line and reports write it: "gauss-seidel", "global".
constexpr const char* method_name(SolverMethod m) {
  return m == SolverMethod::global ? "global" : "gauss-seidel";
}
constexpr SolverMethod kSolverMethods[] = {SolverMethod::gauss_seidel, SolverMethod::global};

// How a world's step orders the phases of a substep over the tires. Both run the same per-tire
// phases in the same order with the same inputs, so they give the same bits (tests/
// test_step_schedule.cpp); only the number of sweeps over the tires' memory differs.
enum class StepSchedule : std::uint8_t {
  // Small Steps' Algorithm 1 as written: each phase (predict, solve positions, update velocities)
  // a sweep over every tire of its own.
  plain,
  // The default. The same phases, with the ones that follow each other on one tire and owe nothing
  // to the rest of the world in between run in one sweep: a substep's prediction with its first
  // iteration, and, when no prop takes impulses, the previous substep's velocity pass with them.
  fused,
};

struct SolverConfig {
  double dt = 1.0 / 60.0;  // fixed tick (s)
  int substeps = 2;        // n: the tick is split into substeps of h = dt/n (Macklin et al. 2019)
  int iterations = 1;      // constraint sweeps per substep (global: Newton iterations per substep)
  SolverMethod method = SolverMethod::global;
  double damping = 0.0;  // decay rate (1/s) of non-rigid particle motion (0 = none)

  // Anti-tunneling clamp: a particle's speed is limited so that it travels at most this many
  // rest outer-segment lengths in one substep.
  double tunnel_clamp = 4.0;
  // A contact counts as ground (for grounded flags and jumping) when its normal's y is at least
  // this: 0.5 accepts surfaces up to 60 degrees steep.
  double ground_normal_y = 0.5;
  // A jump is honoured when the tread touched ground at most this long ago (s), not only when it
  // touches it in the tick's last substep ("coyote time"). A tire as stiff as its material rolls
  // like a polygon: driven on level ground it lands on each corner and leaves the ground between
  // corners. On level 01 at 2 substeps, between 1 and 2 s of full drive, the last substep of 57 % of
  // ticks had no ground contact (Gauss–Seidel 8 × 1, soft from its substeps: none), and a jump
  // asked for in those ticks was lost. 0.1 s is six ticks.
  double jump_grace = 0.1;
  // Restitution (TireSpec::restitution) is owed for a landing faster than this (m/s), as Box2D
  // treats slower impacts as inelastic (b2_velocityThreshold), and only to a tire that leaves the
  // surface within restitution_time (s) of touching it: one that rolls on and later drives off an
  // edge is not bounced by a landing long past.
  double restitution_threshold = 1.0;
  double restitution_time = 0.5;
  // A tire with a coordinate beyond this (m) or any NaN/Inf is reset to its spawn state, and so is
  // one blown up or turned inside out (its area more than divergence_area times its rest area, or
  // below minus it) or one with a particle faster than divergence_speed (m/s): no contact or
  // setting a level can give does that to a tire that is being solved.
  double divergence_limit = 1.0e5;
  double divergence_area = 50.0;
  double divergence_speed = 5000.0;

  // Sleeping (world/sleep_islands.h): bodies that touch form islands; an island whose bodies have all been
  // still for sleep_time stops being simulated until something wakes it. The level's
  // "solver": {"sleep": false} turns it off.
  bool sleep = true;
  // Still (m/s): a tire whose hub has stayed within sleep_speed · sleep_time of where it was when it
  // became still, and its tread within that of where it was then (by the angle it has turned
  // through), so that its mean speed over the time is under sleep_speed (Box2D v3's sleep
  // threshold, 0.05 m/s); whose deformation moved slower than sleep_deform_speed over the tick's
  // last substep (the root mean square of its particles' motion less its rigid motion's: Box2D
  // 2.4's b2_linearSleepTolerance, 0.01 m/s); and whose shape has stayed within sleep_deform (m) of
  // the shape it had then (the root mean square of its particles' offsets from the hub against
  // those it had, its turn taken out). Read from positions, not velocities (sleep_islands.cpp). A
  // dynamic prop is still when its centre and outline move slower than sleep_speed. So a tire
  // sleeps only once its deformation has stopped changing, in the shape it would settle to awake:
  // every preset's sag asleep is its sag awake to 0.15 % at 2–32 substeps. With the speed alone, a
  // soft preset ringing slowly on its air fell asleep up to 3.7 % off; with 0.25 m/s, which let
  // level 08's jittering pile sleep under Gauss–Seidel, up to 35 % (docs/at-rest.md).
  double sleep_speed = 0.05;
  double sleep_deform_speed = 0.01;
  double sleep_deform = 2e-5;
  // How long an island's bodies must all have been still before it sleeps (s): Box2D's
  // b2_timeToSleep.
  double sleep_time = 0.5;

  // The global method's own numbers.
  // Contact active-set passes per iteration: each solves the system with the contacts found so far,
  // then drops those that pull (λ_n < 0) or slip (|λ_t| > μ_s λ_n) and adds particles that now
  // penetrate. A resting tire settles in one or two.
  int contact_passes = 8;
  // Whether a pass that only lets frictions go or takes in new contacts solves on the factor of K
  // the pass before it made (GlobalSolver: the changes as rows, by Woodbury), rather than
  // refactoring K: the same solution to rounding, a fifth less work for a tire driven flat out. For
  // the tests and the bench, which compare the two.
  bool reuse_factor = true;
  // Rolling resistance held in the position solve (the global method; GlobalSolver's rolling row): a
  // tire whose spin the velocity pass stopped keeps its roll in the next solve, up to the moment
  // C_rr·N·R, so that it stays put on a slope gentler than C_rr, as a real tire in neutral does.
  // Without it, the velocity pass stops the spin each substep and the position solve turns the tire
  // again: a soft tire creeps down a 0.5 % slope at 6 mm/s. Only for a tire touching no other tire
  // (docs/at-rest.md). Off by default: on, it changes the bits of every level with a tire at rest,
  // and level 08's pile sleeps within 40 s at the shipped bits only by the luck of its rain
  // (docs/at-rest.md, "Still open"). The level's "solver": {"rolling_hold": true} turns it on.
  bool rolling_hold = false;
  // The compliance of what is rigid in the global solve (m/N): contacts, and distance constraints
  // of compliance 0 (its primal form divides by α, so every α is at least this). It is an XPBD
  // compliance, not a penalty: a tire's whole weight (100 N) sinks a contact by 0.1 nm at any
  // substep count. Static friction holds a particle to where the substep began, so a contact
  // under a tangential force F creeps by α·F a substep: 1e-12 keeps that below 0.01 mm over a
  // minute at 32 substeps (1e-10 let a resting tire's sag creep by 5 % in 4 s at 32 substeps).
  // Far below that, K's condition (h²/α against a particle's mass, 10⁹ at one substep) would cost
  // digits.
  double rigid_compliance = 1e-12;
  // A particle starts a contact in the global solve only when it is deeper than this (m): below it,
  // the rounding of a resting contact could add and drop it pass after pass.
  double contact_slop = 1e-9;
  // A particle that starts a substep inside a surface (an obstacle or a prop: a prop Box2D moved
  // after the tire's solve, a tire spawned or dragged into one) is pushed out at this speed at most
  // (m/s), relative to the surface, as Box2D v3 pushes out its own overlaps
  // (b2WorldDef::contactPushoutVelocity, 3 m/s). Pushed out within one substep, the overlap became
  // velocity: a tread 4 cm inside a 0.2 kg ball that Box2D had rolled back at it pushed the ball
  // with 44 N·s (docs/at-rest.md). A contact met within the substep is met in full.
  double contact_push_speed = 3.0;
  // Refinement. One Newton iteration a substep is XPBD's linearised step, which holds while the step
  // turns each constraint a little. When a tire's solve turns one of its constraints by more than
  // refine_turn (rad), the next tick takes twice the substeps, up to max_refine times the level's;
  // a tick in which none turns by more than settle_turn takes half as many again (World::
  // tick_substeps). A soft tire crushed flat under 100 times its weight (tests/extremes/test_crush.cpp)
  // has its spokes turned by 1–3 rad a step at 2 substeps and blows up; refined it holds, as at 8.
  // A soft tire rolling at 10 m/s turns its tread by 0.15–0.3 rad a step at 2 substeps, and one
  // iteration then makes energy (coasting, it sped up from 10 to 10.8 m/s in 5 s, where at 3–8
  // substeps, or with 2 iterations, it slows to 5–6 m/s): refined past 0.15 rad it gains none
  // (tests/test_materials.cpp, docs/soft-tire.md). The stiff tire rolling, jumping and landing on
  // flat ground turns its constraints by at most 0.05 rad a step at 2 substeps: it refines only for
  // refine_roll, below. max_refine 1 turns it off.
  double refine_turn = 0.15;
  double settle_turn = 0.05;
  int max_refine = 8;
  // A tire on the ground (it touched it within jump_grace), or in the air within reach of an
  // obstacle or a prop (about to land on it), that turns by more than refine_roll of one tread
  // segment's angle, 2π/N, a substep asks the next tick for the substeps that keep it within. Its
  // corners' contacts are met at the end of each substep's turn: past half a segment, a corner that
  // struck the ground ahead of the hub ends the turn behind it, where the push that holds it up
  // spins the tire up. Coasting from 10 m/s at 2 substeps the stiff tire gained 108 J in 5 s; kept
  // within half a segment (4 substeps at 10 m/s, 8 at 14) it gains none at 1–8 substeps
  // (docs/soft-tire.md, "Corners met at the end of their turn"). 0 turns it off.
  double refine_roll = 0.5;

  // The most tires one tire is in contact with in a tick (TirePairFinder, soft_contact.h): a tire
  // with more candidates keeps its nearest. A tire in a pile of its like touches six, and the
  // broad phase finds at most 11 candidates for any tire of the replays (level 08's 300 small tires
  // raining onto a pile); the limit bounds what a heap of tires on one spot costs (each tire inside
  // every other): every tread particle is then tested against this many treads, not all of them,
  // and each tire pushes this many.
  int tire_neighbours = 32;

  // The global method's islands (tires joined by contacts, island_contacts.h) of up to this many
  // tires have the contacts between their tires solved as one problem, each tire through its exact
  // response: a pile does not creep, and its tires stay out of each other (a pile of 60: 3.4 mm deep
  // at most, against 29.5 mm). Larger islands are solved tire by tire against their neighbours
  // (block Gauss–Seidel, tire_neighbours.h), which creeps; 0 solves every island so. An island with
  // a tire near a dynamic prop is solved so too. An awake pile solved as one problem costs more than
  // twice what block Gauss–Seidel costs, and its active set does not settle on light, nearly rigid
  // tires; its cost grows with the pile (level 08's 301 tires as one island: 64 ms a tick on two
  // cores, docs/at-rest.md).
  int island_tires = 64;

  // Gauss–Seidel 8 × 1, clamped to one segment a substep: the engine's default until the global
  // method replaced it (docs/physics.md, "The default method"), and the method for piles of hundreds of
  // tires. Its speed limit, eight rest segments a tick, is the default's (2 substeps × 4).
  static constexpr SolverConfig gauss_seidel_8x1() {
    SolverConfig c;
    c.method = SolverMethod::gauss_seidel;
    c.substeps = 8;
    c.tunnel_clamp = 1.0;
    return c;
  }
};

}  // namespace tire
