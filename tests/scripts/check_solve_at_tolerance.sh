#!/usr/bin/env bash
# scripts/solve_at_tolerance.sh on the seed scene at 21 contact nodes: one row per solver, each
# converged, the iterative ones with a true error within the tolerance and an estimate that bounds
# it, every wall time a positive number.
#   check_solve_at_tolerance.sh PROGRAM SOURCE_DIR
set -euo pipefail
program=$1 source_dir=$2
tol=1e-4
table=$(cd "$source_dir" && STC_BIN=$program scripts/solve_at_tolerance.sh \
  examples/scenes/hemicylinder.toml $tol 2 incremental latin fas-apriori -- --set mesh.arc_nodes=21)
echo "$table"
rows=$(grep -c '^| \(incremental\|latin\|fas-apriori\) |' <<<"$table")
[[ $rows -eq 3 ]] || { echo "FAIL: expected 3 rows, got $rows"; exit 1; }
awk -F'|' -v tol=$tol '
  /^\| (incremental|latin|fas-apriori) \|/ {
    solver = $2; gsub(/ /, "", solver)
    if ($3 !~ /converged/) { print "FAIL: " solver " did not converge"; bad = 1 }
    if (!($7 + 0 > 0)) { print "FAIL: " solver " wall time " $7; bad = 1 }
    if (solver != "incremental" && !($6 + 0 <= tol && $6 + 0 <= $5 + 0)) {
      print "FAIL: " solver " true error " $6 ", estimate " $5; bad = 1
    }
  }
  END { exit bad }' <<<"$table"
