#!/usr/bin/env bash
# true_error_checks.sh PROGRAM SOURCE_DIR WORK: `stcontact true-error` (docs/interface.md, "Checking a
# run's true error") measures, from a run's solution.h5 alone, the true error the run measured itself
# against its own reference: on the seed scene at small settings, for a converged fas-apriori solve
# (error near 1e-7) and for LATIN stopped after 3 iterations (error near 1e-1), to 1e-6 relative
# (the same reference solve and measure, the forces read back bit for bit), and the incremental
# solver's own solution at round-off. Exit 0 when every check holds;
# each failure is printed.
set -uo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
rm -rf "$work" && mkdir -p "$work"
seed=$source/examples/scenes/hemicylinder.toml
small=(--set mesh.arc_nodes=21 --set time.steps=21)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }

# agree NAME: the run's own true error (summary.json) against the command's, both printed.
agree() {
  local run=$work/$1
  local printed
  printed=$("$program" true-error "$seed" "${small[@]}" --solution "$run/solution.h5" --quiet) ||
    { fail "$1: true-error exited $?"; return; }
  echo "$printed"
  python3 - "$run/summary.json" "$printed" <<'PY' || fail "$1: the errors differ"
import json, re, sys
own = json.load(open(sys.argv[1]))["error"]
text = sys.argv[2]
measured = float(re.search(r"^true error (\S+) ", text, re.M).group(1))
said = float(re.search(r"the run's own true error (\S+)", text).group(1))
print(f"  run {own:.6e}, command {measured:.6e}")
sys.exit(0 if abs(measured - own) <= 1e-6 * own and abs(said - own) <= 1e-6 * own and own > 0 else 1)
PY
}

"$program" solve "$seed" "${small[@]}" --solver fas-apriori --set output.frames=false --out "$work/fas" --quiet ||
  fail "fas-apriori solve: exit $?"
agree fas
"$program" solve "$seed" "${small[@]}" --solver latin --max-iterations 3 --set output.frames=false --out "$work/latin3" \
  --quiet
[ $? -eq 2 ] || fail "latin stopped after 3 iterations: exit 2 expected"
agree latin3
# The incremental solver's solution is the reference's own (the same solve): a true error at round-off,
# and no estimate line (the solver has none; solution.h5 holds 0).
"$program" solve "$seed" "${small[@]}" --solver incremental --set output.frames=false --out "$work/incremental" --quiet ||
  fail "incremental solve: exit $?"
printed=$("$program" true-error "$seed" "${small[@]}" --solution "$work/incremental/solution.h5" --quiet)
echo "$printed"
python3 - "$printed" <<'PY' || fail "incremental: a true error at round-off and no estimate expected"
import re, sys
text = sys.argv[1]
sys.exit(0 if float(re.search(r"^true error (\S+) ", text, re.M).group(1)) <= 1e-12 and "estimate" not in text else 1)
PY
[ $failures -eq 0 ] && echo "ok: the command measures the runs' own true errors"
exit $((failures > 0))
