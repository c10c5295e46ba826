// What `tirectl tradeoff` measured, one row per run, and the three files made from the rows: the
// CSV, the SVG plot (tradeoff_report.cpp) and the summary with the recommended settings and the two
// published claims (tradeoff_summary.cpp).
#pragma once

#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tradeoff.h"
#include "tradeoff_scenarios.h"

namespace tirectl {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Row kinds: a setting of the sweep; the converged reference (Gauss–Seidel at the scenario's
// reference substeps x iterations); the global method at the reference's substeps, set against it.
inline constexpr const char* kSweep = "sweep";
inline constexpr const char* kReference = "reference";
inline constexpr const char* kCrossCheck = "cross-check";

struct Row {
  std::string scenario;
  SolverSettings s;
  std::string kind;  // kSweep | kReference | kCrossCheck
  double us_per_step = kNaN;
  double error = kNaN;            // RMS centroid distance to the reference of the same segments (m)
  double error_vs_finest = kNaN;  // ... to the reference of the finest tire in the run (m)
  double motion = kNaN;           // how far the reference's tire moves: RMS distance from its start (m)
  double relative_error() const { return error / motion; }
  double peak_strain = kNaN;
  double area_error = kNaN;
  double energy_drift = kNaN;
  double deflection = kNaN;
  double stiffness = kNaN;        // load / deflection (N/m), static scenes
  double stiffness_ratio = kNaN;  // stiffness / the reference's: 1 = the converged stiffness
  int resets = 0;
  int sweeps() const { return s.substeps * s.iterations; }
};

// The sweep's smallest error per (scenario, segments), over every method.
using BestSweep = std::map<std::pair<std::string, int>, double>;

// Formatting shared by the files.
std::string fmt(double v, int digits = 4);
std::string length_text(double m);  // in the most readable unit
std::string us_text(double us);
// "8x1x28" (substeps x iterations x segments), with the clamp when it is not 1.
std::string label(const SolverSettings& s);
const char* method_text(tire::SolverMethod m);

// The points no other point beats on both cost and error, cheapest first.
std::vector<const Row*> pareto_front(std::vector<const Row*> rows);

const Row* find_row(const std::vector<Row>& rows, const std::string& scenario, tire::SolverMethod method,
                    int substeps, int iterations, int segments, double clamp);
const Row* reference_row(const std::vector<Row>& rows, const std::string& scenario, int segments,
                         const char* kind = kReference);

std::string render_csv(const std::vector<Row>& rows);
std::string render_plot(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                        const TradeoffOptions& o);
std::string render_summary(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                           const TradeoffOptions& o, const BestSweep& best_sweep);

}  // namespace tirectl
