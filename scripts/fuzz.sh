#!/usr/bin/env bash
# Description: builds the libFuzzer targets of tests/fuzz (clang++-14, with AddressSanitizer and
#   UndefinedBehaviorSanitizer, in build-fuzz/) and runs each for a bounded time, side by side,
#   from the seed corpus: the shipped scenes and meshes, tests/cli/bad/*, tests/fuzz/seeds/*.
#     scene  TOML text (+ "#set" overrides) -> Scene, with every check (tests/fuzz/fuzz_scene.cpp)
#     gmsh   MSH 4.1 text -> Mesh (tests/fuzz/fuzz_gmsh.cpp)
#   A finding (crash, exception other than InputError, sanitizer report, leak, timeout, memory
#   blow-up) fails the run; the log then shows the fuzzer's report and the input that caused it
#   (base64 and as text), which also stays in build-fuzz/artifacts/<target>/.
# Sample run:
#   bash scripts/fuzz.sh                          # both targets, 60 s each (build ~3 min)
#   STC_FUZZ_SECONDS=600 bash scripts/fuzz.sh gmsh  # one target, 10 minutes
#   build-fuzz/bin/fuzz_gmsh build-fuzz/artifacts/gmsh/crash-*   # replays a finding
# Options: the targets to run as arguments (default: scene gmsh); environment:
#   STC_FUZZ_SECONDS  time per target (default 60)
#   STC_FUZZ_RUNS     instead of a time: this many inputs per target, from random seed
#                     STC_FUZZ_SEED (default 1), so that a run is repeatable (the test command uses
#                     it: CI fails on a finding of the code, never on the luck of one run); the
#                     corpus then starts from the seeds alone
#   STC_FUZZ_DIR      build folder (default: build-fuzz/ in the repository); its corpus/ keeps
#                     what earlier local runs found, so they start from there
#   STC_FUZZ_CXX      compiler (default clang++-14)
#   STC_FUZZ_CORE_TESTS=1  first builds the core floor's test programs (those that link
#                     stcontact::core alone, tests/CMakeLists.txt) in the same instrumented build
#                     and runs them under its sanitizers: a failure or sanitizer report fails the
#                     run before any fuzzing. The test command uses it (README, "Tests"): one build
#                     checks the library the fuzz targets drive both ways.
#   STC_JOBS          parallel compile jobs (default: nproc)
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_FUZZ_DIR:-$root/build-fuzz}
seconds=${STC_FUZZ_SECONDS:-60}
runs=${STC_FUZZ_RUNS:-}
if [ -n "$runs" ]; then
  bound=(-runs="$runs" -seed="${STC_FUZZ_SEED:-1}") budget="$runs inputs (seed ${STC_FUZZ_SEED:-1})"
else
  bound=(-max_total_time="$seconds") budget="$seconds s"
fi
cxx=${STC_FUZZ_CXX:-clang++-14}
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene gmsh)
for target in "${targets[@]}"; do
  [ -f "$root/tests/fuzz/fuzz_$target.cpp" ] || { echo "fuzz.sh: no target '$target' (scene, gmsh)"; exit 1; }
done
command -v "$cxx" >/dev/null || { echo "fuzz.sh: $cxx not found (apt-get install clang-14 libclang-rt-14-dev)"; exit 1; }

core_tests=${STC_FUZZ_CORE_TESTS:-0}
# Eigen's own dense kernels (-DSTC_EIGEN_USE_BLAS=OFF), as in scripts/sanitize.sh, which says why;
# without PETSc (-DSTC_WITH_PETSC=OFF): this build checks the embedded default (CHOLMOD) and what a
# build without PETSc says, and keeps Open MPI's start-up allocations, which it never frees, out of
# LeakSanitizer's reports.
cmake -S "$root" -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_BUILD_TYPE=Debug \
  -DCMAKE_CXX_FLAGS_DEBUG="-O1 -g" -DCMAKE_CXX_FLAGS="-D_GLIBCXX_ASSERTIONS" \
  -DSTC_BUILD_FUZZERS=ON -DSTC_BUILD_TESTS="$([ "$core_tests" = 1 ] && echo ON || echo OFF)" \
  -DSTC_BUILD_PYTHON=OFF -DSTC_EIGEN_USE_BLAS=OFF -DSTC_WITH_PETSC=OFF >/dev/null
extra_targets=()
[ "$core_tests" = 1 ] && extra_targets=(core_floor_tests)
cmake --build "$build" -j "${STC_JOBS:-$(nproc)}" --target "${targets[@]/#/fuzz_}" "${extra_targets[@]}"

# The core floor's test programs (tests/CMakeLists.txt lists their folders, which are their ctest
# labels, in core_floor_tests.txt) under the sanitizers of this build.
if [ "$core_tests" = 1 ]; then
  read -r -a folders <"$build/core_floor_tests.txt"
  echo "core floor's tests under ASan + UBSan: ${folders[*]}"
  labels=$(IFS='|'; echo "${folders[*]}")
  (source "$root/scripts/sanitizer_env.sh" && cd "$build" &&
     ctest --output-on-failure -j "${STC_JOBS:-$(nproc)}" --timeout 1800 -L "^($labels)\$")
fi

# seeds TARGET: the shipped inputs of the target's kind, copied afresh into one folder, each named
# after its folder too (examples/scenes/fretting.toml and examples/scenes/hard/fretting.toml are two).
seeds() {
  local dir=$build/seeds/$1 file
  rm -rf "$dir" && mkdir -p "$dir"
  local -a inputs
  case $1 in
    scene) inputs=("$root"/examples/scenes/*.toml "$root"/examples/scenes/hard/*.toml
                   "$root"/tests/cli/bad/*.toml "$root"/tests/fuzz/seeds/scene/*) ;;
    gmsh) inputs=("$root"/examples/meshes/*.msh "$root"/tests/cli/bad/*.msh "$root"/tests/fuzz/seeds/gmsh/*) ;;
  esac
  for file in "${inputs[@]}"; do
    cp "$file" "$dir/$(basename "$(dirname "$file")")_$(basename "$file")"
  done
  echo "$dir"
}

# run TARGET: fuzzes for $seconds into build-fuzz/corpus/TARGET; its output goes to TARGET.log.
# -max_len 8192: long enough for every section of a small mesh, short enough to keep inputs fast
# (punch.msh is read truncated); -timeout 25 s for one input, far above any sane parse.
run() {
  local corpus=$build/corpus/$1 artifacts=$build/artifacts/$1
  rm -rf "$artifacts" && mkdir -p "$corpus" "$artifacts"
  [ -z "$runs" ] || { rm -rf "$corpus" && mkdir -p "$corpus"; }  # repeatable: from the seeds alone
  "$build/bin/fuzz_$1" "${bound[@]}" -max_len=8192 -timeout=25 -rss_limit_mb=2048 \
    -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" "$(seeds "$1")" \
    >"$build/$1.log" 2>&1
}

# report TARGET STATUS: the end of the log; on failure the whole report and the inputs.
report() {
  local log=$build/$1.log
  if [ "$2" -eq 0 ]; then
    echo "fuzz $1: no finding in $budget, from $(find "$build/seeds/$1" -type f | wc -l) seeds"
    grep -E '^(Done|stat::(average_exec_per_sec|new_units_added|slowest_unit_time_sec|peak_rss_mb))' \
      "$log" || tail -n 3 "$log"
    return
  fi
  echo "fuzz $1: FINDING (libFuzzer exit status $2); its report:"
  grep -vE '^#[0-9]+' "$log" | tail -n 80
  for input in "$build/artifacts/$1"/*; do
    [ -f "$input" ] || continue
    echo "--- input $input ($(wc -c <"$input") bytes), base64 (base64 -d > input to replay):"
    base64 "$input"
    echo "--- the same as text (first 40 lines, cat -v):"
    head -n 40 "$input" | cat -v
  done
}

# file:line in the stack traces of a report (llvm-14's symbolizer; else addr2line).
sym=/usr/lib/llvm-14/bin/llvm-symbolizer
if [ -x "$sym" ]; then export ASAN_OPTIONS="external_symbolizer_path=$sym${ASAN_OPTIONS:+:$ASAN_OPTIONS}"; fi
declare -A pids
for target in "${targets[@]}"; do
  run "$target" & pids[$target]=$!
done
failed=0
for target in "${targets[@]}"; do
  status=0
  wait "${pids[$target]}" || status=$?
  report "$target" "$status"
  [ "$status" -eq 0 ] || failed=1
done
exit "$failed"
