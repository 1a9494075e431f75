#!/usr/bin/env bash
# check_hard_case.sh CLI SCENE OUT MAX_ERROR [KEY=VALUE...]: solves SCENE (with the --set
# overrides) with every solver of docs/interface.md and requires, for each that is available:
#  - exit 0 (converged) or 2 (not converged), never 1 or 3, and termination agreeing with it;
#  - every output written, and no NaN or Inf in the CSV files nor null where summary.json needs
#    a number;
#  - when converged (non-incremental), a true error against the incremental solution
#    (summary.json "error", docs/method.md §2) <= MAX_ERROR (justified in examples/scenes/hard/cases.txt).
# A solver that answers "not available" (exit 1) is skipped; latin and incremental must run.
set -u
cli=$1 scene=$2 out=$3 max_error=$4
shift 4
sets=()
for s in "$@"; do sets+=(--set "$s"); done
mkdir -p "$out"
failures=0 ran=""
fail() { echo "FAIL [$solver]: $*"; cat "$log"; failures=$((failures + 1)); }
value() { sed -n "s/^  \"$1\": \"\{0,1\}\([^\",]*\).*$/\1/p" "$dir/summary.json" | head -1; }

for solver in latin latin-pgd fas-aposteriori fas-apriori incremental; do
  dir=$out/$solver log=$out/$solver.log
  rm -rf "$dir"
  "$cli" solve "$scene" --solver "$solver" --quiet --out "$dir" "${sets[@]}" >"$log" 2>&1 </dev/null
  status=$?
  if [ $status -eq 1 ] && grep -q "is not available" "$log"; then
    echo "skip [$solver]: not available"
    continue
  fi
  ran+=" $solver" before=$failures
  if [ $status -ne 0 ] && [ $status -ne 2 ]; then fail "exit status $status"; continue; fi
  missing=""
  for f in summary.json history.csv reactions.csv solution.h5; do [ -s "$dir/$f" ] || missing+=" $f"; done
  [ -z "$missing" ] || { fail "missing outputs:$missing"; continue; }
  termination=$(value termination) error=$(value error) indicator=$(value indicator)
  if [ $status -eq 0 ] && [ "$termination" != converged ]; then fail "exit 0 but termination '$termination'"; fi
  if [ $status -eq 2 ] && [ "$termination" = converged ]; then fail "exit 2 but termination converged"; fi
  if grep -Eiq '(^|,)[+-]?(nan|inf)' "$dir"/*.csv; then fail "NaN or Inf in a CSV file"; fi
  [ "$indicator" != null ] || fail "summary.json: indicator is null (non-finite)"
  if [ "$termination" = converged ] && [ "$solver" != incremental ]; then
    if [ "$error" = null ] || [ -z "$error" ]; then
      fail "converged but no true error in summary.json"
    elif ! awk -v e="$error" -v m="$max_error" 'BEGIN { exit !(e <= m) }'; then
      fail "true error $error > $max_error"
    fi
  fi
  [ $failures -eq "$before" ] && echo "ok [$solver]: exit $status, $termination, $(value iterations) iterations, indicator $indicator, error $error"
done
for required in latin incremental; do
  grep -qw -- "$required" <<<"$ran" || { echo "FAIL: solver '$required' did not run"; failures=$((failures + 1)); }
done
exit $((failures > 0))
