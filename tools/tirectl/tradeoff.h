// tirectl tradeoff: its options, their command-line registration and the command (see
// tradeoff.cpp and docs/accuracy.md).
#pragma once

#include <string>
#include <vector>

#include "tire/tire/solver_config.h"

namespace CLI {
class App;
}

namespace tirectl {

struct TradeoffOptions {
  std::vector<int> substeps{1, 2, 4, 8, 16, 32, 64};
  std::vector<int> iterations{1, 2, 4, 8, 16};
  int max_sweeps = 512;  // skip settings with substeps × iterations above this
  std::vector<int> segments{12, 28, 64};
  std::vector<int> extra_iterations;  // filled in: 1 x n settings for claim 2 (not an option)
  // Solver methods to sweep, as method_name() writes them. Each gets the same sweep unless
  // global_substeps / global_iterations narrow the global method's (an iteration of it is a
  // Newton step of the whole tire: from 2 substeps on, a second one changes little; docs/accuracy.md).
  std::vector<std::string> methods{"gauss-seidel", "global"};
  std::vector<int> global_substeps;             // empty: --substeps
  std::vector<int> global_iterations;           // empty: --iterations
  std::vector<tire::SolverMethod> method_list;  // filled in from `methods` (not an option)
  std::vector<double> tunnel_clamp{1.0};
  std::vector<std::string> scenarios;  // empty: all
  int repeats = 3;                     // timed runs per setting; each tick's median is taken
  int ref_substeps = 0;                // the converged reference run; 0: each scenario's own
  int ref_iterations = 0;
  double material_damping = 1e-4;  // the tire's τ (s) in every run (TireSpec{} has 5e-3: docs/accuracy.md)
  // A recommended setting keeps each scenario's centroid error within max(absolute (m),
  // relative × how far the reference's tire moves).
  double game_error = 0.025;
  double game_relative = 0.1;
  double accurate_error = 0.0025;
  double accurate_relative = 0.01;
  // The "game, stiff" setting also keeps load / static deflection at least this fraction of the
  // converged stiffness in every static scene (issue 13 asks 0.95 of the recommended game setting).
  double min_stiffness = 0.95;
  std::string out = "tradeoff-out";
  bool progress = true;
};

// The substeps and iterations swept for one method (after tradeoff() has tidied the options).
const std::vector<int>& substeps_of(const TradeoffOptions& o, tire::SolverMethod m);
const std::vector<int>& iterations_of(const TradeoffOptions& o, tire::SolverMethod m);

// Adds the "tradeoff" subcommand and its options, parsed into `options`, to the app.
CLI::App* add_tradeoff_command(CLI::App& app, TradeoffOptions& options);

}  // namespace tirectl
