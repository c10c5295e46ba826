// The tuning panel's sliders against the solver (docs/tuning-limits.md): at each end of each slider,
// and at each end of each pair of sliders, the other values at the level's, a tire dropped from
// 1.5 m, driven over a kerb and made to jump holds its shape: no cell between tread and rim turns
// inside out, no tread segment crosses another, nothing diverges. And the panel's changes reach the
// tires spawned after them.
//
// `tire_game_tests "[.tuning_sweep]" -s` runs the measurements the slider ranges come from: each
// key swept over its table's range, the pairs of slider ends, and every compliance softened at once
// under the heaviest loads, printing where the tire holds.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "internals.h"
#include "play/game_session.h"
#include "play/tuning.h"
#include "tire/tire/parameters.h"

using namespace game;

namespace {

// Flat ground, a 15 cm kerb 6 m ahead, the tire's bottom 1.5 m above the ground.
std::shared_ptr<const tire::Level> trial_level() {
  const tire::LevelLoad load = tire::load_level_text(
      R"({"name": "Tuning trial", "tires": [{"position": [0, 2.0]}],
          "obstacles": [{"min": [-40, -1], "max": [80, 0]}, {"min": [6, 0], "max": [7, 0.15]}]})",
      "trial.json");
  REQUIRE(load.level);
  return std::make_shared<const tire::Level>(*load.level);
}

// Twice the signed area of the quad a, b, c, d.
double quad_area2(tire::Vec2 a, tire::Vec2 b, tire::Vec2 c, tire::Vec2 d) {
  return (a.x * b.y - b.x * a.y) + (b.x * c.y - c.x * b.y) + (c.x * d.y - d.x * c.y) +
         (d.x * a.y - a.x * d.y);
}

bool segments_cross(tire::Vec2 p, tire::Vec2 q, tire::Vec2 r, tire::Vec2 s) {
  const auto orient = [](tire::Vec2 a, tire::Vec2 b, tire::Vec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
  };
  const double d1 = orient(p, q, r), d2 = orient(p, q, s), d3 = orient(r, s, p), d4 = orient(r, s, q);
  return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0)) && d1 != 0 && d2 != 0 && d3 != 0 && d4 != 0;
}

// What a trial saw, over all its ticks.
struct Trial {
  bool folded = false;        // a cell inside out or two tread segments crossing
  bool diverged = false;      // the world reset the tire, or a position is not finite
  double least_cell = 1e300;  // the smallest cell area over its rest area
  double least_area = 1e300;  // the smallest tire area over its rest area
  bool holds() const { return !folded && !diverged; }
};

// The cells (tread i, tread i+1, rim i+1, rim i) keep the orientation they are built with.
void look(const tire::Tire& t, const std::vector<double>& rest, Trial& out) {
  const std::uint32_t n = t.segments();
  const auto& x = t.particles.x;
  for (std::uint32_t i = 0; i < 2 * n; ++i)
    if (!std::isfinite(x[i].x) || !std::isfinite(x[i].y)) out.diverged = true;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    const double ratio = quad_area2(x[i], x[j], x[n + j], x[n + i]) / rest[i];
    out.least_cell = std::min(out.least_cell, ratio);
    if (!(ratio > 0.0)) out.folded = true;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    for (std::uint32_t k = i + 2; k < n; ++k) {
      if (i == 0 && k == n - 1) continue;  // neighbours across the seam
      if (segments_cross(x[i], x[(i + 1) % n], x[k], x[(k + 1) % n])) out.folded = true;
    }
  out.least_area = std::min(out.least_area, t.area_ratio());
}

// The panel makes `changes` on the trial level's world; then the tire falls, settles, drives right
// over the kerb (and jumps) for three seconds.
Trial run_trial(const std::vector<TuneEvent>& changes) {
  GameSession session;
  session.start("trial.json", trial_level());
  for (const TuneEvent& e : changes) session.queue(e);
  session.flush();
  Trial out;
  const tire::Tire& t = world_of(session).tires().front();
  const std::uint32_t n = t.segments();
  std::vector<double> rest(n);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    const auto& x = t.particles.x;
    rest[i] = quad_area2(x[i], x[j], x[n + j], x[n + i]);
  }
  for (int tick = 0; tick < 240; ++tick) {
    tire::TickInput input;
    input.steer = tick < 60 ? 0.0 : 1.0;
    input.jump = tick == 150;
    session.step(input);
    for (const std::string& w : session.take_warnings())
      if (w.find("diverged") != std::string::npos) out.diverged = true;
    look(world_of(session).tires().front(), rest, out);
  }
  return out;
}

Trial run_trial(const std::string& key, double value) { return run_trial({TuneEvent{key, value}}); }

// The values a slider offers at its ends.
std::pair<double, double> slider_ends(const tire::TunableParameter& p) {
  const SliderRange r = slider_range(p);
  return {r.min, r.max};
}

// Each slider's ends, paired with each other slider's ends (the solver's counts at their least).
std::vector<std::vector<TuneEvent>> end_pairs() {
  std::vector<std::vector<TuneEvent>> ends;  // per slider, its end values
  for (const tire::TunableParameter* p : tuning_parameters()) {
    const SliderSpec* spec = slider_spec(p->key);
    const auto [lo, hi] = slider_ends(*p);
    ends.push_back({TuneEvent{std::string(p->key), lo}});
    if (spec && spec->scale != SliderScale::integer)
      ends.back().push_back(TuneEvent{std::string(p->key), hi});
  }
  std::vector<std::vector<TuneEvent>> pairs;
  for (std::size_t i = 0; i < ends.size(); ++i)
    for (std::size_t j = i + 1; j < ends.size(); ++j)
      for (const TuneEvent& a : ends[i])
        for (const TuneEvent& b : ends[j]) pairs.push_back({a, b});
  return pairs;
}

}  // namespace

TEST_CASE("every tuning slider, at either end, leaves the tire whole", "[unit][game][tuning]") {
  int trials = 0;
  for (const tire::TunableParameter* p : tuning_parameters()) {
    const SliderSpec* spec = slider_spec(p->key);
    REQUIRE(spec != nullptr);
    // The solver's counts make no shape: their ends cost time, not a fold (more substeps and
    // iterations solve the same tire more exactly). The least of them is tried.
    const auto [lo, hi] = slider_ends(*p);
    std::vector<double> ends{lo, hi};
    if (spec->scale == SliderScale::integer) ends = {lo};
    for (const double v : ends) {
      const Trial t = run_trial(std::string(p->key), v);
      INFO(p->key << " = " << v << ": least cell " << t.least_cell << " of its rest area, least area "
                  << t.least_area << (t.folded ? ", folded" : "") << (t.diverged ? ", diverged" : ""));
      CHECK(t.holds());
      ++trials;
    }
  }
  CHECK(trials >= 20);
}

TEST_CASE("every pair of tuning slider ends leaves the tire whole", "[unit][game][tuning]") {
  int trials = 0;
  double least_cell = 1e300;
  for (const std::vector<TuneEvent>& pair : end_pairs()) {
    const Trial t = run_trial(pair);
    INFO(pair[0].key << " = " << pair[0].value << ", " << pair[1].key << " = " << pair[1].value
                     << ": least cell " << t.least_cell << " of its rest area, least area " << t.least_area
                     << (t.folded ? ", folded" : "") << (t.diverged ? ", diverged" : ""));
    CHECK(t.holds());
    least_cell = std::min(least_cell, t.least_cell);
    ++trials;
  }
  CHECK(trials >= 200);
  UNSCOPED_INFO("least cell over all pairs: " << least_cell);
}

TEST_CASE("each material preset chosen in the panel is the preset a level names, and holds its shape",
          "[unit][game][tuning]") {
  for (const tire::MaterialPreset& m : tire::material_presets()) {
    INFO(m.name);
    GameSession session;
    session.start("trial.json", trial_level());
    const Tuning chosen = with_material(session.tuning(), m);
    CHECK(material_of(chosen) == &m);
    const std::vector<TuneEvent> changes = tuning_changes(session.tuning(), chosen);
    for (const TuneEvent& e : changes) session.queue(e);
    session.flush();
    tire::TireSpec named;
    tire::find_material(m.name)->apply_to(named);
    const tire::TireSpec& got = world_of(session).tires().front().spec;
    CHECK(got.compliance.outer == named.compliance.outer);
    CHECK(got.compliance.inner == named.compliance.inner);
    CHECK(got.compliance.spoke == named.compliance.spoke);
    CHECK(got.compliance.pressure == named.compliance.pressure);
    CHECK(got.material_damping == named.material_damping);
    CHECK(got.friction == named.friction);
    CHECK(got.kinetic_friction == named.friction);  // the panel's one friction slider
    CHECK(got.restitution == named.restitution);
    CHECK(got.pressure == named.pressure);
    const Trial t = run_trial(changes);
    INFO("least cell " << t.least_cell << ", least area " << t.least_area);
    CHECK(t.holds());
  }
  // A slider moved after a preset makes it custom.
  Tuning soft = with_material(Tuning{}, *tire::find_material_preset("soft"));
  REQUIRE(soft.set("tires.friction", 0.31));
  CHECK(material_of(soft) == nullptr);
}

TEST_CASE("the tuning panel's changes reach the tires spawned after them", "[unit][game][tuning]") {
  GameSession session;
  session.start("trial.json", trial_level());
  Tuning wanted = session.tuning();
  REQUIRE(wanted.set("tires.friction", 0.25));
  REQUIRE(wanted.set("tires.compliance.spoke", 3e-4));
  REQUIRE(wanted.set("tires.pressure", 1.3));
  for (const TuneEvent& e : tuning_changes(session.tuning(), wanted)) session.queue(e);
  session.queue(SpawnTireEvent{{3, 3}});  // the player's click, after the changes
  session.flush();
  REQUIRE(world_of(session).tires().size() == 2);
  for (const tire::Tire& t : world_of(session).tires()) {
    INFO("tire " << t.id);
    CHECK(t.spec.friction == 0.25);
    CHECK(t.spec.kinetic_friction == 0.25);
    CHECK(t.spec.compliance.spoke == 3e-4);
    CHECK(t.spec.pressure == 1.3);
  }
  // A new level starts from its own values: the tuning belonged to the run before.
  session.start("trial.json", trial_level());
  CHECK(world_of(session).tires().front().spec.friction == tire::TireSpec{}.friction);
}

TEST_CASE("the tuning sweep: pairs of slider ends", "[.tuning_sweep]") {
  int failed = 0, trials = 0;
  double least_cell = 1e300;
  for (const std::vector<TuneEvent>& pair : end_pairs()) {
    const Trial t = run_trial(pair);
    ++trials;
    if (t.holds()) least_cell = std::min(least_cell, t.least_cell);
    if (t.holds()) continue;
    ++failed;
    std::printf("  %s = %g, %s = %g: %s, least cell %.3f, least area %.3f\n", pair[0].key.c_str(),
                pair[0].value, pair[1].key.c_str(), pair[1].value, t.diverged ? "DIVERGED" : "FOLDED",
                t.least_cell, t.least_area);
  }
  std::printf(
      "%d of %d pairs of slider ends fold or diverge; the least cell of those that hold: %.3f of its rest "
      "area\n",
      failed, trials, least_cell);
}

TEST_CASE("the tuning sweep: the softest corner", "[.tuning_sweep]") {
  // Every compliance at one value, with the pressure, the mass and the gravity at the ends that load
  // the tire most.
  const char* const compliances[] = {"tires.compliance.outer", "tires.compliance.inner",
                                     "tires.compliance.spoke", "tires.compliance.pressure"};
  const std::vector<std::vector<TuneEvent>> loads{
      {},
      {{"tires.pressure", 0.1}},
      {{"tires.mass_scale", 10.0}},
      {{"gravity.y", -30.0}},
      {{"tires.pressure", 0.1}, {"tires.mass_scale", 10.0}, {"gravity.y", -30.0}}};
  const char* const load_names[] = {"alone", "pressure 0.1", "mass x10", "gravity -30", "all three"};
  for (std::size_t l = 0; l < loads.size(); ++l) {
    std::printf("every compliance at c, %s\n", load_names[l]);
    for (double e = -7.0; e <= 0.0 + 1e-9; e += 0.5) {
      std::vector<TuneEvent> changes = loads[l];
      for (const char* k : compliances) changes.push_back({k, std::pow(10.0, e)});
      const Trial t = run_trial(changes);
      std::printf("  c = %-10.4g %s  least cell %7.3f  least area %6.3f\n", std::pow(10.0, e),
                  t.holds()    ? "holds "
                  : t.diverged ? "DIVERGED"
                               : "FOLDED",
                  t.least_cell, t.least_area);
    }
  }
  for (const char* k : compliances) {
    std::printf("%s alone, with pressure 0.1, mass x10 and gravity -30\n", k);
    for (double e = -7.0; e <= 0.0 + 1e-9; e += 0.5) {
      std::vector<TuneEvent> changes = loads.back();
      changes.push_back({k, std::pow(10.0, e)});
      const Trial t = run_trial(changes);
      std::printf("  %-10.4g %s  least cell %7.3f  least area %6.3f\n", std::pow(10.0, e),
                  t.holds()    ? "holds "
                  : t.diverged ? "DIVERGED"
                               : "FOLDED",
                  t.least_cell, t.least_area);
    }
  }
}

TEST_CASE("the tuning sweep: where each key holds the tire", "[.tuning_sweep]") {
  for (const tire::TunableParameter* p : tuning_parameters()) {
    const SliderSpec* spec = slider_spec(p->key);
    if (!spec || spec->scale == SliderScale::integer) continue;
    // Over the table's range: decades for an exponent slider, 24 steps (log where the slider is)
    // otherwise.
    const double inset = (p->range.max - p->range.min) * 1e-6;
    const double lo = p->range.min + (p->range.min_open ? inset : 0.0);
    const double hi = p->range.max;
    std::vector<double> values;
    if (spec->scale == SliderScale::exponent) {
      for (double e = std::ceil(std::log10(std::max(lo, 1e-12))); e <= std::log10(hi) + 1e-9; e += 0.5)
        values.push_back(std::pow(10.0, e));
    } else if (spec->scale == SliderScale::logarithmic && lo > 0.0) {
      for (int i = 0; i <= 24; ++i) values.push_back(lo * std::pow(hi / lo, i / 24.0));
    } else {
      const double a = std::max(lo, spec->min - 2.0 * (spec->max - spec->min)),
                   b = std::min(hi, spec->max + 2.0 * (spec->max - spec->min));
      for (int i = 0; i <= 24; ++i) values.push_back(a + (b - a) * i / 24.0);
    }
    std::printf("%s (slider %g to %g)\n", std::string(p->key).c_str(), spec->min, spec->max);
    for (const double v : values) {
      const Trial t = run_trial(std::string(p->key), v);
      std::printf("  %-10.4g %s  least cell %7.3f  least area %6.3f\n", v,
                  t.holds()    ? "holds "
                  : t.diverged ? "DIVERGED"
                               : "FOLDED",
                  t.least_cell, t.least_area);
    }
  }
}
