#!/usr/bin/env bash
# Configures and builds in Release into build/ (or $STC_BUILD_DIR), with the tests and the Python
# module (its pytest suite runs in ctest; scripts/install_deps.sh installs what it needs).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_BUILD_DIR:-$root/build}
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release -DSTC_BUILD_TESTS=ON -DSTC_BUILD_PYTHON=ON >/dev/null
cmake --build "$build" -j "$(nproc)"
