// The summary of `tirectl tradeoff` (DIR/summary.txt and stderr): the references and how far they
// can be trusted, the Pareto fronts, the recommended settings and the two published claims, each
// per solver method.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iomanip>
#include <optional>
#include <sstream>

#include "tradeoff_report.h"

namespace tirectl {

namespace {

bool contains(const std::vector<std::string>& v, const std::string& s) {
  return std::find(v.begin(), v.end(), s) != v.end();
}

void references(std::ostringstream& out, const std::vector<Row>& rows,
                const std::vector<TradeoffScenario>& selected, const TradeoffOptions& o,
                const BestSweep& best_sweep) {
  char line[512];
  const bool cross = std::find(o.method_list.begin(), o.method_list.end(), tire::SolverMethod::global) !=
                     o.method_list.end();
  out << "\nReferences (Gauss-Seidel, substeps x iterations), each checked against one with half the "
         "substeps;\n"
         "the reference's own error is the RMS centroid distance between the two (an upper bound if the "
         "error\n"
         "falls at least linearly with the substep). The references are physics, not a method: the last "
         "column\n"
         "is the global method at the reference's substeps x 1 iteration, its distance from the reference:\n";
  std::snprintf(line, sizeof line, "  %-9s %8s %10s %12s %14s %18s %8s %14s\n", "scenario", "segments",
                "reference", "us/step", "ref. error", "best sweep error", "ratio",
                cross ? "global there" : "");
  out << line;
  int unconverged = 0;
  for (const TradeoffScenario& sc : selected)
    for (const int seg : o.segments) {
      const Row* r = reference_row(rows, sc.name, seg);
      if (!r) continue;
      const Row* x = reference_row(rows, sc.name, seg, kCrossCheck);
      const auto it = best_sweep.find({r->scenario, seg});
      const double best = it == best_sweep.end() ? kNaN : it->second;
      const bool low = !(best >= 3.0 * r->error);
      unconverged += low;
      const std::string setting = std::to_string(r->s.substeps) + "x" + std::to_string(r->s.iterations);
      std::snprintf(line, sizeof line, "  %-9s %8d %10s %12.4g %14s %18s %8.3g %14s%s\n", r->scenario.c_str(),
                    seg, setting.c_str(), r->us_per_step, length_text(r->error).c_str(),
                    length_text(best).c_str(), best / r->error, x ? length_text(x->error).c_str() : "",
                    low ? "  <- the reference is not well below the sweep" : "");
      out << line;
    }
  if (unconverged)
    out << "  " << unconverged
        << " reference(s) are not at least 3 times below the best sweep setting's error: there, the "
           "smallest\n"
           "  errors measure the reference as much as the setting.\n";
}

void fronts(std::ostringstream& out, const std::vector<Row>& rows, const std::vector<std::string>& scenarios,
            const TradeoffOptions& o) {
  out << "\nPareto fronts (cheapest first; setting = substeps x iterations x segments), per method:\n";
  for (const std::string& sc : scenarios)
    for (const int seg : o.segments)
      for (const tire::SolverMethod m : o.method_list) {
        std::vector<const Row*> sweep;
        for (const Row& r : rows)
          if (r.scenario == sc && r.s.segments == seg && r.s.method == m && r.kind == kSweep)
            sweep.push_back(&r);
        out << "  " << sc << ", " << seg << " segments, " << method_text(m) << ":";
        for (const Row* r : pareto_front(sweep))
          out << "  " << label(r->s) << " (" << us_text(r->us_per_step) << ", " << length_text(r->error)
              << ")";
        out << "\n";
      }
}

// Recommended settings: per method and tire resolution, the cheapest setting (mean µs per step over
// the scenarios) whose error in every scenario is within max(absolute, relative × the reference's
// motion). A scenario no setting of the method's sweep brings within its bound cannot decide and is
// named.
void recommendations(std::ostringstream& out, const std::vector<Row>& rows,
                     const std::vector<TradeoffScenario>& selected, const std::vector<std::string>& scenarios,
                     const TradeoffOptions& o) {
  const double clamp = o.tunnel_clamp.front();
  out << "\nRecommended settings: per method and tire resolution, the cheapest setting (mean cost over the\n"
         "scenarios) whose error in each deciding scenario is within max(absolute bound, relative bound x "
         "how far\n"
         "the reference's tire moves, 3 times the reference's own error).";
  {
    std::string bounces;
    for (const TradeoffScenario& sc : selected)
      if (!sc.decides) bounces += (bounces.empty() ? "" : ", ") + sc.name;
    if (!bounces.empty()) out << " Bounces (" << bounces << ") do not decide: their errors are shown.";
  }
  out << "\nStiffness: load / static deflection over the reference's (1 = the converged stiffness), for the "
         "static scenes.\n"
         "\"game, stiff\": the cheapest game setting whose stiffness is also at least "
      << fmt(o.min_stiffness, 3) << " of the converged one in every static scene.\n";
  struct Class {
    std::string name;
    double absolute, relative;
    double min_stiffness;  // in every static scene; 0: no condition
    bool show_default;     // also describe the engine's default substeps x iterations
  };
  std::vector<std::string> static_scenes;
  for (const TradeoffScenario& sc : selected)
    if (sc.deflection) static_scenes.push_back(sc.name);
  const tire::SolverConfig engine_default;
  for (const tire::SolverMethod method : o.method_list) {
    out << "  " << method_text(method) << ":\n";
    std::vector<Class> classes{{"game", o.game_error, o.game_relative, 0.0, true},
                               {"accuracy", o.accurate_error, o.accurate_relative, 0.0, false}};
    if (!static_scenes.empty())
      classes.insert(classes.begin() + 1,
                     {"game, stiff", o.game_error, o.game_relative, o.min_stiffness, false});
    for (const Class& cls : classes) {
      out << "    " << cls.name << " (within " << length_text(cls.absolute) << " or "
          << fmt(100 * cls.relative, 3) << "% of the motion"
          << (cls.min_stiffness > 0.0 ? ", stiffness at least " + fmt(cls.min_stiffness, 3) : "") << "):\n";
      for (const int seg : o.segments) {
        std::map<std::string, double> bound;
        std::vector<std::string> deciding;
        for (const TradeoffScenario& scenario : selected) {
          const std::string& sc = scenario.name;
          const Row* ref = reference_row(rows, sc, seg);
          if (!ref) continue;
          bound[sc] = std::max({cls.absolute, cls.relative * ref->motion, 3.0 * ref->error});
          bool reachable = false;
          for (const Row& r : rows)
            if (r.kind == kSweep && r.scenario == sc && r.s.method == method && r.s.segments == seg &&
                r.s.tunnel_clamp == clamp && r.error <= bound[sc])
              reachable = true;
          if (reachable && scenario.decides) deciding.push_back(sc);
        }
        std::optional<std::pair<int, int>> best;
        double best_us = std::numeric_limits<double>::infinity();
        for (const int ss : substeps_of(o, method))
          for (const int it : iterations_of(o, method)) {
            double sum = 0.0;
            bool ok = true;
            for (const std::string& sc : scenarios) {
              const Row* r = find_row(rows, sc, method, ss, it, seg, clamp);
              if (!r) {
                ok = false;
                break;
              }
              sum += r->us_per_step;
              if (contains(deciding, sc) && !(r->error <= bound[sc])) ok = false;
              if (cls.min_stiffness > 0.0 && contains(static_scenes, sc) &&
                  !(r->stiffness_ratio >= cls.min_stiffness))
                ok = false;
            }
            const double mean = sum / static_cast<double>(scenarios.size());
            if (ok && !deciding.empty() && mean < best_us) best_us = mean, best = std::pair{ss, it};
          }
        // Cost (mean over the scenarios), each scenario's error and the static scenes' stiffness
        // ratios of one setting, with notes.
        auto describe = [&](int ss, int it) {
          double sum = 0.0;
          std::string errors, stiffness;
          for (const std::string& sc : scenarios) {
            const Row* r = find_row(rows, sc, method, ss, it, seg, clamp);
            if (!r) return std::string("not in the sweep");
            sum += r->us_per_step;
            std::string note;
            if (!contains(deciding, sc)) {
              const auto sc_it =
                  std::find_if(selected.begin(), selected.end(), [&](const auto& x) { return x.name == sc; });
              note = sc_it->decides ? " (no setting within " + length_text(bound[sc]) + ")"
                                    : " (" + fmt(100.0 * r->relative_error(), 2) + "% of the motion)";
            } else if (!(r->error <= bound[sc])) {
              note = " (over " + length_text(bound[sc]) + ")";
            }
            errors += " " + sc + " " + length_text(r->error) + note;
            if (std::isfinite(r->stiffness_ratio)) stiffness += " " + sc + " " + fmt(r->stiffness_ratio, 3);
          }
          return std::to_string(ss) + "x" + std::to_string(it) + ", " +
                 us_text(sum / static_cast<double>(scenarios.size())) + " per step;" + errors +
                 (stiffness.empty() ? "" : "; stiffness" + stiffness);
        };
        out << "      " << std::setw(2) << seg
            << " segments: " << (best ? describe(best->first, best->second) : "none in the sweep") << "\n";
        if (cls.show_default &&
            (!best || best->first != engine_default.substeps || best->second != engine_default.iterations))
          out << "        (the engine's default substeps x iterations: "
              << describe(engine_default.substeps, engine_default.iterations) << ")\n";
      }
    }
  }
}

// Claim 1 (Macklin et al. 2016): stiffness independent of iterations and time step.
void claim_stiffness(std::ostringstream& out, const std::vector<Row>& rows,
                     const std::vector<TradeoffScenario>& selected, const TradeoffOptions& o) {
  char line[512];
  const double clamp = o.tunnel_clamp.front();
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
      for (const tire::SolverMethod method : o.method_list) {
        std::snprintf(line, sizeof line, "    %-12s %10s", method_text(method), "substeps\\it");
        out << line;
        for (const int it : iterations_of(o, method))
          std::snprintf(line, sizeof line, " %7d", it), out << line;
        out << "\n";
        for (const int ss : substeps_of(o, method)) {
          std::snprintf(line, sizeof line, "    %-12s %10d", "", ss);
          out << line;
          for (const int it : iterations_of(o, method)) {
            const Row* r = find_row(rows, sc, method, ss, it, seg, clamp);
            std::snprintf(line, sizeof line, " %7s", r ? fmt(r->stiffness_ratio, 3).c_str() : "");
            out << line;
          }
          out << "\n";
        }
      }
    }
  }
}

// Claim 2 (Macklin et al. 2019): n substeps x 1 iteration beat 1 substep x n iterations, at equal
// sweeps and at equal measured cost.
void claim_substeps(std::ostringstream& out, const std::vector<Row>& rows,
                    const std::vector<std::string>& scenarios, const TradeoffOptions& o) {
  char line[512];
  const double clamp = o.tunnel_clamp.front();
  for (const tire::SolverMethod method : o.method_list) {
    const char* name = method_text(method);
    out << "\nClaim 2, " << name
        << ": n substeps x 1 iteration against 1 substep x n iterations (same n sweeps per step):\n";
    std::snprintf(line, sizeof line, "  %-9s %4s %4s %14s %10s %14s %10s %10s\n", "scenario", "segs", "n",
                  "error nx1", "us nx1", "error 1xn", "us 1xn", "1xn/nx1");
    out << line;
    int small_wins = 0, large_wins = 0;
    for (const std::string& sc : scenarios)
      for (const int seg : o.segments)
        for (const int n : substeps_of(o, method)) {
          if (n < 2) continue;
          const Row* a = find_row(rows, sc, method, n, 1, seg, clamp);
          const Row* b = find_row(rows, sc, method, 1, n, seg, clamp);
          if (!a || !b) continue;
          (a->error < b->error ? small_wins : large_wins)++;
          std::snprintf(line, sizeof line, "  %-9s %4d %4d %14s %10.3g %14s %10.3g %10.3g\n", sc.c_str(), seg,
                        n, length_text(a->error).c_str(), a->us_per_step, length_text(b->error).c_str(),
                        b->us_per_step, b->error / a->error);
          out << line;
        }
    if (small_wins + large_wins == 0)
      out << "  " << name
          << ": no pairs: the sweep has no n x 1 and 1 x n settings with the same n >= 2\n"
             "  (sweep 1 substep and more iterations too).\n";
    else
      out << "  " << name << ": n x 1 has the smaller error in " << small_wins << " of "
          << small_wins + large_wins << " pairs.\n";

    // The same at equal measured cost: a substep costs more than a sweep (prediction, contacts,
    // velocities), so n x 1 is set against the 1 x m curve at n x 1's cost, interpolated log–log
    // between the two 1 x m settings around it.
    out << "\nClaim 2 at equal measured cost, " << name
        << ": n x 1 against 1 substep x m iterations at the same µs per step\n"
           "(the 1 x m error interpolated log-log between the 1 x m settings that bracket the cost):\n";
    std::snprintf(line, sizeof line, "  %-9s %4s %6s %14s %10s %11s %16s %10s\n", "scenario", "segs", "nx1",
                  "error", "us", "1xm around", "1xm error there", "ratio");
    out << line;
    int wins = 0, losses = 0, undecided = 0;
    bool any_curve = false;  // two 1 x m settings or more somewhere, to interpolate between
    for (const std::string& sc : scenarios)
      for (const int seg : o.segments) {
        std::vector<const Row*> curve;  // 1 x m, by cost
        for (const Row& r : rows)
          if (r.kind == kSweep && r.scenario == sc && r.s.method == method && r.s.segments == seg &&
              r.s.substeps == 1 && r.s.tunnel_clamp == clamp)
            curve.push_back(&r);
        std::sort(curve.begin(), curve.end(),
                  [](const Row* x, const Row* y) { return x->us_per_step < y->us_per_step; });
        if (curve.size() >= 2) any_curve = true;
        for (const int n : substeps_of(o, method)) {
          if (n < 2) continue;
          const Row* a = find_row(rows, sc, method, n, 1, seg, clamp);
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
    if (!any_curve)
      out << "  " << name
          << ": no pairs: the sweep has fewer than two 1 x m settings (1 substep, m iterations) to "
             "interpolate between.\n";
    else
      out << "  " << name << ": n x 1 has the smaller error in " << wins << " of " << wins + losses
          << " pairs (" << undecided
          << " n x 1 settings fall outside the cost range of the 1 x m settings).\n";
  }
}

}  // namespace

std::string render_summary(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                           const TradeoffOptions& o, const BestSweep& best_sweep) {
  std::ostringstream out;
  std::vector<std::string> scenarios;
  for (const TradeoffScenario& sc : selected) scenarios.push_back(sc.name);

  out << "Scenarios (dt = 1/60 s, TireSpec{} but material damping " << fmt(o.material_damping, 3) << " s):\n";
  for (const TradeoffScenario& sc : selected) out << "  " << sc.name << ": " << sc.what << "\n";
  out << "Methods:";
  for (const tire::SolverMethod m : o.method_list) {
    out << " " << method_text(m) << " (substeps";
    for (const int ss : substeps_of(o, m)) out << " " << ss;
    out << "; iterations";
    for (const int it : iterations_of(o, m)) out << " " << it;
    out << ")";
  }
  out << "\n";
  references(out, rows, selected, o, best_sweep);
  fronts(out, rows, scenarios, o);
  recommendations(out, rows, selected, scenarios, o);
  claim_stiffness(out, rows, selected, o);
  claim_substeps(out, rows, scenarios, o);
  return out.str();
}

}  // namespace tirectl
