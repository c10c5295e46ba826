// The CSV and the SVG plot of `tirectl tradeoff`, and the helpers its files share.
#include "tradeoff_report.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <sstream>

#include "svg_plot.h"

namespace tirectl {

std::string fmt(double v, int digits) {
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

const char* method_text(tire::SolverMethod m) { return tire::method_name(m); }

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

const Row* find_row(const std::vector<Row>& rows, const std::string& scenario, tire::SolverMethod method,
                    int substeps, int iterations, int segments, double clamp) {
  for (const Row& r : rows)
    if (r.scenario == scenario && r.s.method == method && r.s.substeps == substeps &&
        r.s.iterations == iterations && r.s.segments == segments && r.s.tunnel_clamp == clamp &&
        r.kind == kSweep)
      return &r;
  return nullptr;
}

const Row* reference_row(const std::vector<Row>& rows, const std::string& scenario, int segments,
                         const char* kind) {
  for (const Row& r : rows)
    if (r.scenario == scenario && r.s.segments == segments && r.kind == kind) return &r;
  return nullptr;
}

std::string render_csv(const std::vector<Row>& rows) {
  std::ostringstream out;
  out << "scenario,substeps,iterations,segments,us_per_step,error,relative_error,error_vs_finest,peak_strain,"
         "area_error,"
         "energy_drift,deflection,stiffness,stiffness_ratio,tunnel_clamp,material_damping,sweeps,resets,"
         "method,kind\n";
  for (const Row& r : rows)
    out << r.scenario << "," << r.s.substeps << "," << r.s.iterations << "," << r.s.segments << ","
        << fmt(r.us_per_step) << "," << fmt(r.error) << "," << fmt(r.relative_error()) << ","
        << fmt(r.error_vs_finest) << "," << fmt(r.peak_strain) << "," << fmt(r.area_error) << ","
        << fmt(r.energy_drift) << "," << fmt(r.deflection) << "," << fmt(r.stiffness, 5) << ","
        << fmt(r.stiffness_ratio) << "," << fmt(r.s.tunnel_clamp) << "," << fmt(r.s.material_damping) << ","
        << r.sweeps() << "," << r.resets << "," << method_text(r.s.method) << "," << r.kind << "\n";
  return out.str();
}

namespace {

const char* kSubstepColors[] = {"#d62728", "#ff7f0e", "#bcbd22", "#2ca02c", "#17becf",
                                "#1f77b4", "#9467bd", "#8c564b", "#e377c2", "#7f7f7f"};

int index_of(const std::vector<int>& values, int v) {
  const auto it = std::find(values.begin(), values.end(), v);
  return static_cast<int>(it - values.begin());
}

// The union of two sorted lists, sorted.
std::vector<int> merged(const std::vector<int>& a, const std::vector<int>& b) {
  std::vector<int> m;
  std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(m));
  return m;
}

// How each method is painted: Gauss–Seidel filled with a solid black front, global hollow with a
// dashed magenta one.
PlotSeries series_for(tire::SolverMethod m) {
  PlotSeries s;
  s.label = method_text(m);
  if (m == tire::SolverMethod::global) {
    s.hollow = true;
    s.front_color = "#c2006b";
    s.front_dash = "7,3";
  }
  return s;
}

}  // namespace

std::string render_plot(const std::vector<Row>& rows, const std::vector<TradeoffScenario>& selected,
                        const TradeoffOptions& o) {
  std::vector<int> substeps, iterations;
  for (const tire::SolverMethod m : o.method_list) {
    substeps = merged(substeps, substeps_of(o, m));
    iterations = merged(iterations, iterations_of(o, m));
  }
  PlotSpec spec;
  spec.title = "tirectl tradeoff: centroid trajectory error against cost";
  spec.subtitle =
      "error = RMS distance of the tire's centroid from a converged reference run of the same scene and "
      "tire\n(Gauss-Seidel, its substeps x iterations in each title; the global method converges to it too)\n"
      "cost = µs of Simulation::step per 1/60 s tick (each tick's median over the repeats); tire material "
      "damping " +
      fmt(o.material_damping, 3) + " s; one row per scene, one column per tire resolution";
  spec.x_label = "cost (µs per step)";
  spec.y_label = "centroid error";
  spec.columns = static_cast<int>(o.segments.size());
  spec.color_title = "substeps";
  for (std::size_t i = 0; i < substeps.size(); ++i) {
    spec.colors.push_back(kSubstepColors[i % std::size(kSubstepColors)]);
    spec.color_labels.push_back(std::to_string(substeps[i]));
  }
  spec.marker_title = "iterations";
  for (const int it : iterations) spec.marker_labels.push_back(std::to_string(it));
  if (!o.extra_iterations.empty()) {
    std::string more;
    for (const int m : o.extra_iterations) more += (more.empty() ? "" : ",") + std::to_string(m);
    spec.marker_labels.push_back(more + " (1 substep only)");
  }
  spec.series.clear();
  for (const tire::SolverMethod m : o.method_list) spec.series.push_back(series_for(m));
  spec.series_title = "method";
  if (o.tunnel_clamp.size() > 1) spec.faded_label = "tunnel clamp != " + fmt(o.tunnel_clamp.front(), 3);
  spec.x_tick = microseconds_label;
  spec.y_tick = metres_label;
  for (const TradeoffScenario& sc : selected) {
    const std::string& scenario = sc.name;
    for (const int seg : o.segments) {
      PlotPanel panel;
      panel.title = scenario + ", " + std::to_string(seg) + " segments (ref. " +
                    std::to_string(sc.ref_substeps) + "x" + std::to_string(sc.ref_iterations) + ")";
      std::vector<std::vector<const Row*>> sweep(o.method_list.size());
      for (const Row& r : rows) {
        if (r.scenario != scenario || r.s.segments != seg) continue;
        if (r.kind == kReference) {
          panel.floor = r.error;
          continue;
        }
        if (r.kind != kSweep) continue;
        const int series = static_cast<int>(
            std::find(o.method_list.begin(), o.method_list.end(), r.s.method) - o.method_list.begin());
        if (series >= static_cast<int>(sweep.size())) continue;
        sweep[static_cast<std::size_t>(series)].push_back(&r);
        PlotPoint p;
        p.x = r.us_per_step;
        p.y = r.error;
        p.color = index_of(substeps, r.s.substeps);
        p.marker = std::min(index_of(iterations, r.s.iterations), static_cast<int>(iterations.size()));
        p.series = series;
        p.faded = r.s.tunnel_clamp != o.tunnel_clamp.front();
        p.tooltip = scenario + " " + method_text(r.s.method) + " " + label(r.s) + ": " +
                    us_text(r.us_per_step) + " per step, error " + length_text(r.error);
        panel.points.push_back(p);
      }
      for (std::size_t m = 0; m < sweep.size(); ++m) {
        PlotFront front;
        front.series = static_cast<int>(m);
        for (const Row* r : pareto_front(sweep[m])) front.points.emplace_back(r->us_per_step, r->error);
        panel.fronts.push_back(std::move(front));
      }
      spec.panels.push_back(std::move(panel));
    }
  }
  return render_svg(spec);
}

}  // namespace tirectl
