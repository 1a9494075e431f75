#!/usr/bin/env bash
# Description: for every hard case (examples/scenes/hard/cases.txt, full settings), the relaxations a
# strategy needs to first reach a true error, with extra scene overrides: how a setting changes the
# iteration itself, independently of where the error estimate stops it (solves run to tolerance
# 1e-9; the count is the first row of history.csv whose `error` is at or below the target).
# Sample run:
#   scripts/relaxations_to_error.sh --set "solver.coarse_iterations=15 solver.coarse_anderson=0"
# Options: --solver S (default fas-apriori), --error E (default 1e-6), --set "k=v ...", --cases "a b",
# --out DIR (default results/relaxations_to_error), --bin PATH (default build/bin/stcontact).
# Prints one markdown row per case: case | relaxations to E | relaxations to 1e-4.
set -uo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bin=$root/build/bin/stcontact
solver=fas-apriori; target=1e-6; extra=""; only_cases=""; out=$root/results/relaxations_to_error
while [ $# -gt 0 ]; do
  case $1 in
    --solver) solver=$2; shift ;;
    --error) target=$2; shift ;;
    --set) extra=$2; shift ;;
    --cases) only_cases=$2; shift ;;
    --out) out=$2; shift ;;
    --bin) bin=$2; shift ;;
    *) echo "error: unknown option '$1' (see the top of $0)" >&2; exit 1 ;;
  esac
  shift
done
[ -x "$bin" ] || { echo "error: $bin not found: build first (scripts/build.sh)" >&2; exit 1; }
trim() { sed 's/^ *//; s/ *$//' <<<"$1"; }
# first_below FILE E: relaxations of the first history row with error <= E, or "-".
first_below() {
  awk -F, -v e="$2" 'NR == 1 { for (i = 1; i <= NF; i++) col[$i] = i; next }
    $col["error"] != "" && $col["error"] + 0 <= e + 0 { print $col["relaxations"]; found = 1; exit }
    END { if (!found) print "-" }' "$1"
}
echo "| case | to $target | to 1e-4 |"
echo "|---|---|---|"
while IFS="|" read -r name scene full _small _bound; do
  name=$(trim "$name")
  case $name in ''|'#'*) continue ;; esac
  if [ -n "$only_cases" ] && ! grep -qw -- "$name" <<<"$only_cases"; then continue; fi
  args=(--set output.frames=false)
  for s in $(trim "$full") $extra; do args+=(--set "$s"); done
  dir=$out/$name
  rm -rf "$dir"
  "$bin" solve "$root/examples/scenes/hard/$(trim "$scene")" --solver "$solver" --tol 1e-9 --max-iterations 600 \
    --quiet --out "$dir" "${args[@]}" </dev/null 2>/dev/null
  if [ -f "$dir/history.csv" ]; then
    echo "| $name | $(first_below "$dir/history.csv" "$target") | $(first_below "$dir/history.csv" 1e-4) |"
  else
    echo "| $name | failed | failed |"
  fi
done <"$root/examples/scenes/hard/cases.txt"
