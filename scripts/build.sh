#!/usr/bin/env bash
# Configures in Release into build/ (or $STC_BUILD_DIR), with the tests and the Python module (its
# pytest suite runs in ctest; scripts/install_deps.sh installs what it needs), and builds the
# targets named (default: every target). The main job builds the program alone
# (scripts/main_job.sh: `scripts/build.sh stcontact_cli`); the test command builds the rest.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSTC_BUILD_TESTS=ON -DSTC_BUILD_PYTHON=ON >/dev/null
if [ $# -eq 0 ]; then
  cmake --build "$build" -j "$(nproc)"
else
  for target in "$@"; do cmake --build "$build" -j "$(nproc)" --target "$target"; done
fi
