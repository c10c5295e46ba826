// tirectl tradeoff: what each solver setting costs and how far it strays from the converged answer.
//
// For every scenario and tire resolution (segments) it runs a converged reference (Gauss–Seidel at
// many substeps and several iterations), checks that reference against one with half the substeps
// (and, when the global method is swept, against the global method at the reference's substeps),
// then sweeps solver method × substeps × iterations (× tunnel clamp): each setting is run once to
// measure it (centroid trajectory, peak strain, area error, energy, static deflection) and `repeats`
// times with nothing but Simulation::step in the timed loop (each tick's median over the repeats,
// averaged over the ticks). Writes DIR/tradeoff.csv, DIR/tradeoff.svg (error against cost, log–log,
// one panel per scenario and resolution, one Pareto front per method) and DIR/summary.txt (reference
// checks, fronts, recommendations and the numbers for the two published claims, per method); the
// files are made in tradeoff_report.cpp and tradeoff_summary.cpp.
#include "tradeoff.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <thread>

#include "cli_numbers.h"
#include "commands.h"
#include "progress.h"
#include "tire/io/file_io.h"
#include "tire/tire/solver_config.h"
#include "tradeoff_report.h"
#include "tradeoff_scenarios.h"

namespace tirectl {

namespace {

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

// A progress bar on stderr while it runs (on a terminal, tire_tools::TerminalLine; otherwise a
// line per tenth done). The bar follows the expected work, the count follows the runs.
class Progress {
 public:
  Progress(std::size_t total, bool enabled, double total_weight)
      : total_(total), total_weight_(total_weight), enabled_(enabled), line_(enabled) {}
  void update(std::size_t done, double done_weight, const std::string& what) {
    if (!enabled_) return;
    const double f = total_weight_ > 0.0 ? std::clamp(done_weight / total_weight_, 0.0, 1.0) : 1.0;
    if (!line_.active()) {
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
    char text[128];
    std::snprintf(text, sizeof text, "[%s] %zu/%zu %-36.36s", bar.c_str(), done, total_, what.c_str());
    line_.show(text);
  }
  void note(const std::string& text) { line_.note("tradeoff: " + text); }
  void finish() { line_.clear(); }

 private:
  std::size_t total_;
  double total_weight_;
  bool enabled_;
  tire_tools::TerminalLine line_;
  int last_tenth_ = 0;
};

// --methods: each value one of the method names, as levels write them.
CLI::Validator method_names() {
  std::string names;
  for (const tire::SolverMethod m : tire::kSolverMethods)
    names += std::string(names.empty() ? "" : ", ") + tire::method_name(m);
  return CLI::Validator(
      [names](std::string& text) -> std::string {
        for (const tire::SolverMethod m : tire::kSolverMethods)
          if (text == tire::method_name(m)) return "";
        return "must be one of " + names + ", got \"" + text + "\"";
      },
      "one of " + names);
}

}  // namespace

const std::vector<int>& substeps_of(const TradeoffOptions& o, tire::SolverMethod m) {
  return m == tire::SolverMethod::global && !o.global_substeps.empty() ? o.global_substeps : o.substeps;
}

const std::vector<int>& iterations_of(const TradeoffOptions& o, tire::SolverMethod m) {
  return m == tire::SolverMethod::global && !o.global_iterations.empty() ? o.global_iterations : o.iterations;
}

CLI::App* add_tradeoff_command(CLI::App& app, TradeoffOptions& options) {
  using tire_tools::integer_in;
  using tire_tools::number_in;
  const tire::Range kPositive{0, tire_tools::kUnbounded, true, true};
  CLI::App* cmd = app.add_subcommand("tradeoff",
                                     "Measure error against cost over solver methods, substeps, iterations "
                                     "and segments; writes DIR/tradeoff.csv and .svg");
  cmd->add_option("--methods", options.methods, "Solver methods to sweep (default both): gauss-seidel,global")
      ->delimiter(',')
      ->check(method_names());
  cmd->add_option("--substeps", options.substeps, "Substeps to sweep, e.g. 1,2,4,8")
      ->delimiter(',')
      ->transform(integer_in({1, 256}));
  cmd->add_option("--iterations", options.iterations, "Iterations to sweep, e.g. 1,2,4")
      ->delimiter(',')
      ->transform(integer_in({1, 64}));
  cmd->add_option("--global-substeps", options.global_substeps,
                  "Substeps to sweep with the global method (default: --substeps)")
      ->delimiter(',')
      ->transform(integer_in({1, 256}));
  cmd->add_option("--global-iterations", options.global_iterations,
                  "Iterations to sweep with the global method (default: --iterations)")
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
                  "Substeps of the converged (Gauss-Seidel) reference (default: each scenario's own)")
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
  cmd->add_option(
         "--min-stiffness", options.min_stiffness,
         "Stiffness over the converged one that the \"game, stiff\" setting keeps in each static scene "
         "(default 0.95)")
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
  tidy(o.global_substeps);
  tidy(o.global_iterations);
  tidy(o.segments);
  // Methods in the engine's order, each once.
  o.method_list.clear();
  for (const tire::SolverMethod m : tire::kSolverMethods)
    if (std::find(o.methods.begin(), o.methods.end(), tire::method_name(m)) != o.methods.end())
      o.method_list.push_back(m);
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
      std::cerr << "tirectl tradeoff: unknown scenario \"" << tire::printable(name) << "\"; scenarios:";
      for (const TradeoffScenario& sc : tradeoff_scenarios()) std::cerr << " " << sc.name;
      std::cerr << "\n";
      return 2;
    }
  }
  if (o.substeps.empty() || o.iterations.empty() || o.segments.empty() || o.tunnel_clamp.empty() ||
      o.method_list.empty()) {
    std::cerr << "tirectl tradeoff: --methods, --substeps, --iterations, --segments and --tunnel-clamp need "
                 "at least "
                 "one value\n";
    return 2;
  }
  // The global method's own substeps and iterations apply only when it is swept.
  if ((!o.global_substeps.empty() || !o.global_iterations.empty()) &&
      std::find(o.method_list.begin(), o.method_list.end(), tire::SolverMethod::global) ==
          o.method_list.end()) {
    std::cerr << "tirectl tradeoff: --global-substeps and --global-iterations apply to the global method, "
                 "which --methods leaves out; add it to --methods or leave them out\n";
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
  // For claim 2: 1 substep x n iterations for every n of the method's substeps (and one more
  // doubling), so that n x 1 meets 1 x n at equal sweeps and 1 x m at equal measured cost.
  auto extra_iterations_of = [&](tire::SolverMethod method) {
    std::vector<int> extra;
    const std::vector<int>& substeps = substeps_of(o, method);
    const std::vector<int>& iterations = iterations_of(o, method);
    if (std::find(substeps.begin(), substeps.end(), 1) == substeps.end()) return extra;
    std::vector<int> wanted = substeps;
    wanted.push_back(std::min(2 * substeps.back(), 256));
    for (const int m : wanted)
      if (m > 1 && std::find(iterations.begin(), iterations.end(), m) == iterations.end() &&
          std::find(extra.begin(), extra.end(), m) == extra.end())
        extra.push_back(m);
    return extra;
  };
  // The plot's legend names those that are no method's regular iterations.
  for (const tire::SolverMethod method : o.method_list)
    for (const int m : extra_iterations_of(method)) {
      const bool regular = std::any_of(o.method_list.begin(), o.method_list.end(), [&](tire::SolverMethod x) {
        const std::vector<int>& its = iterations_of(o, x);
        return std::find(its.begin(), its.end(), m) != its.end();
      });
      if (!regular &&
          std::find(o.extra_iterations.begin(), o.extra_iterations.end(), m) == o.extra_iterations.end())
        o.extra_iterations.push_back(m);
    }
  std::sort(o.extra_iterations.begin(), o.extra_iterations.end());
  const bool global_swept = std::find(o.method_list.begin(), o.method_list.end(),
                                      tire::SolverMethod::global) != o.method_list.end();

  const std::filesystem::path dir = o.out;
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec) {
    std::cerr << "tirectl tradeoff: cannot create " << tire::printable(dir.string()) << ": " << ec.message()
              << "\n";
    return 2;
  }

  // Every run to measure: per scenario and segments a reference, its checks and each method's sweep.
  constexpr const char* kCheck = "check";
  struct Job {
    const TradeoffScenario* scenario;
    SolverSettings settings;
    std::string kind;  // kReference | kCheck | kCrossCheck | kSweep
    RunMeasure measure;
    double weight;  // expected cost, for the progress bar
  };
  std::vector<Job> jobs;
  for (const TradeoffScenario& sc : selected)
    for (const int seg : o.segments) {
      auto add = [&](tire::SolverMethod method, int ss, int it, double clamp, const char* kind) {
        SolverSettings s;
        s.substeps = ss;
        s.iterations = it;
        s.segments = seg;
        s.tunnel_clamp = clamp;
        s.method = method;
        s.material_damping = o.material_damping;
        // A global iteration costs about five Gauss–Seidel sweeps (docs/accuracy.md); for the progress bar.
        const double sweep = method == tire::SolverMethod::global ? 5.0 : 1.0;
        jobs.push_back(
            {&sc, s, kind, {}, static_cast<double>(sc.ticks) * ss * (sweep * it + 2.0) * (seg + 8.0)});
      };
      // The reference is Gauss–Seidel: converged, it is the physics, whatever the method.
      add(tire::SolverMethod::gauss_seidel, sc.ref_substeps, sc.ref_iterations, 1.0, kReference);
      // The check runs at half the reference's substeps: if the error falls as h^p, their distance
      // is (2^p - 1) times the reference's own error, so it never understates it.
      add(tire::SolverMethod::gauss_seidel, std::max(1, sc.ref_substeps / 2), sc.ref_iterations, 1.0, kCheck);
      // The global method at the reference's substeps: does it converge to the same answer?
      if (global_swept) add(tire::SolverMethod::global, sc.ref_substeps, 1, 1.0, kCrossCheck);
      for (const tire::SolverMethod method : o.method_list) {
        for (const double clamp : o.tunnel_clamp)
          for (const int ss : substeps_of(o, method))
            for (const int it : iterations_of(o, method))
              if (ss * it <= o.max_sweeps) add(method, ss, it, clamp, kSweep);
        for (const int m : extra_iterations_of(method)) add(method, 1, m, o.tunnel_clamp.front(), kSweep);
      }
    }
  const std::size_t sweep_count = static_cast<std::size_t>(
      std::count_if(jobs.begin(), jobs.end(), [](const Job& j) { return j.kind == kSweep; }));
  double total_weight = 0.0;
  for (const Job& j : jobs) total_weight += j.weight;
  // Timing: each sweep run `repeats` more times, serially.
  double sweep_weight = 0.0;
  for (const Job& j : jobs)
    if (j.kind == kSweep) sweep_weight += j.weight * o.repeats;
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
        progress.update(done, done_weight,
                        "measure " + job.scenario->name + " " + method_text(job.settings.method) + " " +
                            label(job.settings));
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
  BestSweep best_sweep;
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
    const Job* ref = find_job(name, seg, kReference);
    const Job* finest_ref = find_job(name, finest, kReference);
    if (job.kind == kCheck) continue;
    Row row{name, job.settings, job.kind};
    fill(row, *job.scenario, job.measure);
    row.motion = rms_distance(ref->measure.centroid, std::vector<tire::Vec2>(ref->measure.centroid.size(),
                                                                             ref->measure.centroid.front()));
    row.error_vs_finest = rms_distance(job.measure.centroid, finest_ref->measure.centroid);
    if (job.kind == kReference) {
      row.error = rms_distance(job.measure.centroid, find_job(name, seg, kCheck)->measure.centroid);
      row.us_per_step = job.measure.us_per_step;  // one run, timed while measuring
    } else if (job.kind == kCrossCheck) {
      row.error = rms_distance(job.measure.centroid, ref->measure.centroid);
      row.us_per_step = job.measure.us_per_step;
    } else {
      row.error = rms_distance(job.measure.centroid, ref->measure.centroid);
      progress.update(done, done_weight,
                      "time " + name + " " + method_text(job.settings.method) + " " + label(job.settings));
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
  // Stiffness relative to the converged one: the reference's deflection over the run's.
  for (Row& row : rows) {
    const Row* ref = reference_row(rows, row.scenario, row.s.segments);
    if (ref && std::isfinite(ref->stiffness)) row.stiffness_ratio = row.stiffness / ref->stiffness;
  }

  // Rows in reading order: scenario, segments ascending, reference and cross-check first, then
  // the sweep method by method.
  auto rank = [](const std::string& kind) { return kind == kReference ? 0 : kind == kCrossCheck ? 1 : 2; };
  std::stable_sort(rows.begin(), rows.end(), [&](const Row& a, const Row& b) {
    const auto ia = std::find(scenarios.begin(), scenarios.end(), a.scenario);
    const auto ib = std::find(scenarios.begin(), scenarios.end(), b.scenario);
    if (ia != ib) return ia < ib;
    if (a.s.segments != b.s.segments) return a.s.segments < b.s.segments;
    return rank(a.kind) < rank(b.kind);
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
      std::cerr << "tirectl tradeoff: " << tire::printable(path.string()) << ": " << error << "\n";
      return 2;
    }
  }
  std::cerr << summary;
  for (const auto& [path, text] : files) std::cout << "wrote " << tire::printable(path.string()) << "\n";
  return 0;
}

}  // namespace tirectl
