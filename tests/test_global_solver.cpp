// The global method (issue 13): a tire's stiffness is its compliances', whatever the substeps.
// Each test reads what the engine's own solve produced (World::step, or the tire's substep), and
// compares it with what the material alone predicts.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>
#include <numbers>

#include "tire/tire/tire_solver.h"
#include "tire_fixtures.h"

using namespace tire;
using namespace tire::test;

namespace {

constexpr double kG = 9.81;

SolverConfig global_config(int substeps, int iterations = 1) {
  SolverConfig c;
  c.method = SolverMethod::global;
  c.substeps = substeps;
  c.iterations = iterations;
  c.sleep = false;  // the solve's own figures, not where a still tire is frozen (sleep_islands.h)
  return c;
}

// A tire resting on flat ground from a flat tread segment, after `seconds`: how far its hub sank.
double rest_sag(const SolverConfig& config, const TireCompliance& compliance, double seconds = 4.0) {
  TireSpec spec;
  spec.compliance = compliance;
  const double hub0 = spec.outer_radius * std::cos(M_PI / spec.segments);  // a flat segment on y = 0
  spec.position = {0.0, hub0};
  World world = flat_world(spec, config);
  run(world, static_cast<int>(std::lround(seconds / config.dt)));
  return hub0 - world.tires().front().centroid().y;
}

TireCompliance softer(double factor) {
  const TireCompliance d;
  return {d.outer * factor, d.inner * factor, d.spoke * factor, d.pressure * factor};
}

// Particles of a tire laid out as one vertical chain c₀ … c_{2n−1} hanging down from (0, 0), links
// of length `link` and compliance `alpha`: c_{2k} is tread particle k and c_{2k+1} rim particle k,
// so each link joins a block of the global solve to itself or to the next (as a tire's do). c₀
// hangs from the mouse grab (compliance `grab`) at the origin.
Tire hanging_chain(std::uint32_t n, double link, double alpha, double grab) {
  TireSpec spec;
  spec.segments = static_cast<int>(n);
  spec.compliance.inner = 1e-3;  // not a rigid rim: no tread–rim contact (soft_contact.h)
  Tire t(0, spec);
  const auto particle = [n](std::uint32_t j) { return j % 2 == 0 ? j / 2 : n + j / 2; };
  std::vector<DistanceConstraint> links;
  for (std::uint32_t j = 0; j < 2 * n; ++j) {
    t.particles.x[particle(j)] = {0.0, -link * j};
    t.particles.v[particle(j)] = {};
    if (j > 0) links.push_back({particle(j - 1), particle(j), link, alpha});
  }
  t.distance = DistanceConstraintSet(links);
  // The area constraints keep three vertices on the line (tread particles 0, 1, 2): their area is
  // 0, and stays 0 as long as the chain hangs straight, so they never act.
  t.area_constraint.count = t.rim_area_constraint.count = 3;
  t.area_constraint.rest_area = t.rim_area_constraint.rest_area = 0.0;
  t.grabbed = true;
  t.grab_particle = particle(0);
  t.grab_target = {0.0, 0.0};
  t.grab_compliance = grab;
  return t;
}

// Steps a lone tire with no surfaces around for `seconds` with the engine's substep.
void hang(Tire& t, const SolverConfig& config, double seconds) {
  RigidWorld rigid({0.0, -kG});
  GlobalSolverPool pool;
  pool.reserve(1, t.n);
  const double h = config.dt / config.substeps;
  SubstepContext ctx{h, 0.0, {0.0, -kG}, &config, &rigid, false, &pool};
  for (int tick = 0; tick < static_cast<int>(std::lround(seconds / config.dt)); ++tick) {
    begin_tick(t, config, rigid);
    for (int s = 0; s < config.substeps; ++s) {
      ctx.time = s * h;
      substep(t, ctx, rigid);
    }
  }
}

double chain_stretch(const Tire& t, std::uint32_t n, double link) {
  const auto particle = [n](std::uint32_t j) { return j % 2 == 0 ? j / 2 : n + j / 2; };
  double stretch = 0.0;
  for (std::uint32_t j = 1; j < 2 * n; ++j)
    stretch += length(t.particles.x[particle(j)] - t.particles.x[particle(j - 1)]) - link;
  return stretch;
}

}  // namespace

TEST_CASE("global: a resting tire's sag is its compliances', at any substep count",
          "[unit][global][physics]") {
  const double factor = GENERATE(1.0, 100.0);
  const TireCompliance compliance = softer(factor);
  const double sag2 = rest_sag(global_config(2), compliance);
  const double sag8 = rest_sag(global_config(8), compliance);
  const double sag32 = rest_sag(global_config(32), compliance);
  INFO("x" << factor << " compliance: sag " << sag2 * 1e3 << ", " << sag8 * 1e3 << ", " << sag32 * 1e3
           << " mm at 2, 8, 32 substeps");
  CHECK(sag8 == Approx(sag2).epsilon(0.03));
  CHECK(sag32 == Approx(sag2).epsilon(0.03));
  CHECK(sag32 == Approx(sag8).epsilon(0.03));
  // A dense reference solve of the same method (numpy, contacts inside the solve; docs/physics.md,
  // "The global method") finds 0.114 mm for this material on a tire without the rim's area; the
  // engine's default tire sits 0.11 mm down.
  if (factor == 1.0) CHECK(sag8 == Approx(0.11e-3).margin(0.01e-3));
  // Gauss–Seidel with the same material at 2 substeps: hundreds of times softer.
  if (factor == 1.0) {
    SolverConfig gs;
    gs.method = SolverMethod::gauss_seidel;
    gs.substeps = 2;
    CHECK(rest_sag(gs, compliance) > 100.0 * sag2);
  }
}

TEST_CASE("global: a tire hanging from the grab stretches it by α·Mg at every substep count",
          "[unit][global][physics]") {
  const int substeps = GENERATE(1, 2, 8, 32);
  TireSpec spec;
  spec.position = {0.0, -0.5};
  spec.angle = -M_PI / spec.segments;  // turned half a segment: tread particle N/2 is straight above the hub
  Tire t(0, spec);
  t.grabbed = true;
  t.grab_particle = t.n / 2;
  REQUIRE(t.particles.x[t.grab_particle].x == Approx(t.centroid().x).margin(1e-12));
  const double alpha = 1e-4;  // m/N: 10 kg hangs 9.8 mm below the target
  const double expected = alpha * t.total_mass() * kG;
  // Released at the stretch the material predicts: a tire that hangs there stays there, one that
  // does not bounces about where it does (nothing damps its motion as a whole): the mean over one
  // second, five periods of that bounce (ω = (1/(αM))^½ = 31.6 rad/s), tells.
  t.grab_target = t.particles.x[t.grab_particle] + Vec2{0.0, expected};
  t.grab_compliance = alpha;
  SolverConfig config = global_config(substeps);
  hang(t, config, 1.0);
  double stretch = 0.0;
  const int ticks = 60;
  for (int tick = 0; tick < ticks; ++tick) {
    hang(t, config, config.dt);
    stretch += length(t.particles.x[t.grab_particle] - t.grab_target) / ticks;
  }
  INFO(substeps << " substeps: mean stretch " << stretch * 1e3 << " mm");
  CHECK(stretch == Approx(expected).epsilon(1e-3));
}

TEST_CASE("global: a chain of stiff links under load stretches by Σ α·load in one substep",
          "[unit][global][physics]") {
  // 8 particles of 10/8 kg, 7 links: link j carries the 8 − j particles below it.
  const std::uint32_t n = 4;
  const double link = 0.1, alpha = 1e-6;
  Tire global_chain = hanging_chain(n, link, alpha, 1e-6);
  const double m = global_chain.particle_mass();
  double expected = 0.0;
  for (std::uint32_t j = 1; j < 2 * n; ++j) expected += alpha * (2 * n - j) * m * kG;
  SolverConfig config = global_config(1);
  hang(global_chain, config, 3.0);
  const double global_stretch = chain_stretch(global_chain, n, link);
  // Gauss–Seidel, one substep of one sweep, on the same chain.
  Tire gs_chain = hanging_chain(n, link, alpha, 1e-6);
  SolverConfig gs;
  gs.method = SolverMethod::gauss_seidel;
  gs.substeps = 1;
  hang(gs_chain, gs, 3.0);
  const double gs_stretch = chain_stretch(gs_chain, n, link);
  INFO("expected " << expected * 1e6 << " µm; global " << global_stretch * 1e6 << " µm; Gauss–Seidel "
                   << gs_stretch * 1e6 << " µm");
  CHECK(global_stretch == Approx(expected).epsilon(1e-3));
  CHECK(std::abs(gs_stretch - expected) > 0.5 * expected);
}

TEST_CASE("global: a free-spinning tire keeps its spin and its shape at any substep count",
          "[unit][global][physics]") {
  // No gravity, nothing to touch: angular momentum is conserved, and a rigid spin should go on as
  // it is. Stepping along straight chords and projecting back onto the ring would take ω²h/3 of it
  // a second (global_method.cpp, turn_velocities); damping a turn read as a shortening would squeeze
  // the tire (global_solver.cpp, assemble). The spin is the angle turned, tick by tick: the chords'
  // spin, angular_velocity(), reads sin(ωh)/h. Built from tangents and turned as chords, the tire
  // spun 3 % faster than it was built to at one substep (global_method.cpp, chord_spin).
  SolverConfig config = global_config(GENERATE(1, 2, 8));
  config.tunnel_clamp = 4.0;  // the tread's 12.5 m/s within it at one substep (the default allows 6.7)
  CAPTURE(config.substeps);
  World world(config, {0, 0});
  TireSpec spec = tire_at({0, 0});
  spec.angular_velocity = 25.0;  // the tread at 12.5 m/s: a tire flat out
  world.add_tire(spec);
  const auto angle = [&] {
    const Tire& t = world.tires()[0];
    const Vec2 r = t.particles.x[0] - t.centroid();
    return std::atan2(r.y, r.x);
  };
  double turned = 0.0, last = angle();
  for (int tick = 0; tick < 120; ++tick) {
    world.step({});
    const double now = angle();
    turned += std::remainder(now - last, 2.0 * std::numbers::pi);
    last = now;
  }
  const Tire& t = world.tires()[0];
  CHECK(turned / (120 * config.dt) == Approx(spec.angular_velocity).epsilon(0.001));
  CHECK(t.area_ratio() == Approx(1.0).margin(0.002));
  CHECK(length(t.velocity()) < 1e-9);
}

TEST_CASE("global: a tire whose air and rings disagree exerts no torque on itself",
          "[unit][global][physics]") {
  // Pressure 1.2 or 0.8: the air asks for 20 % more (or less) area than the rings allow, and the
  // constraints push against each other every substep. Internal forces are central, so a free tire
  // that starts at rest stays at rest, spin included. (Gauss–Seidel's projections, one after another,
  // do not keep it: the same tire spins up to 16.6 rad/s in 4 s at 8 × 1, docs/physics.md.)
  SolverConfig config = global_config(GENERATE(1, 2, 8));
  const double pressure = GENERATE(0.8, 1.2);
  CAPTURE(config.substeps, pressure);
  World world(config, {0, 0});
  TireSpec spec = tire_at({0, 0});
  spec.pressure = pressure;
  world.add_tire(spec);
  run(world, 240);
  const Tire& t = world.tires()[0];
  CHECK(std::abs(t.angular_velocity()) < 1e-9);
  CHECK(length(t.velocity()) < 1e-9);
  CHECK(std::abs(t.area_ratio() - 1.0) > 1e-4);  // the air did push: the constraints disagreed
}

TEST_CASE("global: a spinning tire that lands rolls off at the speed its angular momentum gives",
          "[unit][global][physics]") {
  // A tire spinning clockwise at 27 rad/s (its tread at 13.5 m/s) lands from 2 cm, falling at
  // 1.17 m/s and drifting at 0.5 m/s: kinetic friction at the contact turns spin into speed until it
  // rolls. Friction and the normal force act at the contact point, gravity through it, so the angular
  // momentum about it is kept: v = (I ω₀ + M R v₀) / (I/R + M R). Taken off each sliding particle
  // alone, as Gauss–Seidel does, the friction stopped the landing particle dead while its ring spun
  // on, and at 2 substeps the tire left the ground again at 5 m/s (tire_solver.cpp,
  // apply_kinetic_friction_split). The landing must not throw the tire: its upward speed stays
  // below half of what it fell with.
  const int substeps = GENERATE(1, 2, 4, 8, 16);
  SolverConfig config;
  config.method = SolverMethod::global;
  config.substeps = substeps;
  config.tunnel_clamp = 4.0;  // at 1 substep, one segment a substep (6.7 m/s) would clamp the tread
  TireSpec spec = tire_at({0.0, 0.52});
  spec.velocity = {0.5, -1.17};
  spec.angular_velocity = -27.0;
  spec.rolling_resistance = 0.0;
  World world = flat_world(spec, config);
  const Tire& t = world.tires().front();
  const double inertia = t.rigid_motion().inertia, mass = t.total_mass(), radius = spec.outer_radius;
  const double expected = (inertia * 27.0 + mass * radius * 0.5) / (inertia / radius + mass * radius);
  double highest_vy = -std::numeric_limits<double>::infinity();
  for (int tick = 0; tick < 30; ++tick) {
    world.step({});
    highest_vy = std::max(highest_vy, t.velocity().y);
  }
  const RigidMotion m = t.rigid_motion();
  INFO(substeps << " substeps: rolls at " << m.velocity.x << " m/s (expected " << expected << "), tread slip "
                << m.velocity.x + m.omega * radius << " m/s, highest upward speed " << highest_vy << " m/s");
  CHECK(highest_vy < 0.5 * 1.17);
  CHECK(m.velocity.x == Approx(expected).epsilon(0.05));
  CHECK(std::abs(m.velocity.x + m.omega * radius) < 0.05 * expected);  // rolling, not sliding
}

TEST_CASE(
    "global: a tire rolling, jumping and landing under half a segment a substep keeps the level's substeps",
    "[unit][global][refine]") {
  // Its solves turn no constraint by more than refine_turn, and it turns by less than refine_roll
  // of a segment a substep (6 m/s: 12 rad/s, 0.1 rad a substep against 0.11), so the refinement
  // never takes more substeps: what a tire costs stays what the level asks for.
  SolverConfig config = global_config(2);
  config.tunnel_clamp = 4.0;
  TireSpec spec = tire_at({0.0, 0.5}, true);
  spec.max_speed = 6.0;
  World world = flat_world(spec, config);
  const Tire& t = world.tires().front();
  double most_turn = 0.0;
  for (int tick = 0; tick < 300; ++tick) {
    world.step({1.0, tick % 60 == 30});  // full drive, a jump every second
    most_turn = std::max(most_turn, t.newton_turn);
    INFO("tick " << tick << ": the solves turned a constraint by " << t.newton_turn << " rad, spin "
                 << t.angular_velocity() << " rad/s");
    REQUIRE(world.tick_substeps() == 2);
  }
  INFO("most turn " << most_turn << " rad, speed " << t.velocity().x << " m/s");
  CHECK(t.velocity().x > 5.0);  // it did roll
  CHECK(most_turn < config.settle_turn);
}

TEST_CASE("global: a tire rolling faster takes the substeps that keep its turn within half a segment",
          "[unit][global][refine]") {
  // SolverConfig::refine_roll: a tire on the ground turning by |ω| h a substep asks the next tick
  // for the smallest power of two (up to max_refine) that keeps |ω| h within half of 2π/N.
  const double speed = GENERATE(8.0, 12.0, 14.0);
  SolverConfig config = global_config(2);
  config.sleep = false;
  TireSpec spec = tire_at({0.0, 0.5});
  spec.velocity = {speed, 0.0};
  spec.angular_velocity = -speed / spec.outer_radius;
  World world = flat_world(spec, config);
  const Tire& t = world.tires().front();
  const double half_segment = std::numbers::pi / t.n;
  world.step({});
  int refined = 0;
  for (int tick = 1; tick < 120; ++tick) {
    int wanted = 1;  // from the spin the last tick left, if it touched the ground lately
    while (t.touched_ground_within(config.jump_grace) && wanted < config.max_refine &&
           std::abs(t.angular_velocity()) * config.dt / (config.substeps * wanted) > half_segment)
      wanted *= 2;
    world.step({});
    INFO(speed << " m/s, tick " << tick << ": spin " << t.angular_velocity() << " rad/s, substeps "
               << world.tick_substeps());
    REQUIRE(world.tick_substeps() >= config.substeps * wanted);
    if (wanted > 1) ++refined;
  }
  CHECK(refined > 100);  // it rolled fast enough to ask, all along
}

TEST_CASE("global: a solve that turns a constraint past refine_turn doubles the next tick's substeps",
          "[unit][global][refine]") {
  // A free tire (no gravity, nothing to touch) with one tread particle pulled 0.4 m towards the hub:
  // the solve that pulls it back turns the tread edges next to it by about a radian. The next ticks
  // take 4, then 8 substeps (max_refine 4: up to 8), and once it is round again and only rings, 2.
  const int max_refine = GENERATE(1, 4);
  SolverConfig config = global_config(2);
  config.max_refine = max_refine;
  World world(config, {0.0, 0.0});
  const TireId id = world.add_tire(tire_at({0.0, 0.0}));
  Tire& t = *world.find_tire(id);
  t.particles.x[0] = t.particles.x[0] * ((0.5 - 0.4) / 0.5);
  t.particles.x_prev[0] = t.particles.x[0];
  std::vector<int> substeps;
  for (int tick = 0; tick < 120; ++tick) {
    world.step({});
    substeps.push_back(world.tick_substeps());
  }
  INFO("the substeps each tick took " << ::Catch::Detail::stringify(substeps));
  CHECK(substeps.front() == 2);
  CHECK(*std::max_element(substeps.begin(), substeps.end()) == 2 * max_refine);
  CHECK(substeps.back() == 2);  // settled: the level's substeps again
  if (max_refine > 1) CHECK(substeps[1] == 4);
}

TEST_CASE("global: an active-set pass that lets friction go solves on the factor it has, as a refactor would",
          "[unit][global]") {
  // A tire driven flat out spins its wheel (the drive, 12 m/s², beats μ g): in its first two seconds
  // one solve in seven lets a contact's friction go after the first pass. Solved on the first pass's factor
  // (the friction a row of the capacitance system, dropped) or with K refactored without it, the solution is
  // the same but for rounding (Woodbury), tick after tick.
  SolverConfig reuse = global_config(2);
  reuse.tunnel_clamp = 4.0;
  SolverConfig refactor = reuse;
  refactor.reuse_factor = false;
  World a = flat_world(tire_at({0.0, 0.5}, true), reuse);
  World b = flat_world(tire_at({0.0, 0.5}, true), refactor);
  Tire::GlobalWork work_a, work_b;
  double most_apart = 0.0;
  for (int tick = 0; tick < 120; ++tick) {
    a.step({1.0, false});
    b.step({1.0, false});
    const Tire& ta = a.tires().front();
    const Tire& tb = b.tires().front();
    for (std::size_t i = 0; i < ta.particles.x.size(); ++i)
      most_apart = std::max(most_apart, length(ta.particles.x[i] - tb.particles.x[i]));
    work_a += ta.global_work;
    work_b += tb.global_work;
  }
  INFO("reusing: " << work_a.solves << " solves, " << work_a.factorisations << " factorisations, "
                   << work_a.updates << " updates; refactoring: " << work_b.factorisations
                   << " factorisations; most apart " << most_apart << " m");
  CHECK(a.tires().front().velocity().x > 5.0);  // it did roll
  CHECK(work_b.updates == 0);
  CHECK(work_b.factorisations > work_b.solves + work_b.solves / 10);
  CHECK(work_a.updates > work_a.solves / 10);
  CHECK(work_a.factorisations < work_a.solves + work_a.solves / 20);
  CHECK(most_apart < 1e-9);
}

TEST_CASE("global: a solve that is not finite is counted and reported, and the tire reset",
          "[unit][global]") {
  // A NaN put into a tread particle from outside: the tire's factorisation is not finite. The
  // failure is not silent: World counts it, warns with the tick and the tire, and the divergence
  // guard puts the tire back at its spawn state, after which it solves again.
  World world = flat_world(tire_at({0.0, 0.5}), global_config(2));
  Tire& t = *world.find_tire(0);
  run(world, 10);
  REQUIRE(world.failed_solves() == 0);
  t.particles.x[3].x = std::numeric_limits<double>::quiet_NaN();
  world.step({});
  const std::uint64_t failed = world.failed_solves();
  CHECK(failed >= 1);
  int reported = 0;
  for (const std::string& w : world.warnings())
    reported += w.find("global solve(s) failed") != std::string::npos;
  INFO(::Catch::Detail::stringify(world.warnings()));
  CHECK(reported == 1);
  CHECK(t.is_finite());
  world.warnings().clear();
  run(world, 60);
  CHECK(world.failed_solves() == failed);  // the reset tire solves as before
  CHECK(world.warnings().empty());
  CHECK(t.centroid().y == Approx(0.5).margin(0.01));
}

TEST_CASE("global: a tire that starts inside the ground is pushed out at contact_push_speed, not at once",
          "[unit][global]") {
  // Placed 5 cm into the ground without gravity: undone in one substep (2.5 cm a substep at the
  // default two), the overlap would leave the tire at 6 m/s; pushed out at 3 m/s it leaves at that
  // speed and is out of the ground within three ticks.
  for (const double push : {SolverConfig{}.contact_push_speed, std::numeric_limits<double>::infinity()}) {
    SolverConfig config;
    config.contact_push_speed = push;
    World world = flat_world(tire_at({0.0, 0.45}), config, {0, 0});
    world.step({});
    const double rising = world.tires().front().velocity().y;
    INFO("push speed " << push << ": rising at " << rising << " m/s after a tick");
    if (std::isinf(push)) {
      CHECK(rising > 4.0);  // the overlap went in the tick's first substep and became speed
    } else {
      CHECK(rising <= push);
      CHECK(rising > 0.8 * push);  // the tread's particles are pushed at it; the rest follow
      run(world, 2);
      const Tire& t = world.tires().front();
      double lowest = std::numeric_limits<double>::infinity();
      for (std::uint32_t i = 0; i < t.segments(); ++i) lowest = std::min(lowest, t.particles.x[i].y);
      CHECK(lowest > -1e-6);  // out of the ground
    }
  }
}
