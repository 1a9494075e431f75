#!/usr/bin/env bash
# The test command (README "Tests", CI): builds in Release and runs the whole ctest suite, then
#   scripts/fuzz.sh      one clang build instrumented with AddressSanitizer + UndefinedBehaviorSanitizer
#                        (and libFuzzer's hooks): the core floor's test programs run under the
#                        sanitizers, then the scene and Gmsh fuzz targets, 300 000 inputs each from
#                        random seed 1 (repeatable), side by side
# and prints each stage's wall time. The whole suite under the sanitizers (scripts/sanitize.sh,
# GCC) is a third build and over half an hour on 2 cores: STC_FULL_SANITIZERS=1 adds it (before a
# release; README "Tests" says why CI leaves it out). STC_QUICK_TESTS=1 stops after the Release
# suite (for local edit-test loops).
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
  export STC_FUZZ_RUNS=${STC_FUZZ_RUNS:-300000} STC_FUZZ_CORE_TESTS=1
  stage "core floor under ASan+UBSan, then fuzzing (clang build + tests + bounded runs)" \
    "$root/scripts/fuzz.sh"
  if [ "${STC_FULL_SANITIZERS:-0}" = 1 ]; then
    stage "whole suite under ASan+UBSan (GCC build + tests)" "$root/scripts/sanitize.sh"
  fi
fi
echo "=== stage times"
printf '  %s\n' "${times[@]}"
