#!/usr/bin/env bash
# interrupt_runs.sh PROGRAM SCENE WORK [--set KEY=VALUE]...: a solve interrupted at any moment leaves its output folder
# whole (src/io/run_folder.hpp, docs/interface.md "Output files"). A first, complete run writes a
# short VTU series into WORK/out and times itself; then solves writing a long series into the same
# folder, in turn as solution.h5 + solution.xdmf and as a VTU series, get SIGINT or SIGTERM at
# fractions of that time, from the first iterations to the middle of the frames. After each: the
# exit status is 0 (it finished first) or 128 + the signal, and the folder is one complete run (its
# summary.json and marker; exactly the frames its solution.pvd lists, or a solution.h5 holding every
# frame its solution.xdmf lists), with no temporary and no lock left beside it. Exit 0 when every
# check held.
set -uo pipefail
program=$1 scene=$2 work=$3
shift 3
sets=("$@")  # the scene's size, for every run
out=$work/out
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# whole: the folder holds one complete run, and nothing is left beside it.
whole() {
  local context=$1
  [ -f "$out/summary.json" ] || fail "$context: no summary.json"
  [ -f "$out/.stcontact-run" ] || fail "$context: no marker"
  local listed on_disk
  if [ -f "$out/solution.pvd" ]; then
    listed=$(grep -o 'file="[^"]*"' "$out/solution.pvd" | sed 's/file="//; s/"//' | sort)
    on_disk=$(cd "$out" && ls vtu/*.vtu | sort)
  else
    listed=$(grep -o 'solution.h5:/frames/step_[0-9]*/displacement' "$out/solution.xdmf" | sed 's|.*/frames/||; s|/.*||' | sort)
    on_disk=$("${STC_PYTHON:-python3}" -c "import h5py, sys; print('\n'.join(sorted(k for k in h5py.File(sys.argv[1], 'r')['frames'] if k.startswith('step_'))))" "$out/solution.h5")
  fi
  [ -n "$listed" ] && [ "$listed" = "$on_disk" ] || fail "$context: the frames on disk ($(echo "$on_disk" | wc -l)) are not the ones listed ($(echo "$listed" | wc -l))"
  local left
  left=$(ls -A "$work" | grep -v '^out$')
  [ -z "$left" ] || fail "$context: left beside the folder: $left"
}

start=$(date +%s.%N)
"$program" solve "$scene" --out "$out" --quiet --no-reference "${sets[@]}" --set output.frame_stride=40 --set output.format='"vtu"' >/dev/null ||
  fail "the first run did not complete"
whole "first run"
duration=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { print b - a }')
long=(--set output.frame_stride=1)  # every instant: most of the run is the series

for signal in INT TERM; do
  format=hdf5
  for share in 0.05 0.2 0.4 0.6 0.8 1.0 1.3; do
    format=$([ "$format" = hdf5 ] && echo vtu || echo hdf5)  # in turn
    delay=$(awk -v d="$duration" -v s="$share" 'BEGIN { printf "%.3f", d * s * 2.5 }')
    "$program" solve "$scene" --out "$out" --quiet --no-reference "${sets[@]}" "${long[@]}" --set "output.format=\"$format\"" >/dev/null 2>"$work/stderr" &
    pid=$!
    sleep "$delay"
    kill -"$signal" "$pid" 2>/dev/null
    wait "$pid"
    status=$?
    expected=$([ "$signal" = INT ] && echo 130 || echo 143)
    if [ "$status" != 0 ] && [ "$status" != "$expected" ]; then
      fail "SIG$signal after ${delay}s: exit status $status ($(cat "$work/stderr"))"
    fi
    rm -f "$work/stderr"
    whole "SIG$signal after ${delay}s (exit $status)"
    echo "SIG$signal after ${delay}s ($format): exit $status, $(ls "$out" | tr '\n' ' ')"
  done
done
[ "$failures" = 0 ] && echo "every interrupted run left a whole folder" || echo "$failures failures"
exit $((failures > 0))
