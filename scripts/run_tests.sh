#!/usr/bin/env bash
# The test command (README "Set-up", CI): builds in Release and runs the whole ctest suite, then
#   scripts/sanitize.sh  the same suite built with AddressSanitizer + UndefinedBehaviorSanitizer
#   scripts/fuzz.sh      the scene and Gmsh fuzz targets, 300 000 inputs each from random seed 1
#                        (repeatable; about a minute each, side by side)
# and prints each stage's wall time. STC_QUICK_TESTS=1 stops after the Release suite (for local
# edit-test loops; CI always runs every stage).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_BUILD_DIR:-$root/build}
times=()
stage() {  # stage NAME COMMAND...: runs COMMAND, records its wall time
  local start=$SECONDS
  echo "=== $1"
  "${@:2}"
  times+=("$1: $((SECONDS - start)) s")
}
release() {
  "$root/scripts/build.sh"
  (cd "$build" && ctest --output-on-failure -j "$(nproc)" --timeout 900)
}
stage "release build + tests" release
if [ "${STC_QUICK_TESTS:-0}" = 1 ]; then
  echo "STC_QUICK_TESTS=1: sanitizer and fuzz stages skipped"
else
  stage "sanitizers (ASan+UBSan build + tests)" "$root/scripts/sanitize.sh"
  export STC_FUZZ_RUNS=${STC_FUZZ_RUNS:-300000}
  stage "fuzzing (build + bounded runs)" "$root/scripts/fuzz.sh"
fi
echo "=== stage times"
printf '  %s\n' "${times[@]}"
