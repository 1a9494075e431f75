#!/usr/bin/env bash
# What a user gets from `stcontact solve SCENE --tol TOL`: each solver's wall time (summary.json's
# wall_s, the solve without set-up; median of REPEATS runs, the solvers alternated in each round),
# stopping on its own error estimate without the reference, then one more run with the reference
# for the true error at termination. Prints a Markdown table.
#
#   scripts/solve_at_tolerance.sh SCENE TOL REPEATS SOLVER... [-- --set KEY=VALUE ...]
#   scripts/solve_at_tolerance.sh examples/scenes/hemicylinder.toml 1e-6 5 \
#       incremental latin latin-pgd fas-aposteriori fas-apriori
#
# STC_BIN names the program (default build/bin/stcontact).
set -euo pipefail
if [[ $# -lt 4 ]]; then
  sed -n 2,10p "$0" >&2
  exit 1
fi
scene=$1 tol=$2 repeats=$3
shift 3
solvers=()
while [[ $# -gt 0 && $1 != -- ]]; do solvers+=("$1"); shift; done
[[ ${1:-} == -- ]] && shift
sets=("$@")
bin=${STC_BIN:-build/bin/stcontact}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

field() { /usr/bin/python3 -c "import json,sys; v=json.load(open(sys.argv[1]))[sys.argv[2]]; print('' if v is None else v)" "$1" "$2"; }

run() {  # run SOLVER OUT [extra arguments]: exit 0 or 2 are results, anything else stops the study
  local solver=$1 out=$2
  shift 2
  local rc=0
  "$bin" solve "$scene" --solver "$solver" --tol "$tol" --out "$out" --quiet \
    --set output.frames=false "${sets[@]}" "$@" || rc=$?
  if [[ $rc -ne 0 && $rc -ne 2 ]]; then
    echo "error: $solver exited with $rc" >&2
    exit 1
  fi
}

for ((r = 1; r <= repeats; r++)); do
  for s in "${solvers[@]}"; do
    run "$s" "$work/$s-$r" --no-reference
    field "$work/$s-$r/summary.json" wall_s >>"$work/$s.times"
  done
done

echo "| solver | termination | relaxations | error estimate | true error | wall s (median of $repeats) |"
echo "|---|---|---:|---:|---:|---:|"
for s in "${solvers[@]}"; do
  run "$s" "$work/$s-ref"
  summary=$work/$s-ref/summary.json
  median=$(sort -g "$work/$s.times" | awk '{v[NR] = $1} END {print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2}')
  if [[ $s == incremental ]]; then  # exact to round-off: it is the reference
    printf '| %s | %s | · | · | (the reference) | %.3g |\n' "$s" "$(field "$summary" termination)" "$median"
    continue
  fi
  # A scene too large for the command line's reference has no true error: say so, never print 0.
  error=$(field "$summary" error)
  [[ -n $error ]] && error=$(printf '%.2g' "$error") || error="not measured"
  printf '| %s | %s | %s | %.2g | %s | %.3g |\n' "$s" "$(field "$summary" termination)" \
    "$(field "$summary" relaxations)" "$(field "$summary" error_estimate)" "$error" "$median"
done
