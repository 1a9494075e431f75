#!/usr/bin/env bash
# The targets of docs/floor.md on the user's measure: `fas-apriori` against `incremental` on the
# scenes of the targets table, each a solve at tolerance τ that stops on its own estimate
# (`stcontact compare --solvers fas-apriori,incremental --tol τ`: timed runs alternated by strategy,
# medians of REPEATS, the true error at termination from the error run). Prints one Markdown table;
# each comparison's files stay in results/floor_at_tolerance/<scene>_<τ>/.
#
#   scripts/floor_at_tolerance.sh [REPEATS] [--large]     # default 3 repeats; about 2 minutes here
#
# --large adds the hemisphere at divisions 16 (its incremental solve alone takes about 30 s here).
# STC_BIN names the program (default build/bin/stcontact).
set -euo pipefail
repeats=${1:-3}
large=false
[[ ${2:-} == --large ]] && large=true
bin=${STC_BIN:-build/bin/stcontact}
out=results/floor_at_tolerance
seed=examples/scenes/hemicylinder.toml
half_ball=examples/scenes/hemisphere.toml

cases=(
  "seed|$seed|"
  "arc_nodes 801|$seed|--set mesh.arc_nodes=801"
  "arc_nodes 1601|$seed|--set mesh.arc_nodes=1601"
  "401 x 2001|$seed|--set mesh.arc_nodes=401 --set time.steps=2001"
  "fretting, 10 cycles x 2001|examples/scenes/fretting.toml|"
  "hemisphere, divisions 8|$half_ball|"
  "hemisphere, divisions 12|$half_ball|--set mesh.divisions=12"
)
$large && cases+=("hemisphere, divisions 16|$half_ball|--set mesh.divisions=16")

# column FILE SOLVER NAME: the value of column NAME in summary.csv's row of SOLVER.
column() {
  awk -F, -v solver="$2" -v name="$3" 'NR == 1 { for (i = 1; i <= NF; i++) c[$i] = i; next }
    $1 == solver { print $c[name] }' "$1"
}

echo "| scene | τ | incremental (s) | fas-apriori (s) | ratio | termination | relaxations | sparse solves | estimate | true error |"
echo "|---|---|---:|---:|---:|---|---:|---:|---:|---:|"
for case in "${cases[@]}"; do
  IFS='|' read -r label scene sets <<<"$case"
  for tol in 1e-4 1e-6; do
    dir=$out/$(tr ' ,' '__' <<<"$label")_$tol
    # shellcheck disable=SC2086  # $sets holds whole --set arguments
    "$bin" compare "$scene" --solvers fas-apriori,incremental --tol "$tol" --repeats "$repeats" \
      --out "$dir" --quiet $sets
    csv=$dir/summary.csv
    inc=$(column "$csv" incremental median_total_s)
    fas=$(column "$csv" fas-apriori median_total_s)
    printf '| %s | %s | %.3g | %.3g | %.2f | %s | %s | %s | %s | %s |\n' "$label" "$tol" "$inc" "$fas" \
      "$(awk -v a="$fas" -v b="$inc" 'BEGIN { print a / b }')" "$(column "$csv" fas-apriori termination)" \
      "$(column "$csv" fas-apriori relaxations)" "$(column "$csv" fas-apriori sparse_solves)" \
      "$(column "$csv" fas-apriori final_error_estimate)" "$(column "$csv" fas-apriori final_error)"
  done
done
