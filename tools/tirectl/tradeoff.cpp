// tirectl tradeoff: what each solver setting costs and how far it strays from the converged answer.
//
// For every scenario and tire resolution (segments) it runs a converged reference (many substeps,
// several iterations), checks that reference against one with half the substeps, then sweeps
// substeps × iterations (× tunnel clamp): each setting is run once to measure it (centroid
// trajectory, peak strain, area error, energy) and `repeats` times with nothing but World::step in
// the timed loop (each tick's median over the repeats, averaged over the ticks). Writes
// DIR/tradeoff.csv, DIR/tradeoff.svg (error against cost, log–log, one panel per scenario and
// resolution, Pareto front marked) and DIR/summary.txt
// (reference checks, fronts, recommendations, and the numbers for the two published claims).
#include "tradeoff.h"

#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

#include "cli_numbers.h"
#include "commands.h"
#include "svg_plot.h"
#include "tire/io/file_io.h"
#include "tire/tire/solver_config.h"
#include "tradeoff_scenarios.h"

namespace tirectl {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

struct Row {
  std::string scenario;
  SolverSettings s;
  std::string kind;  // sweep | reference
  double us_per_step = kNaN;
  double error = kNaN;            // RMS centroid distance to the reference of the same segments (m)
  double error_vs_finest = kNaN;  // ... to the reference of the finest tire in the run (m)
  double motion = kNaN;           // how far the reference's tire moves: RMS distance from its start (m)
  double relative_error() const { return error / motion; }
  double peak_strain = kNaN;
  double area_error = kNaN;
  double energy_drift = kNaN;
  double deflection = kNaN;
  double stiffness = kNaN;
  int resets = 0;
  int sweeps() const { return s.substeps * s.iterations; }
};

double rms_distance(const std::vector<tire::Vec2>& a, const std::vector<tire::Vec2>& b) {
  const std::size_t n = std::min(a.size(), b.size());
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += tire::length_squared(a[i] - b[i]);
  return n ? std::sqrt(sum / static_cast<double>(n)) : kNaN;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

std::string fmt(double v, int digits = 4) {
  if (!std::isfinite(v)) return "";
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.*g", digits, v);
  return buf;
}

std::string label(const SolverSettings& s) {
  std::string l =
      std::to_string(s.substeps) + "x" + std::to_string(s.iterations) + "x" + std::to_string(s.segments);
  if (s.tunnel_clamp != 1.0) l += " clamp " + fmt(s.tunnel_clamp, 3);
  return l;
}

// A length in the most readable unit.
std::string length_text(double m) {
  if (!std::isfinite(m)) return "n/a";
  const double a = std::abs(m);
  char buf[40];
  if (a >= 0.1)
    std::snprintf(buf, sizeof buf, "%.3g m", m);
  else if (a >= 0.01)
    std::snprintf(buf, sizeof buf, "%.3g cm", m * 100);
  else if (a >= 1e-3)
    std::snprintf(buf, sizeof buf, "%.3g mm", m * 1e3);
  else
    std::snprintf(buf, sizeof buf, "%.3g µm", m * 1e6);
  return buf;
}

std::string us_text(double us) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.3g µs", us);
  return buf;
}

// A progress bar on stderr while it runs (only on a terminal; otherwise a line per tenth done).
// The bar follows the expected work, the count follows the runs.
class Progress {
 public:
  Progress(std::size_t total, bool enabled, double total_weight)
      : total_(total),
        total_weight_(total_weight),
        enabled_(enabled),
        tty_(enabled && isatty(STDERR_FILENO) == 1) {}
  void update(std::size_t done, double done_weight, const std::string& what) {
    if (!enabled_) return;
    const double f = total_weight_ > 0.0 ? std::clamp(done_weight / total_weight_, 0.0, 1.0) : 1.0;
    if (!tty_) {
      const int tenth = static_cast<int>(f * 10.0);
      if (tenth > last_tenth_) {
        last_tenth_ = tenth;
        std::fprintf(stderr, "tradeoff: %3d%% (%zu/%zu runs)\n", tenth * 10, done, total_);
      }
      return;
    }
    constexpr int kWidth = 30;
    std::string bar(static_cast<std::size_t>(f * kWidth), '#');
    bar.resize(kWidth, '.');
    std::fprintf(stderr, "\r[%s] %zu/%zu %-36.36s", bar.c_str(), done, total_, what.c_str());
    std::fflush(stderr);
  }
  void note(const std::string& text) {
    if (tty_) std::fprintf(stderr, "\r%-80s\n", ("tradeoff: " + text).c_str());
  }
  void finish() {
    if (tty_) std::fprintf(stderr, "\r%-80s\r", "");
  }

 private:
  std::size_t total_;
  double total_weight_;
  bool enabled_;
  bool tty_;
  int last_tenth_ = 0;
};

// The points no other point beats on both cost and error, cheapest first.
std::vector<const Row*> pareto_front(std::vector<const Row*> rows) {
  std::sort(rows.begin(), rows.end(), [](const Row* a, const Row* b) {
    return a->us_per_step != b->us_per_step ? a->us_per_step < b->us_per_step : a->error < b->error;
  });
  std::vector<const Row*> front;
  double best = std::numeric_limits<double>::infinity();
  for (const Row* r : rows)
    if (r->error < best) front.push_back(r), best = r->error;
  return front;
}

const char* kSubstepColors[] = {"#d62728", "#ff7f0e", "#bcbd22", "#2ca02c", "#17becf",
                                "#1f77b4", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

int index_of(const std::vector<int>& values, int v) {
  const auto it = std::find(values.begin(), values.end(), v);
  return static_cast<int>(it - values.begin());
}

std::string render_plot(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                        const TradeoffOptions& o) {
  PlotSpec spec;
  spec.title = "tirectl tradeoff: centroid trajectory error against cost";
  spec.subtitle =
      "error = RMS distance of the tire's centroid from a converged reference run of the same scene and "
      "tire (its substeps x iterations in each title)\ncost = µs of World::step per 1/60 s tick (each tick's "
      "median over the repeats); tire material damping " +
      fmt(o.material_damping, 3) + " s; one row per scene, one column per tire resolution";
  spec.x_label = "cost (µs per step)";
  spec.y_label = "centroid error";
  spec.columns = static_cast<int>(o.segments.size());
  spec.color_title = "substeps";
  for (std::size_t i = 0; i < o.substeps.size(); ++i) {
    spec.colors.push_back(kSubstepColors[i % std::size(kSubstepColors)]);
    spec.color_labels.push_back(std::to_string(o.substeps[i]));
  }
  spec.marker_title = "iterations";
  for (const int it : o.iterations) spec.marker_labels.push_back(std::to_string(it));
  if (!o.extra_iterations.empty()) {
    std::string more;
    for (const int m : o.extra_iterations) more += (more.empty() ? "" : ",") + std::to_string(m);
    spec.marker_labels.push_back(more + " (1 substep only)");
  }
  if (o.tunnel_clamp.size() > 1) spec.hollow_label = "tunnel clamp != " + fmt(o.tunnel_clamp.front(), 3);
  spec.x_tick = microseconds_label;
  spec.y_tick = metres_label;
  for (const TradeoffScenario& sc : selected) {
    const std::string& scenario = sc.name;
    for (const int seg : o.segments) {
      PlotPanel panel;
      panel.title = scenario + ", " + std::to_string(seg) + " segments (ref. " +
                    std::to_string(sc.ref_substeps) + "x" + std::to_string(sc.ref_iterations) + ")";
      std::vector<const Row*> sweep;
      for (const Row& r : rows) {
        if (r.scenario != scenario || r.s.segments != seg) continue;
        if (r.kind == "reference") {
          panel.floor = r.error;
          continue;
        }
        sweep.push_back(&r);
        PlotPoint p;
        p.x = r.us_per_step;
        p.y = r.error;
        p.color = index_of(o.substeps, r.s.substeps);
        p.marker = std::min(index_of(o.iterations, r.s.iterations), static_cast<int>(o.iterations.size()));
        p.hollow = r.s.tunnel_clamp != o.tunnel_clamp.front();
        p.tooltip = scenario + " " + label(r.s) + ": " + us_text(r.us_per_step) + " per step, error " +
                    length_text(r.error);
        panel.points.push_back(p);
      }
      for (const Row* r : pareto_front(sweep)) panel.front.emplace_back(r->us_per_step, r->error);
      spec.panels.push_back(std::move(panel));
    }
  }
  return render_svg(spec);
}

std::string render_csv(const std::vector<Row>& rows) {
  std::ostringstream out;
  out << "scenario,substeps,iterations,segments,us_per_step,error,relative_error,error_vs_finest,peak_strain,"
         "area_error,"
         "energy_drift,deflection,stiffness,tunnel_clamp,material_damping,sweeps,resets,kind\n";
  for (const Row& r : rows)
    out << r.scenario << "," << r.s.substeps << "," << r.s.iterations << "," << r.s.segments << ","
        << fmt(r.us_per_step) << "," << fmt(r.error) << "," << fmt(r.relative_error()) << ","
        << fmt(r.error_vs_finest) << "," << fmt(r.peak_strain) << "," << fmt(r.area_error) << ","
        << fmt(r.energy_drift) << "," << fmt(r.deflection) << "," << fmt(r.stiffness, 5) << ","
        << fmt(r.s.tunnel_clamp) << "," << fmt(r.s.material_damping) << "," << r.sweeps() << "," << r.resets
        << "," << r.kind << "\n";
  return out.str();
}

const Row* find_row(const std::vector<Row>& rows, const std::string& scenario, int substeps, int iterations,
                    int segments, double clamp, const char* kind = "sweep") {
  for (const Row& r : rows)
    if (r.scenario == scenario && r.s.substeps == substeps && r.s.iterations == iterations &&
        r.s.segments == segments && r.s.tunnel_clamp == clamp && r.kind == kind)
      return &r;
  return nullptr;
}

const Row* reference_row(const std::vector<Row>& rows, const std::string& scenario, int segments) {
  for (const Row& r : rows)
    if (r.scenario == scenario && r.s.segments == segments && r.kind == "reference") return &r;
  return nullptr;
}

std::string render_summary(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                           const TradeoffOptions& o,
                           const std::map<std::pair<std::string, int>, double>& best_sweep) {
  std::ostringstream out;
  char line[512];
  const double clamp = o.tunnel_clamp.front();
  std::vector<std::string> scenarios;
  for (const TradeoffScenario& sc : selected) scenarios.push_back(sc.name);

  out << "Scenarios (dt = 1/60 s, TireSpec{} but material damping " << fmt(o.material_damping, 3) << " s):\n";
  for (const TradeoffScenario& sc : selected) out << "  " << sc.name << ": " << sc.what << "\n";

  out << "\nReferences (substeps x iterations), each checked against one with half the substeps; the\n"
         "reference's own error is the RMS centroid distance between the two (an upper bound if the error\n"
         "falls at least linearly with the substep):\n";
  std::snprintf(line, sizeof line, "  %-9s %8s %10s %12s %14s %18s %8s\n", "scenario", "segments",
                "reference", "us/step", "ref. error", "best sweep error", "ratio");
  out << line;
  int unconverged = 0;
  for (const TradeoffScenario& sc : selected)
    for (const int seg : o.segments) {
      const Row* r = reference_row(rows, sc.name, seg);
      if (!r) continue;
      const auto it = best_sweep.find({r->scenario, seg});
      const double best = it == best_sweep.end() ? kNaN : it->second;
      const bool low = !(best >= 3.0 * r->error);
      unconverged += low;
      const std::string setting = std::to_string(r->s.substeps) + "x" + std::to_string(r->s.iterations);
      std::snprintf(line, sizeof line, "  %-9s %8d %10s %12.4g %14s %18s %8.3g%s\n", r->scenario.c_str(), seg,
                    setting.c_str(), r->us_per_step, length_text(r->error).c_str(), length_text(best).c_str(),
                    best / r->error, low ? "  <- the reference is not well below the sweep" : "");
      out << line;
    }
  if (unconverged)
    out << "  " << unconverged
        << " reference(s) are not at least 3 times below the best sweep setting's error: there, the "
           "smallest\n"
           "  errors measure the reference as much as the setting.\n";

  out << "\nPareto fronts (cheapest first; setting = substeps x iterations x segments):\n";
  for (const std::string& sc : scenarios)
    for (const int seg : o.segments) {
      std::vector<const Row*> sweep;
      for (const Row& r : rows)
        if (r.scenario == sc && r.s.segments == seg && r.kind == "sweep") sweep.push_back(&r);
      out << "  " << sc << ", " << seg << " segments:";
      for (const Row* r : pareto_front(sweep))
        out << "  " << label(r->s) << " (" << us_text(r->us_per_step) << ", " << length_text(r->error) << ")";
      out << "\n";
    }

  // Recommended settings: per tire resolution, the cheapest setting (mean µs per step over the
  // scenarios) whose error in every scenario is within max(absolute, relative × the reference's
  // motion). A scenario no setting of the sweep brings within its bound cannot decide and is named.
  out << "\nRecommended settings: per tire resolution, the cheapest setting (mean cost over the scenarios) "
         "whose\n"
         "error in each deciding scenario is within max(absolute bound, relative bound x how far the "
         "reference's tire\n"
         "moves, 3 times the reference's own error). Bounces (";
  {
    std::string sep;
    for (const TradeoffScenario& sc : selected)
      if (!sc.decides) out << sep << sc.name, sep = ", ";
  }
  out << ") do not decide: their errors are shown.\n";
  struct Class {
    const char* name;
    double absolute, relative;
  };
  for (const Class& cls : {Class{"game", o.game_error, o.game_relative},
                           Class{"accuracy", o.accurate_error, o.accurate_relative}}) {
    out << "  " << cls.name << " (within " << length_text(cls.absolute) << " or "
        << fmt(100 * cls.relative, 3) << "% of the motion):\n";
    for (const int seg : o.segments) {
      std::map<std::string, double> bound;
      std::vector<std::string> deciding, undecided;
      for (const TradeoffScenario& scenario : selected) {
        const std::string& sc = scenario.name;
        const Row* ref = reference_row(rows, sc, seg);
        if (!ref) continue;
        bound[sc] = std::max({cls.absolute, cls.relative * ref->motion, 3.0 * ref->error});
        bool reachable = false;
        for (const Row& r : rows)
          if (r.kind == "sweep" && r.scenario == sc && r.s.segments == seg && r.s.tunnel_clamp == clamp &&
              r.error <= bound[sc])
            reachable = true;
        (reachable && scenario.decides ? deciding : undecided).push_back(sc);
      }
      std::optional<std::pair<int, int>> best;
      double best_us = std::numeric_limits<double>::infinity();
      for (const int ss : o.substeps)
        for (const int it : o.iterations) {
          double sum = 0.0;
          bool ok = true;
          for (const std::string& sc : scenarios) {
            const Row* r = find_row(rows, sc, ss, it, seg, clamp);
            if (!r) {
              ok = false;
              break;
            }
            sum += r->us_per_step;
            if (std::find(deciding.begin(), deciding.end(), sc) != deciding.end() && !(r->error <= bound[sc]))
              ok = false;
          }
          const double mean = sum / static_cast<double>(scenarios.size());
          if (ok && !deciding.empty() && mean < best_us) best_us = mean, best = std::pair{ss, it};
        }
      // Cost (mean over the scenarios) and each scenario's error of one setting, with notes.
      auto describe = [&](int ss, int it) {
        double sum = 0.0;
        std::string errors;
        for (const std::string& sc : scenarios) {
          const Row* r = find_row(rows, sc, ss, it, seg, clamp);
          if (!r) return std::string("not in the sweep");
          sum += r->us_per_step;
          const bool decides = std::find(deciding.begin(), deciding.end(), sc) != deciding.end();
          std::string note;
          if (!decides) {
            const auto sc_it =
                std::find_if(selected.begin(), selected.end(), [&](const auto& x) { return x.name == sc; });
            note = sc_it->decides ? " (no setting within " + length_text(bound[sc]) + ")"
                                  : " (" + fmt(100.0 * r->relative_error(), 2) + "% of the motion)";
          } else if (!(r->error <= bound[sc])) {
            note = " (over " + length_text(bound[sc]) + ")";
          }
          errors += " " + sc + " " + length_text(r->error) + note;
        }
        return std::to_string(ss) + "x" + std::to_string(it) + ", " +
               us_text(sum / static_cast<double>(scenarios.size())) + " per step;" + errors;
      };
      out << "    " << std::setw(2) << seg
          << " segments: " << (best ? describe(best->first, best->second) : "none in the sweep") << "\n";
      const tire::SolverConfig engine_default;
      if (cls.relative == o.game_relative &&
          (!best || best->first != engine_default.substeps || best->second != engine_default.iterations))
        out << "      (the engine's default " << describe(engine_default.substeps, engine_default.iterations)
            << ")\n";
    }
  }

  // Claim 1 (Macklin et al. 2016): stiffness independent of iterations and time step.
  out << "\nClaim 1, stiffness = load / static deflection, relative to the reference's (1.00 = same "
         "stiffness):\n";
  for (const TradeoffScenario& scenario : selected) {
    if (!scenario.deflection) continue;
    const std::string& sc = scenario.name;
    for (const int seg : o.segments) {
      const Row* ref = reference_row(rows, sc, seg);
      if (!ref || !std::isfinite(ref->stiffness)) continue;
      out << "  " << sc << ", " << seg << " segments: reference deflection " << length_text(ref->deflection)
          << ", stiffness " << fmt(ref->stiffness / 1000.0, 4) << " kN/m\n";
      std::snprintf(line, sizeof line, "    %10s", "substeps\\it");
      out << line;
      for (const int it : o.iterations) std::snprintf(line, sizeof line, " %7d", it), out << line;
      out << "\n";
      for (const int ss : o.substeps) {
        std::snprintf(line, sizeof line, "    %10d", ss);
        out << line;
        for (const int it : o.iterations) {
          const Row* r = find_row(rows, sc, ss, it, seg, clamp);
          std::snprintf(line, sizeof line, " %7s", r ? fmt(r->stiffness / ref->stiffness, 3).c_str() : "");
          out << line;
        }
        out << "\n";
      }
    }
  }

  // Claim 2 (Macklin et al. 2019): n substeps x 1 iteration beat 1 substep x n iterations.
  out << "\nClaim 2, n substeps x 1 iteration against 1 substep x n iterations (same n sweeps per step):\n";
  std::snprintf(line, sizeof line, "  %-9s %4s %4s %14s %10s %14s %10s %10s\n", "scenario", "segs", "n",
                "error nx1", "us nx1", "error 1xn", "us 1xn", "1xn/nx1");
  out << line;
  int small_wins = 0, large_wins = 0;
  for (const std::string& sc : scenarios)
    for (const int seg : o.segments)
      for (const int n : o.substeps) {
        if (n < 2) continue;
        const Row* a = find_row(rows, sc, n, 1, seg, clamp);
        const Row* b = find_row(rows, sc, 1, n, seg, clamp);
        if (!a || !b) continue;
        (a->error < b->error ? small_wins : large_wins)++;
        std::snprintf(line, sizeof line, "  %-9s %4d %4d %14s %10.3g %14s %10.3g %10.3g\n", sc.c_str(), seg,
                      n, length_text(a->error).c_str(), a->us_per_step, length_text(b->error).c_str(),
                      b->us_per_step, b->error / a->error);
        out << line;
      }
  out << "  n x 1 has the smaller error in " << small_wins << " of " << small_wins + large_wins
      << " pairs.\n";

  // The same at equal measured cost: a substep costs more than a sweep (prediction, contacts,
  // velocities), so n x 1 is set against the 1 x m curve at n x 1's cost, interpolated log–log
  // between the two 1 x m settings around it.
  out << "\nClaim 2 at equal measured cost: n x 1 against 1 substep x m iterations at the same µs per step\n"
         "(the 1 x m error interpolated log-log between the 1 x m settings that bracket the cost):\n";
  std::snprintf(line, sizeof line, "  %-9s %4s %6s %14s %10s %11s %16s %10s\n", "scenario", "segs", "nx1",
                "error", "us", "1xm around", "1xm error there", "ratio");
  out << line;
  int wins = 0, losses = 0, undecided = 0;
  for (const std::string& sc : scenarios)
    for (const int seg : o.segments) {
      std::vector<const Row*> curve;  // 1 x m, by cost
      for (const Row& r : rows)
        if (r.kind == "sweep" && r.scenario == sc && r.s.segments == seg && r.s.substeps == 1 &&
            r.s.tunnel_clamp == clamp)
          curve.push_back(&r);
      std::sort(curve.begin(), curve.end(),
                [](const Row* x, const Row* y) { return x->us_per_step < y->us_per_step; });
      for (const int n : o.substeps) {
        if (n < 2) continue;
        const Row* a = find_row(rows, sc, n, 1, seg, clamp);
        if (!a) continue;
        const auto hi = std::find_if(curve.begin(), curve.end(),
                                     [&](const Row* r) { return r->us_per_step >= a->us_per_step; });
        if (hi == curve.end() || hi == curve.begin()) {
          ++undecided;
          continue;
        }
        const Row* lo_row = *(hi - 1);
        const Row* hi_row = *hi;
        const double f = std::log(a->us_per_step / lo_row->us_per_step) /
                         std::log(hi_row->us_per_step / lo_row->us_per_step);
        const double e = std::exp(std::log(lo_row->error) + f * std::log(hi_row->error / lo_row->error));
        (a->error < e ? wins : losses)++;
        const std::string around =
            std::to_string(lo_row->s.iterations) + "-" + std::to_string(hi_row->s.iterations);
        std::snprintf(line, sizeof line, "  %-9s %4d %6s %14s %10.3g %11s %16s %10.3g\n", sc.c_str(), seg,
                      (std::to_string(n) + "x1").c_str(), length_text(a->error).c_str(), a->us_per_step,
                      around.c_str(), length_text(e).c_str(), e / a->error);
        out << line;
      }
    }
  out << "  n x 1 has the smaller error in " << wins << " of " << wins + losses << " pairs (" << undecided
      << " n x 1 settings fall outside the cost range of the 1 x m settings).\n";
  return out.str();
}

}  // namespace

CLI::App* add_tradeoff_command(CLI::App& app, TradeoffOptions& options) {
  using tire_tools::integer_in;
  using tire_tools::number_in;
  const tire::Range kPositive{0, tire_tools::kUnbounded, true, true};
  CLI::App* cmd = app.add_subcommand(
      "tradeoff",
      "Measure error against cost over substeps, iterations and segments; writes DIR/tradeoff.csv and .svg");
  cmd->add_option("--substeps", options.substeps, "Substeps to sweep, e.g. 1,2,4,8")
      ->delimiter(',')
      ->transform(integer_in({1, 256}));
  cmd->add_option("--iterations", options.iterations, "Iterations to sweep, e.g. 1,2,4")
      ->delimiter(',')
      ->transform(integer_in({1, 64}));
  cmd->add_option("--segments", options.segments, "Tire segments to sweep, e.g. 12,28,64")
      ->delimiter(',')
      ->transform(integer_in({6, 256}));
  cmd->add_option("--tunnel-clamp", options.tunnel_clamp,
                  "Anti-tunneling clamps to sweep (rest segments per substep); the first is the main one")
      ->delimiter(',')
      ->check(number_in({0.1, 1000}));
  cmd->add_option("--max-sweeps", options.max_sweeps,
                  "Skip settings with substeps x iterations above this (default 512)")
      ->transform(integer_in({1, 65536}));
  cmd->add_option("--scenarios", options.scenarios,
                  "Only these scenarios: rest,rest-soft,drop,slope,crush,impact")
      ->delimiter(',');
  cmd->add_option("--repeats", options.repeats,
                  "Timed runs per setting; each tick's median over them is used (default 3)")
      ->transform(integer_in({1, 1000}));
  cmd->add_option("--ref-substeps", options.ref_substeps,
                  "Substeps of the converged reference (default: each scenario's own)")
      ->transform(integer_in({1, 65536}));
  cmd->add_option("--ref-iterations", options.ref_iterations,
                  "Iterations of the converged reference (default: each scenario's own)")
      ->transform(integer_in({1, 64}));
  cmd->add_option("--material-damping", options.material_damping,
                  "The tire's material damping time (s) in every run (default 1e-4; TireSpec's is 5e-3)")
      ->check(number_in({0, 1}));
  cmd->add_option("--game-error", options.game_error,
                  "A game setting's centroid error bound in each scenario (m; default 0.025)...")
      ->check(number_in(kPositive));
  cmd->add_option("--game-relative", options.game_relative,
                  "...or this fraction of how far the tire moves, if larger (default 0.1)")
      ->check(number_in(kPositive));
  cmd->add_option("--accurate-error", options.accurate_error,
                  "An accurate setting's centroid error bound (m; default 0.0025)...")
      ->check(number_in(kPositive));
  cmd->add_option("--accurate-relative", options.accurate_relative,
                  "...or this fraction of how far the tire moves, if larger (default 0.01)")
      ->check(number_in(kPositive));
  cmd->add_option("--out", options.out, "Output directory (created if missing)");
  cmd->add_flag("!--no-progress", options.progress, "No progress bar on stderr");
  return cmd;
}

int tradeoff(const TradeoffOptions& options) {
  TradeoffOptions o = options;
  auto tidy = [](auto& v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
  };
  tidy(o.substeps);
  tidy(o.iterations);
  tidy(o.segments);
  // The first clamp given is the one the fronts and the claims use.
  {
    std::vector<double> clamps;
    for (const double c : o.tunnel_clamp)
      if (std::find(clamps.begin(), clamps.end(), c) == clamps.end()) clamps.push_back(c);
    o.tunnel_clamp = clamps;
  }
  for (const std::string& name : o.scenarios) {
    if (std::none_of(tradeoff_scenarios().begin(), tradeoff_scenarios().end(),
                     [&](const TradeoffScenario& sc) { return sc.name == name; })) {
      std::cerr << "tirectl tradeoff: unknown scenario \"" << name << "\"; scenarios:";
      for (const TradeoffScenario& sc : tradeoff_scenarios()) std::cerr << " " << sc.name;
      std::cerr << "\n";
      return 2;
    }
  }
  if (o.substeps.empty() || o.iterations.empty() || o.segments.empty() || o.tunnel_clamp.empty()) {
    std::cerr << "tirectl tradeoff: --substeps, --iterations, --segments and --tunnel-clamp need at least "
                 "one value\n";
    return 2;
  }
  // The scenarios to run, in the table's order, with their references.
  std::vector<TradeoffScenario> selected;
  for (const TradeoffScenario& sc : tradeoff_scenarios()) {
    if (!o.scenarios.empty() &&
        std::find(o.scenarios.begin(), o.scenarios.end(), sc.name) == o.scenarios.end())
      continue;
    selected.push_back(sc);
    if (o.ref_substeps > 0) selected.back().ref_substeps = o.ref_substeps;
    if (o.ref_iterations > 0) selected.back().ref_iterations = o.ref_iterations;
  }
  std::vector<std::string> scenarios;
  for (const TradeoffScenario& sc : selected) scenarios.push_back(sc.name);
  if (std::find(o.substeps.begin(), o.substeps.end(), 1) != o.substeps.end()) {
    std::vector<int> wanted = o.substeps;
    wanted.push_back(std::min(2 * o.substeps.back(), 256));
    for (const int m : wanted)
      if (m > 1 && std::find(o.iterations.begin(), o.iterations.end(), m) == o.iterations.end() &&
          std::find(o.extra_iterations.begin(), o.extra_iterations.end(), m) == o.extra_iterations.end())
        o.extra_iterations.push_back(m);
  }

  const std::filesystem::path dir = o.out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::cerr << "tirectl tradeoff: cannot create " << dir.string() << ": " << ec.message() << "\n";
    return 2;
  }

  // Every run to measure: per scenario and segments a reference, its check and the sweep.
  struct Job {
    const TradeoffScenario* scenario;
    SolverSettings settings;
    std::string kind;  // reference | check | sweep
    RunMeasure measure;
    double weight;  // expected cost, for the progress bar
  };
  std::vector<Job> jobs;
  for (const TradeoffScenario& sc : selected)
    for (const int seg : o.segments) {
      auto add = [&](int ss, int it, double clamp, const char* kind) {
        const SolverSettings s{ss, it, seg, clamp, o.material_damping};
        jobs.push_back({&sc, s, kind, {}, static_cast<double>(sc.ticks) * ss * (it + 2.0) * (seg + 8.0)});
      };
      add(sc.ref_substeps, sc.ref_iterations, 1.0, "reference");
      // The check runs at half the reference's substeps: if the error falls as h^p, their distance
      // is (2^p - 1) times the reference's own error, so it never understates it.
      add(std::max(1, sc.ref_substeps / 2), sc.ref_iterations, 1.0, "check");
      for (const double clamp : o.tunnel_clamp)
        for (const int ss : o.substeps)
          for (const int it : o.iterations)
            if (ss * it <= o.max_sweeps) add(ss, it, clamp, "sweep");
      // For claim 2: 1 substep x n iterations for every n of --substeps (and one more doubling),
      // so that n x 1 meets 1 x n at equal sweeps and 1 x m at equal measured cost.
      for (const int m : o.extra_iterations) add(1, m, o.tunnel_clamp.front(), "sweep");
    }
  const std::size_t sweep_count = static_cast<std::size_t>(
      std::count_if(jobs.begin(), jobs.end(), [](const Job& j) { return j.kind == "sweep"; }));
  double total_weight = 0.0;
  for (const Job& j : jobs) total_weight += j.weight;
  // Timing: each sweep run `repeats` more times, serially.
  double sweep_weight = 0.0;
  for (const Job& j : jobs)
    if (j.kind == "sweep") sweep_weight += j.weight * o.repeats;
  Progress progress(jobs.size() + sweep_count, o.progress, total_weight + sweep_weight);

  // Phase 1: measure every run, on every core (no timing depends on these).
  {
    std::mutex mutex;
    std::mutex box2d;  // one scene with dynamic props at a time (see TradeoffScenario::dynamic_props)
    std::atomic<std::size_t> next{0};
    std::size_t done = 0;
    double done_weight = 0.0;
    // Longest first, so that the big references do not end up last on one core.
    std::vector<std::size_t> order(jobs.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return jobs[a].weight > jobs[b].weight; });
    auto worker = [&] {
      for (std::size_t k; (k = next.fetch_add(1)) < order.size();) {
        Job& job = jobs[order[k]];
        if (job.scenario->dynamic_props) {
          const std::lock_guard<std::mutex> one_at_a_time(box2d);
          job.measure = measure_run(*job.scenario, job.settings);
        } else {
          job.measure = measure_run(*job.scenario, job.settings);
        }
        const std::lock_guard<std::mutex> lock(mutex);
        ++done;
        done_weight += job.weight;
        progress.update(done, done_weight, "measure " + job.scenario->name + " " + label(job.settings));
      }
    };
    const unsigned threads = std::max(1u, std::min(std::thread::hardware_concurrency(), 8u));
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) pool.emplace_back(worker);
    worker();
    for (std::thread& t : pool) t.join();
    progress.note("measured " + std::to_string(jobs.size()) + " runs");
  }

  // Phase 2: errors against the references; cost of each sweep setting, one run at a time.
  std::vector<Row> rows;
  std::map<std::pair<std::string, int>, double> best_sweep;
  const int finest = o.segments.back();
  auto find_job = [&](const std::string& scenario, int seg, const char* kind) -> const Job* {
    for (const Job& j : jobs)
      if (j.scenario->name == scenario && j.settings.segments == seg && j.kind == kind) return &j;
    return nullptr;
  };
  auto fill = [](Row& row, const TradeoffScenario& sc, const RunMeasure& m) {
    row.peak_strain = m.peak_strain;
    row.area_error = m.area_error;
    row.energy_drift = (m.energy_end - m.energy_start) / m.energy_start;
    row.deflection = m.deflection;
    if (sc.deflection && m.deflection > 0.0) row.stiffness = sc.load / m.deflection;
    row.resets = m.resets;
  };
  std::size_t done = jobs.size();
  double done_weight = total_weight;
  for (const Job& job : jobs) {
    const std::string& name = job.scenario->name;
    const int seg = job.settings.segments;
    const Job* ref = find_job(name, seg, "reference");
    const Job* finest_ref = find_job(name, finest, "reference");
    if (job.kind == "check") continue;
    Row row{name, job.settings, job.kind};
    fill(row, *job.scenario, job.measure);
    row.motion = rms_distance(ref->measure.centroid, std::vector<tire::Vec2>(ref->measure.centroid.size(),
                                                                             ref->measure.centroid.front()));
    row.error_vs_finest = rms_distance(job.measure.centroid, finest_ref->measure.centroid);
    if (job.kind == "reference") {
      row.error = rms_distance(job.measure.centroid, find_job(name, seg, "check")->measure.centroid);
      row.us_per_step = job.measure.us_per_step;  // one run, timed while measuring
    } else {
      row.error = rms_distance(job.measure.centroid, ref->measure.centroid);
      progress.update(done, done_weight, "time " + name + " " + label(job.settings));
      // Each tick's median over the repeats, then the mean over the ticks: a repeat that the OS
      // interrupted at some tick is outvoted there, and the cost still follows the scene.
      std::vector<std::vector<double>> runs;
      for (int r = 0; r < o.repeats; ++r) runs.push_back(time_run(*job.scenario, job.settings));
      double sum = 0.0;
      std::vector<double> at_tick(runs.size());
      for (std::size_t t = 0; t < runs.front().size(); ++t) {
        for (std::size_t r = 0; r < runs.size(); ++r) at_tick[r] = runs[r][t];
        sum += median(at_tick);
      }
      row.us_per_step = sum / static_cast<double>(runs.front().size());
      auto [it, inserted] = best_sweep.try_emplace({name, seg}, row.error);
      if (!inserted) it->second = std::min(it->second, row.error);
      ++done;
      done_weight += job.weight * o.repeats;
    }
    rows.push_back(row);
  }
  progress.finish();

  // Rows in reading order: scenario, segments ascending, reference first.
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    const auto ia = std::find(scenarios.begin(), scenarios.end(), a.scenario);
    const auto ib = std::find(scenarios.begin(), scenarios.end(), b.scenario);
    if (ia != ib) return ia < ib;
    if (a.s.segments != b.s.segments) return a.s.segments < b.s.segments;
    return a.kind == "reference" && b.kind != "reference";
  });

  const std::string summary = render_summary(rows, selected, o, best_sweep);
  const std::pair<std::filesystem::path, std::string> files[] = {
      {dir / "tradeoff.csv", render_csv(rows)},
      {dir / "tradeoff.svg", render_plot(rows, selected, o)},
      {dir / "summary.txt", summary},
  };
  for (const auto& [path, text] : files) {
    std::string error;
    if (!tire::write_file_atomically(path, text, error)) {
      std::cerr << "tirectl tradeoff: " << path.string() << ": " << error << "\n";
      return 2;
    }
  }
  std::cerr << summary;
  for (const auto& [path, text] : files) std::cout << "wrote " << path.string() << "\n";
  return 0;
}

}  // namespace tirectl
