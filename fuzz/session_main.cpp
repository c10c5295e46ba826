// The fuzz_session target as a plain program, as libFuzzer's StandaloneFuzzTargetMain runs a target
// without libFuzzer: the test suite's bounded fuzz run, built by any compiler (tests/CMakeLists.txt).
//   tire_fuzz_session [--mutations N] [--seed S] [--dict FILE]... [--max-rss-mb MB]
//                     [--input-file FILE] [--expect-budgets] PATH...
// Every file of the PATHs (a directory: its regular files, in name order) runs once through
// LLVMFuzzerTestOneInput, then N inputs the mutator (mutator.h) makes from them. What runs depends
// on the files, the seed and N only. Each input is written to the --input-file before it runs: when
// an invariant aborts the run, that file is the input (make it a regression, tests/fuzz-regressions/).
// Exit 1 when the peak resident set passes --max-rss-mb, or with --expect-budgets when some run
// budget was never reached (the inputs would not be testing what they should).
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "fuzz_session.h"
#include "mutator.h"
#include "tire/io/file_io.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace {

int usage() {
  std::fprintf(stderr,
               "usage: tire_fuzz_session [--mutations N] [--seed S] [--dict FILE]... [--max-rss-mb MB]\n"
               "                         [--input-file FILE] [--expect-budgets] PATH...\n");
  return 2;
}

bool read_input(const std::filesystem::path& file, std::vector<std::string>& corpus) {
  std::string error;
  const auto text = tire::read_file(file, tire::LevelLimits::max_file_bytes, error);
  if (!text) {
    std::fprintf(stderr, "tire_fuzz_session: %s\n", error.c_str());
    return false;
  }
  corpus.push_back(*text);
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  using tire::fuzz::session_stats;
  long mutations = 0, max_rss_mb = 0;
  std::uint64_t seed = 1;
  bool expect_budgets = false;
  std::string input_file;
  std::vector<std::string> dictionary, corpus;
  std::vector<std::filesystem::path> files;
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    const bool has_value = i + 1 < argc;
    if (arg == "--mutations" && has_value) {
      mutations = std::atol(argv[++i]);
    } else if (arg == "--seed" && has_value) {
      seed = std::strtoull(argv[++i], nullptr, 10);
    } else if (arg == "--max-rss-mb" && has_value) {
      max_rss_mb = std::atol(argv[++i]);
    } else if (arg == "--input-file" && has_value) {
      input_file = argv[++i];
    } else if (arg == "--dict" && has_value) {
      std::string error;
      const auto words = tire::fuzz::read_dictionary(argv[++i], error);
      if (!words) {
        std::fprintf(stderr, "tire_fuzz_session: %s\n", error.c_str());
        return 2;
      }
      dictionary.insert(dictionary.end(), words->begin(), words->end());
    } else if (arg == "--expect-budgets") {
      expect_budgets = true;
    } else if (arg.starts_with("--")) {
      return usage();
    } else if (std::filesystem::is_directory(arg)) {
      std::vector<std::filesystem::path> in_dir;
      for (const auto& entry : std::filesystem::directory_iterator(arg))
        if (entry.is_regular_file()) in_dir.push_back(entry.path());
      std::sort(in_dir.begin(), in_dir.end());
      files.insert(files.end(), in_dir.begin(), in_dir.end());
    } else {
      files.emplace_back(arg);
    }
  }
  if (files.empty() || mutations < 0) return usage();
  for (const auto& file : files)
    if (!read_input(file, corpus)) return 2;
  tire::fuzz::session_budget().max_rss_mb = max_rss_mb;
  if (!input_file.empty())
    std::fprintf(stderr, "tire_fuzz_session: each input is written to %s before it runs\n",
                 input_file.c_str());

  const auto started = std::chrono::steady_clock::now();  // for the report only
  long peak = 0;
  const auto run = [&](const std::string& input, const std::string& what) {
    if (!input_file.empty()) {
      std::string error;
      if (!tire::write_file_atomically(input_file, input, error)) {
        std::fprintf(stderr, "tire_fuzz_session: %s\n", error.c_str());
        std::exit(2);
      }
    }
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(input.data()), input.size());
    tire::fuzz::check_memory(max_rss_mb, what);
    peak = tire::fuzz::peak_rss_mb();
  };
  for (std::size_t i = 0; i < corpus.size(); ++i) run(corpus[i], files[i].string());
  tire::fuzz::Mutator mutator(seed, dictionary);
  for (long m = 0; m < mutations; ++m) run(mutator.mutate(corpus), "mutation " + std::to_string(m));
  if (!input_file.empty()) std::filesystem::remove(input_file);

  const tire::fuzz::SessionStats& s = session_stats();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  std::printf(
      "tire_fuzz_session: %zu files and %ld mutations (seed %llu): %llu levels, %llu skipped as too costly, "
      "%llu played for %llu ticks in all (%llu restarts, %llu tires and props spawned, %llu ticks with a "
      "message on screen, %llu won, %llu lost); peak RSS %ld MB; %.1f s\n",
      corpus.size(), mutations, static_cast<unsigned long long>(seed),
      static_cast<unsigned long long>(s.levels), static_cast<unsigned long long>(s.skipped),
      static_cast<unsigned long long>(s.runs), static_cast<unsigned long long>(s.ticks),
      static_cast<unsigned long long>(s.restarts), static_cast<unsigned long long>(s.spawned),
      static_cast<unsigned long long>(s.messages), static_cast<unsigned long long>(s.won),
      static_cast<unsigned long long>(s.lost), peak, seconds);
  bool missing = false;
  for (std::size_t i = 0; i < s.budget_reached.size(); ++i) {
    std::printf("  %s reached in %llu runs\n", tire::fuzz::session_detail::budget_key(i),
                static_cast<unsigned long long>(s.budget_reached[i]));
    missing = missing || s.budget_reached[i] == 0;
  }
  if (expect_budgets && missing) {
    std::fprintf(stderr, "tire_fuzz_session: some budget was never reached: the inputs do not test it\n");
    return 1;
  }
  return 0;
}
