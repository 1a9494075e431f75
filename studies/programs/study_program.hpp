#pragma once
// What the study programs of this folder share (like MFEM's miniapps beside the library): the
// options every study takes (SCENE, --out, --set, --small, --repeats), parsed by CLI11 as the program
// parses its own, and one exit-status contract (docs/interface.md): 0 the study's check held, 1 bad
// input (one "error:" line), 2 the check failed, 3 internal failure; --help prints the options, exit 0.
// Statistics come from the studies library (stc::median, studies/work_precision.hpp).
#include <CLI/CLI.hpp>

#include <chrono>
#include <exception>
#include <filesystem>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "stcontact/core/clock.hpp"
#include "stcontact/core/input_error.hpp"
#include "stcontact/linalg/blas_kernels.hpp"
#include "stcontact/problem/problem.hpp"
#include "stcontact/scene/scene_reader.hpp"
#include "stcontact/solver/solve_summary.hpp"

namespace stc::study {

struct StudyOptions {
  std::filesystem::path scene;
  std::filesystem::path out;
  std::vector<std::string> overrides;  ///< --set KEY=VALUE, and --small's before them
  int repeats = 1;
  bool small = false;
};

/// The small settings of the ctest cases: the seed scene at 21 arc nodes and 21 instants.
inline const std::vector<std::string>& smallSettings() {
  static const std::vector<std::string> settings = {"mesh.arc_nodes=21", "time.steps=21"};
  return settings;
}

/// Declares SCENE, --out, --set, --small and --repeats on `app`, with the defaults in `o`.
inline void addStudyOptions(CLI::App& app, StudyOptions& o) {
  app.add_option("scene", o.scene, "scene file (TOML)")->capture_default_str();
  app.add_option("--out", o.out, "output folder")->capture_default_str();
  app.add_option("--set", o.overrides, "override a scene value: section.key=value")->take_all();
  app.add_flag("--small", o.small, "the small settings of the ctest case (mesh.arc_nodes=21, time.steps=21)");
  app.add_option("--repeats", o.repeats, "timed runs, medians over them")->capture_default_str()->check(
      CLI::PositiveNumber);
}

/// The study's scene (its --set overrides applied) at mesh.divisions `divisions`: one size of a
/// study's --sizes.
inline Problem problemAtDivisions(const StudyOptions& o, int divisions) {
  std::vector<std::string> sets = o.overrides;
  sets.push_back("mesh.divisions=" + std::to_string(divisions));
  return buildProblem(readScene(o.scene, sets));
}

/// Parses the command line, then runs `study` (which returns 0 or 2) under the exit-status contract.
inline int runStudy(CLI::App& app, StudyOptions& o, int argc, char** argv, const std::function<int()>& study) {
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int status = app.exit(e);  // prints --help (status 0) or the parse error
    return status == 0 ? 0 : 1;
  }
  if (o.small) o.overrides.insert(o.overrides.begin(), smallSettings().begin(), smallSettings().end());
  linalg::preferFastBlasKernels();  // as the command line (src/linalg/blas_kernels.hpp)
  try {
    return study();
  } catch (const InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return 1;
  } catch (const std::exception& e) {
    std::cerr << "error: internal failure: " << e.what() << '\n';
    return 3;
  }
}

/// The first record of `summary` whose true error is at or below `target` (null: none).
inline const IterationRecord* firstRecordBelow(const SolveSummary& summary, double target) {
  for (const IterationRecord& h : summary.history)
    if (h.error && *h.error <= target) return &h;
  return nullptr;
}

/// The wall time of `work`, in seconds.
template <class Work>
double secondsOf(Work&& work) {
  const auto start = std::chrono::steady_clock::now();
  work();
  return secondsSince(start);
}

}  // namespace stc::study
