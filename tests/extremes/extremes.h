// Stability at the extremes: what every case measures, and how it is judged.
//
// Energy. E = Σ ½ m v² + Σ m g (y − y_ground) over the tire particles, plus ½ M v² + ½ I ω² +
// M g (y_com − y_ground) for every live dynamic prop. The potential is measured from the ground
// (the lowest height anything can reach), so a resting tire has a meaningful nonzero scale.
// E leaves out the elastic energy of the constraints, U = Σ ½ C²/α, which is never negative: so if
// the true total E + U never rises, E(t) ≤ E(0) + U(0) at all times. The reference (the "budget")
// is therefore E(0), plus U(0) where a case starts strained on purpose (coincident particles, an
// inverted tire, a tire released from under a box); U(0) is 0 for a tire built at rest. Contacts,
// friction, damping and the speed clamp only take energy out: E(t) − budget > 1% of the scale is a
// solver defect.
//
// Area. Every tire's area_ratio (outer ring area / rest area) is held within [lo, hi] at every
// tick after `after` seconds; each case states its bounds.
//
// Divergence guard. World resets a NaN/Inf/far-away tire and pushes a warning: no case may rely on
// it, so every case requires world.warnings() to be empty unless it says otherwise. A NaN that the
// guard caught shows up here as a warning, since the reset tire is finite again.
//
// Each case prints one line to stdout ("extremes: <case>: ..."; `ctest -V -L extremes` shows them);
// a failing case also prints a timeline (tick, time, energy, area range, max strain, prop speed)
// around its worst moments.
#pragma once

#include <algorithm>
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "../tire_fixtures.h"

namespace tire::extremes {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kGround = 0.0;  // top of the ground box in every case
// A tire whose stiff constraints (compliance ≤ kStiffCompliance) are still strained by more than
// kTangledStrain at the end of its case is flagged in its report line as SUSPECT: 25% of a 0.11 m
// segment at α = 1e-5 m/N would take 2.8 kN, far beyond any load on a tire at rest in these cases
// but the crush, so the ring or spoke must be left folded or tangled. Reported, not asserted: the
// issue's criteria are NaN, energy and area.
inline constexpr double kTangledStrain = 0.25;
inline constexpr double kStiffCompliance = 1e-5;

// ---------------------------------------------------------------------------------------------
// Measurements

inline double tire_energy(const Tire& t, Vec2 gravity, double ground_y = kGround) {
  const double m = t.particle_mass();
  double e = 0.0;
  for (std::size_t i = 0; i < t.particles.size(); ++i) {
    e += 0.5 * m * length_squared(t.particles.v[i]);
    e += -m * dot(gravity, t.particles.x[i] - Vec2{0.0, ground_y});
  }
  return e;
}

// Live dynamic prop i's kinetic and potential energy, as Box2D holds it (between ticks).
inline double prop_energy(const RigidWorld& rigid, std::uint32_t i, Vec2 gravity, double ground_y = kGround) {
  const Prop& p = rigid.props()[i];
  if (!p.alive || p.spec.type != PropType::dynamic_body) return 0.0;
  const PropState s = rigid.prop_state(i);
  if (s.mass <= 0.0) return 0.0;
  const double w = s.angular_velocity;
  return 0.5 * s.mass * length_squared(s.velocity) + 0.5 * s.inertia * w * w -
         s.mass * dot(gravity, s.center - Vec2{0.0, ground_y});
}

inline double world_energy(const World& world, double ground_y = kGround) {
  double e = 0.0;
  for (const Tire& t : world.tires()) e += tire_energy(t, world.gravity(), ground_y);
  for (std::uint32_t i = 0; i < world.rigid().props().size(); ++i)
    e += prop_energy(world.rigid(), i, world.gravity(), ground_y);
  return e;
}

// U = Σ ½ C²/α over the tire's constraints (distance and area). A violated rigid constraint (α = 0)
// holds unbounded energy: +inf.
inline double elastic_energy(const Tire& t) {
  double u = 0.0;
  for (const DistanceConstraint& c : t.distance.constraints()) {
    const double C = length(t.particles.x[c.b] - t.particles.x[c.a]) - c.rest_length;
    if (c.compliance > 0.0)
      u += 0.5 * C * C / c.compliance;
    else if (std::abs(C) > 1e-9)
      return kInf;
  }
  const AreaConstraint& a = t.area_constraint;
  const double C = t.area() - a.pressure * a.rest_area;
  if (a.compliance > 0.0)
    u += 0.5 * C * C / a.compliance;
  else if (std::abs(C) > 1e-9)
    return kInf;
  return u;
}

// Largest |L/L0 − 1| over the tire's distance constraints (those with compliance ≤ max_compliance).
inline double max_strain(const Tire& t, double max_compliance = kInf) {
  double s = 0.0;
  for (const DistanceConstraint& c : t.distance.constraints())
    if (c.rest_length > 0.0 && c.compliance <= max_compliance)
      s = std::max(s, std::abs(length(t.particles.x[c.b] - t.particles.x[c.a]) / c.rest_length - 1.0));
  return s;
}

inline bool props_finite(const World& world) {
  for (std::uint32_t i = 0; i < world.rigid().props().size(); ++i) {
    if (!world.rigid().props()[i].alive) continue;
    const PropState s = world.rigid().prop_state(i);
    const Vec2 x = s.pose.position, v = s.velocity;
    if (!std::isfinite(x.x) || !std::isfinite(x.y) || !std::isfinite(v.x) || !std::isfinite(v.y) ||
        !std::isfinite(s.pose.angle) || !std::isfinite(s.angular_velocity))
      return false;
  }
  return true;
}

inline std::string fmt(const char* format, double value) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, format, value);
  return buffer;
}

// ---------------------------------------------------------------------------------------------
// A case: steps a world, watches it, reports one line and judges it.

struct AreaBounds {
  double lo = 0.2;
  double hi = 3.0;
  double after = 1.0;  // s: checked at every tick from this time on
};

class Probe {
 public:
  struct Sample {
    std::uint64_t tick;
    double time;
    double energy;
    double area_min;
    double area_max;
    double strain;
    double prop_speed;  // fastest live dynamic prop's centre (m/s)
    bool finite;
  };

  // `count_elastic`: add the tires' elastic energy U now to the budget, for a case that starts
  // strained on purpose. Otherwise U(0) is left out: a tire built at rest has none, and in a tire
  // that has settled the solver's unconverged residual strain (a few percent on constraints of
  // α = 1e-7 m/N) reads as ~80 J of U that no force stands for and that the settled tire keeps;
  // counting it would loosen the budget by more than the 1% being checked.
  Probe(std::string name, World& world, AreaBounds bounds = {}, bool count_elastic = false)
      : name_(std::move(name)), world_(world), bounds_(bounds), count_elastic_(count_elastic) {
    rebase();
  }

  // Takes the current state as the reference: budget = E (+ U) now, scale = the same.
  void rebase() {
    double u = 0.0;
    if (count_elastic_)
      for (const Tire& t : world_.tires()) u += elastic_energy(t);
    e0_ = world_energy(world_);
    u0_ = u;
    budget_ = e0_ + u0_;
    scale_ = budget_;
    max_gain_ = -kInf;
    max_gain_tick_ = world_.tick();
  }
  // A tighter budget known from before (e.g. what is left of an earlier phase's budget once a prop
  // and its energy have left the world); it becomes the scale too.
  void cap_budget(double budget) {
    if (budget < budget_) budget_ = scale_ = budget;
  }

  void step(int ticks, TickInput input = {}) {
    for (int i = 0; i < ticks; ++i) {
      world_.step(input);
      observe();
    }
  }
  // Steps until `done()` holds (checked after each tick) or `max_ticks` pass; true if it held.
  template <class Done>
  bool step_until(int max_ticks, Done done) {
    for (int i = 0; i < max_ticks; ++i) {
      world_.step({});
      observe();
      if (done()) return true;
    }
    return false;
  }

  void observe() {
    Sample s{world_.tick(), world_.time(), world_energy(world_), kInf, -kInf, 0.0, 0.0, props_finite(world_)};
    for (std::uint32_t i = 0; i < world_.rigid().props().size(); ++i) {
      const Prop& p = world_.rigid().props()[i];
      if (p.alive && p.spec.type == PropType::dynamic_body)
        s.prop_speed = std::max(s.prop_speed, length(world_.rigid().current_velocity(i)));
    }
    for (const Tire& t : world_.tires()) {
      const double r = t.area_ratio();
      s.area_min = std::min(s.area_min, r);
      s.area_max = std::max(s.area_max, r);
      s.strain = std::max(s.strain, max_strain(t));
      s.finite = s.finite && t.is_finite() && std::isfinite(r);
    }
    s.finite = s.finite && std::isfinite(s.energy);
    samples_.push_back(s);
    if (!s.finite && first_nonfinite_ == kNever) first_nonfinite_ = s.tick;
    if (warnings_seen_ == 0 && !world_.warnings().empty()) first_warning_tick_ = s.tick;
    warnings_seen_ = world_.warnings().size();
    if (s.energy - budget_ > max_gain_) max_gain_ = s.energy - budget_, max_gain_tick_ = s.tick;
    area_all_min_ = std::min(area_all_min_, s.area_min);
    area_all_max_ = std::max(area_all_max_, s.area_max);
    if (s.time >= bounds_.after - 1e-12) {
      if (s.area_min < area_min_) area_min_ = s.area_min, area_min_tick_ = s.tick;
      if (s.area_max > area_max_) area_max_ = s.area_max, area_max_tick_ = s.tick;
    }
    if (s.strain > strain_max_) strain_max_ = s.strain, strain_max_tick_ = s.tick;
  }

  double gain_percent() const { return 100.0 * max_gain_ / scale_; }
  double area_min() const { return area_min_; }
  double area_max() const { return area_max_; }
  double area_all_min() const { return area_all_min_; }
  double area_all_max() const { return area_all_max_; }
  double strain_max() const { return strain_max_; }
  bool finite() const { return first_nonfinite_ == kNever; }
  std::size_t guard_count() const { return world_.warnings().size(); }
  const std::string& name() const { return name_; }

  // A tick of interest to a case (shown in the timeline around it).
  void mark(std::uint64_t tick) { extra_marks_.push_back(tick); }

  // Extra "key value" text for the report line.
  void note(const std::string& text) { notes_ += ", " + text; }

  std::string line() const {
    std::ostringstream out;
    out << "extremes: " << name_ << ": max energy gain " << fmt("%+.3f", gain_percent()) << "% of "
        << fmt("%.4g", scale_) << " J (E(0) " << fmt("%.4g", e0_) << " J";
    if (u0_ > 0.0) out << " + elastic U(0) " << fmt("%.4g", u0_) << " J";
    if (budget_ < e0_ + u0_) out << ", capped by the earlier budget";
    out << ", ground-referenced; at t=" << fmt("%.3f", tick_time(max_gain_tick_)) << " s)";
    out << ", area [" << fmt("%.3f", area_min_) << ", " << fmt("%.3f", area_max_) << "] after "
        << fmt("%g", bounds_.after) << " s (bounds [" << fmt("%g", bounds_.lo) << ", "
        << fmt("%g", bounds_.hi) << "]; whole run [" << fmt("%.3f", area_all_min_) << ", "
        << fmt("%.3f", area_all_max_) << "])";
    out << ", max strain " << fmt("%.2f", 100.0 * strain_max_)
        << "% at t=" << fmt("%.3f", tick_time(strain_max_tick_)) << " s";
    if (!samples_.empty()) {
      double stiff = 0.0;
      for (const Tire& t : world_.tires()) stiff = std::max(stiff, max_strain(t, kStiffCompliance));
      out << ", final max strain " << fmt("%.2f", 100.0 * samples_.back().strain) << "% (stiff constraints "
          << fmt("%.2f", 100.0 * stiff) << "%)";
      if (stiff > kTangledStrain)
        out << " SUSPECT: a stiff ring or spoke is left folded/tangled (not asserted)";
    }
    out << ", NaN " << (finite() ? std::string("none") : "at tick " + std::to_string(first_nonfinite_));
    out << ", guard "
        << (guard_count() == 0 ? std::string("none")
                               : std::to_string(guard_count()) + "x, first: " + world_.warnings().front());
    out << notes_;
    return out.str();
  }

  // Prints the report line and checks the case. `energy_limit` is the allowed gain in percent of
  // the scale (1%); `guard_expected` for the case designed to trip the divergence guard.
  // Returns whether it passed (and printed no timeline).
  bool judge(double energy_limit = 1.0, bool guard_expected = false, bool check_area = true) const {
    std::cout << line() << std::endl;
    const bool energy_ok = gain_percent() <= energy_limit;
    const bool area_ok = !check_area || (area_min_ >= bounds_.lo && area_max_ <= bounds_.hi);
    const bool guard_ok = guard_expected || guard_count() == 0;
    INFO(line());
    CHECK(finite());
    CHECK(gain_percent() <= energy_limit);
    if (check_area) {
      CHECK(area_min_ >= bounds_.lo);
      CHECK(area_max_ <= bounds_.hi);
    }
    if (!guard_expected) CHECK(world_.warnings().empty());
    const bool ok = finite() && energy_ok && area_ok && guard_ok;
    if (!ok) print_timeline();
    return ok;
  }

  // Tick, time, energy, area range and strain: evenly spaced, plus the ticks around every worst
  // moment (energy peak, area extremes, strain peak, first NaN, first guard warning).
  void print_timeline(int rows = 24) const {
    if (samples_.empty()) return;
    std::vector<std::uint64_t> marks;
    const std::uint64_t first = samples_.front().tick, last = samples_.back().tick;
    for (int r = 0; r <= rows; ++r)
      marks.push_back(first +
                      (last - first) * static_cast<std::uint64_t>(r) / static_cast<std::uint64_t>(rows));
    std::vector<std::uint64_t> worst = {max_gain_tick_,   area_min_tick_,   area_max_tick_,
                                        strain_max_tick_, first_nonfinite_, first_warning_tick_};
    worst.insert(worst.end(), extra_marks_.begin(), extra_marks_.end());
    for (const std::uint64_t k : worst)
      if (k != kNever)
        for (std::uint64_t d = 0; d < 7; ++d)
          if (k + d >= 3) marks.push_back(k + d - 3);
    std::sort(marks.begin(), marks.end());
    marks.erase(std::unique(marks.begin(), marks.end()), marks.end());
    std::cout << "  timeline of " << name_ << " (budget " << fmt("%.6g", budget_) << " J):\n"
              << "      tick    time(s)        energy(J)   gain(% scale)   area_min   area_max  strain(%)  "
                 "prop v(m/s)  finite\n";
    for (const Sample& s : samples_) {
      if (!std::binary_search(marks.begin(), marks.end(), s.tick)) continue;
      char row[200];
      std::snprintf(row, sizeof row, "  %8llu %10.4f %16.6g %15.4f %10.4f %10.4f %10.3f %12.4g  %s\n",
                    static_cast<unsigned long long>(s.tick), s.time, s.energy,
                    100.0 * (s.energy - budget_) / scale_, s.area_min, s.area_max, 100.0 * s.strain,
                    s.prop_speed, s.finite ? "yes" : "NO");
      std::cout << row;
    }
    std::cout.flush();
  }

  const std::vector<Sample>& samples() const { return samples_; }
  double budget() const { return budget_; }
  double scale() const { return scale_; }

 private:
  static constexpr std::uint64_t kNever = std::numeric_limits<std::uint64_t>::max();
  double tick_time(std::uint64_t tick) const {
    return tick == kNever ? -1.0 : static_cast<double>(tick) * world_.config().dt;
  }

  std::string name_;
  World& world_;
  AreaBounds bounds_;
  bool count_elastic_ = false;
  std::string notes_;
  std::vector<std::uint64_t> extra_marks_;
  std::vector<Sample> samples_;
  double e0_ = 0.0, u0_ = 0.0, budget_ = 0.0, scale_ = 1.0;
  double max_gain_ = -kInf;
  std::uint64_t max_gain_tick_ = kNever;
  double area_min_ = kInf, area_max_ = -kInf;
  double area_all_min_ = kInf, area_all_max_ = -kInf;
  std::uint64_t area_min_tick_ = kNever, area_max_tick_ = kNever;
  double strain_max_ = 0.0;
  std::uint64_t strain_max_tick_ = kNever;
  std::uint64_t first_nonfinite_ = kNever;
  std::uint64_t first_warning_tick_ = kNever;
  std::size_t warnings_seen_ = 0;
};

// ---------------------------------------------------------------------------------------------
// Worlds

// A tire of the default spec with its hub at `hub`.
inline TireSpec tire_spec(Vec2 hub) {
  TireSpec spec;
  spec.position = hub;
  return spec;
}

// Flat ground (top at y = 0), 2 km wide.
inline World ground_world(const SolverConfig& config = {}, Vec2 gravity = {0, -9.81}) {
  World world(config, gravity);
  world.add_obstacle({{{-1000, -10}, {1000, kGround}}});
  return world;
}

inline PropSpec box_prop(std::string name, Vec2 position, Vec2 size, double mass) {
  PropSpec p;
  p.name = std::move(name);
  p.shape = PropShape::box;
  p.type = PropType::dynamic_body;
  p.position = position;
  p.size = size;
  p.density = mass / (size.x * size.y);
  return p;
}

inline double tick_count(double seconds, const SolverConfig& config) {
  return std::ceil(seconds / config.dt - 1e-9);
}
inline int ticks_for(double seconds, const SolverConfig& config) {
  return static_cast<int>(tick_count(seconds, config));
}

}  // namespace tire::extremes
