#pragma once
// --threads N on the sub-commands that solve (docs/threads.md): stc::setThreadCount before the run.
// Unset: STC_THREADS, else the built-in default (src/core/threads.hpp).
#include <CLI/CLI.hpp>

#include "stcontact/core/input_error.hpp"
#include "stcontact/core/threads.hpp"

namespace stc::cli {

inline CLI::Option* addThreadsOption(CLI::App& command) {
  return command
      .add_option_function<int>(
          "--threads",
          [](int n) {
            try {
              stc::setThreadCount(n);
            } catch (const InputError& e) {
              throw InputError(std::string("--threads: ") + e.what());
            }
          },
          "threads for the local stage (over nodes) and the global stage (over blocks of instants); results are "
          "identical for every count (default: STC_THREADS, else " +
              std::to_string(stc::kDefaultThreads) + ")")
      ->type_name("N");  // 1 to stc::maxThreadCount(): setThreadCount's InputError otherwise
}

}  // namespace stc::cli
