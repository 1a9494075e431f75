#!/usr/bin/env bash
# mpi_ranks.sh PROGRAM SOURCE_DIR WORK: two MPI ranks give one process's answer (docs/linear_solvers.md,
# "Ranks"). On the seed scene, the hemisphere at divisions 8 and the two cylinders (small settings),
# `mpirun -np 2 stcontact solve` with
#   - mumps: the iterations and the reactions of one process, to 1e-8 relative (round-off apart);
#   - cg-gamg: converged, its true error (against the incremental reference the ranks compute
#     together) within the tolerance;
# each summary saying 2 ranks, its backend, each rank's peak memory (and cg-gamg's Krylov iterations); `auto` takes mumps on 2 ranks; `solver.linear =
# "cholmod"` and another command than solve are refused there; fas-apriori's frames are written on 2
# ranks as in one process, incremental's not (it holds no displacement); the incremental solver's
# whole-body form on 2 ranks gives the interface form's forces; cg-gamg's columns solved in two
# groups of one rank give the ranks' answer together; `stcontact true-error` on one process measures the
# true error the ranks measured. Exit 0 when every check held; each failure is printed.
set -uo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
rm -rf "$work" && mkdir -p "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
# One machine: ranks started by fork (no ssh needed, which a fresh machine may lack), and shared
# memory without the cross-memory attach that containers forbid.
export OMPI_MCA_plm=isolated OMPI_MCA_btl_vader_single_copy_mechanism=none
export STC_THREADS=1
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
mpi() { mpirun -np "$1" --oversubscribe "${@:2}"; }

# compare ONE TWO BACKEND: summaries and reactions of the run on one process and on two ranks.
compare() {
  python3 - "$1" "$2" "$3" <<'PY' || fail "$3: $1 against $2"
import csv, json, sys
one, two, backend = sys.argv[1:]
s1, s2 = (json.load(open(d + "/summary.json")) for d in (one, two))
ok = True
def check(cond, what):
    global ok
    if not cond:
        print("  " + what); ok = False
check(s1["ranks"] == 1 and s2["ranks"] == 2, f"ranks {s1['ranks']}, {s2['ranks']}")
check(all(p["backend"] == backend for p in s1["preparations"] + s2["preparations"]), "backend")
peaks = s2["peak_memory_bytes_per_rank"]
check(len(peaks) == 2 and min(peaks) > 0 and s2["peak_memory_bytes"] == max(peaks), f"peak memory per rank {peaks}")
if backend == "cg-gamg":
    # the solve's iterations, within those of its operators (which the reference used too)
    check(0 < s2["krylov_iterations"] <= sum(p["krylov_iterations"] for p in s2["preparations"]),
          f"krylov iterations {s2['krylov_iterations']}")
check(s2["termination"] == "converged", f"2 ranks: {s2['termination']} ({s2['message']})")
if backend == "mumps":
    check(abs(s1["iterations"] - s2["iterations"]) <= 1, f"iterations {s1['iterations']} against {s2['iterations']}")
    rows = [list(csv.reader(open(d + "/reactions.csv"))) for d in (one, two)]
    worst, scale = 0.0, 0.0
    for a, b in zip(rows[0][1:], rows[1][1:]):
        for x, y in zip(a, b):
            if x == "" and y == "":
                continue  # a column without a value at this instant
            worst = max(worst, abs(float(x) - float(y))); scale = max(scale, abs(float(x)))
    check(worst <= 1e-8 * scale, f"reactions differ by {worst:.3g} of {scale:.3g}")
    print(f"  {one}: reactions agree to {worst / scale:.2g} relative")
else:
    check(s2["error"] is not None and s2["error"] <= 1e-6, f"true error {s2['error']} against tolerance 1e-6")
    print(f"  {two}: true error {s2['error']:.3g}")
sys.exit(0 if ok else 1)
PY
}

scenes=(
  "seed:$source/examples/scenes/hemicylinder.toml:mesh.arc_nodes=31 time.steps=31"
  "hemisphere:$source/examples/scenes/hemisphere.toml:mesh.divisions=8 time.steps=21"
  "two_cylinders:$source/examples/scenes/two_cylinders.toml:mesh.arc_nodes=31 time.steps=21"
)
for entry in "${scenes[@]}"; do
  IFS=: read -r name scene settings <<<"$entry"
  sets=(); for s in $settings; do sets+=(--set "$s"); done
  for backend in mumps cg-gamg; do
    for ranks in 1 2; do
      out=$work/${name}_${backend}_$ranks
      mpi "$ranks" "$program" solve "$scene" "${sets[@]}" --set "solver.linear=\"$backend\"" --set output.frames=false \
        --out "$out" --quiet > "$out.log" 2>&1 || fail "$name $backend on $ranks ranks: exit $? ($(tail -1 "$out.log"))"
    done
    compare "$work/${name}_${backend}_1" "$work/${name}_${backend}_2" "$backend"
  done
done

seed=$source/examples/scenes/hemicylinder.toml
mpi 2 "$program" solve "$seed" --set mesh.arc_nodes=21 --set time.steps=11 --set output.frames=false --out "$work/auto" \
  --quiet > "$work/auto.log" 2>&1 || fail "auto on 2 ranks: exit $? ($(tail -1 "$work/auto.log"))"
grep -q '"backend": "mumps"' "$work/auto/summary.json" 2>/dev/null || fail "auto on 2 ranks did not take mumps"
err=$(mpi 2 "$program" solve "$seed" --set 'solver.linear="cholmod"' --out "$work/cholmod" 2>&1); status=$?
[ $status -eq 1 ] && grep -q 'runs in one process; on 2 ranks choose' <<<"$err" ||
  fail "cholmod on 2 ranks: exit $status ($err)"
[ ! -e "$work/cholmod" ] || fail "cholmod on 2 ranks created its folder"
err=$(mpi 2 "$program" check "$seed" 2>&1); status=$?
[ $status -eq 1 ] && grep -q "only 'solve' runs on several MPI ranks" <<<"$err" || fail "check on 2 ranks: exit $status ($err)"
[ "$(grep -c '^error:' <<<"$err")" -eq 1 ] || fail "check on 2 ranks: the error said $(grep -c '^error:' <<<"$err") times"

# Frames on two ranks: fas-apriori holds its displacement, rank 0 forms them without a solve; they
# agree with one process's (each within the tolerance of u(lambda) in energy: compared at 1e-4 of
# the largest displacement). incremental holds none: its run says so and writes no frames.
for ranks in 1 2; do
  mpi "$ranks" "$program" solve "$seed" --set mesh.arc_nodes=31 --set time.steps=21 --set 'solver.linear="mumps"' \
    --out "$work/frames_$ranks" --quiet > "$work/frames_$ranks.log" 2>&1 || fail "frames on $ranks ranks: exit $?"
done
"${STC_PYTHON:-python3}" - "$work/frames_1" "$work/frames_2" <<'PY' || fail "frames on 2 ranks"
import sys
import h5py, numpy as np
one, two = (h5py.File(d + "/solution.h5", "r") for d in sys.argv[1:])
assert list(one["frames/steps"]) == list(two["frames/steps"]) == list(range(21)), list(two["frames/steps"])
u1, u2 = one["frames/step_00020/displacement"][()], two["frames/step_00020/displacement"][()]
worst = np.abs(u1 - u2).max() / np.abs(u1).max()
print(f"  frames on 2 ranks: the last displacement agrees to {worst:.2g} relative")
sys.exit(0 if worst <= 1e-4 else 1)
PY
grep -q '"writer_sparse_solves": 0' "$work/frames_2/summary.json" || fail "frames on 2 ranks: the writer solved"
mpi 2 "$program" solve "$seed" --set mesh.arc_nodes=31 --set time.steps=21 --set 'solver.linear="mumps"' \
  --solver incremental --out "$work/no_frames" > "$work/no_frames.log" 2>&1 || fail "incremental on 2 ranks: exit $?"
grep -q 'no frames on 2 ranks from incremental' "$work/no_frames/run.log" && [ ! -e "$work/no_frames/solution.xdmf" ] &&
  [ -e "$work/no_frames/solution.h5" ] || fail "incremental on 2 ranks: frames or no note"

# The incremental solver's whole-body form on two ranks (cg-gamg, its contact dofs held on both):
# the forces of the interface form on one process with CHOLMOD, to 1e-6 of the largest (its instants
# stop at the noise of solves at the linear tolerance, 1e-10 of ‖b‖ at τ = 1e-6: measured 3e-9).
hemisphere=(solve "$source/examples/scenes/hemisphere.toml" --set mesh.divisions=8 --set time.steps=21 --solver incremental
            --set output.frames=false --quiet)
mpi 1 "$program" "${hemisphere[@]}" --set 'solver.linear="cholmod"' --out "$work/interface_form" \
  > "$work/interface_form.log" 2>&1 || fail "incremental on one process: exit $?"
mpi 2 "$program" "${hemisphere[@]}" --set 'solver.linear="cg-gamg"' --set 'solver.incremental_form="whole-body"' \
  --out "$work/whole_body_2" > "$work/whole_body_2.log" 2>&1 || fail "whole-body form on 2 ranks: exit $?"
"${STC_PYTHON:-python3}" - "$work/interface_form" "$work/whole_body_2" <<'PY' || fail "whole-body form on 2 ranks"
import sys
import h5py, numpy as np
one, two = (h5py.File(d + "/solution.h5", "r")["interface/force"][()] for d in sys.argv[1:])
worst = np.abs(one - two).max() / np.abs(one).max()
print(f"  whole-body form on 2 ranks: the forces agree with the interface form's to {worst:.2g} relative")
sys.exit(0 if worst <= 1e-6 else 1)
PY

# cg-gamg's right-hand sides in two groups of one rank each (solver.linear_groups = 2): each rank
# solves its half of a block of directions with its own copy of the operator, then both hold every
# column. The same relaxations and directions as the two ranks solving each column together, the
# forces to 1e-6 of the largest (both stop each column at 1e-10 of its right-hand side), Krylov
# iterations counted over both groups; three groups on two ranks are refused by name.
fas=(solve "$source/examples/scenes/hemisphere.toml" --set mesh.divisions=8 --set time.steps=21
     --set 'solver.linear="cg-gamg"' --set output.frames=false --no-reference --quiet)
for groups in 1 2; do
  mpi 2 "$program" "${fas[@]}" --set "solver.linear_groups=$groups" --out "$work/groups_$groups" \
    > "$work/groups_$groups.log" 2>&1 || fail "linear_groups = $groups on 2 ranks: exit $?"
done
"${STC_PYTHON:-python3}" - "$work/groups_1" "$work/groups_2" <<'PY' || fail "linear_groups = 2 on 2 ranks"
import json, sys
import h5py, numpy as np
one, two = sys.argv[1:]
s1, s2 = (json.load(open(d + "/summary.json")) for d in (one, two))
f1, f2 = (h5py.File(d + "/solution.h5", "r")["interface/force"][()] for d in (one, two))
worst = np.abs(f1 - f2).max() / np.abs(f1).max()
print(f"  two groups: {s2['sparse_solves']} solves, {s2['krylov_iterations']} Krylov iterations "
      f"(together: {s1['sparse_solves']}, {s1['krylov_iterations']}); forces agree to {worst:.2g}")
ok = (s2["termination"] == "converged" and s2["relaxations"] == s1["relaxations"]
      and s2["sparse_solves"] == s1["sparse_solves"] and worst <= 1e-6
      and 0.8 * s1["krylov_iterations"] <= s2["krylov_iterations"] <= 1.2 * s1["krylov_iterations"])
sys.exit(0 if ok else 1)
PY
err=$(mpi 2 "$program" "${fas[@]}" --set solver.linear_groups=3 --out "$work/groups_3" 2>&1); status=$?
[ $status -eq 1 ] && grep -q 'linear_groups = 3: must divide the 2 ranks' <<<"$err" ||
  fail "linear_groups = 3 on 2 ranks: exit $status ($err)"

# The true error measured afterwards on one process (`stcontact true-error`, its reference on the
# embedded CHOLMOD) agrees with the one the two ranks measured during the solve against their own
# CG + GAMG reference: to 2 % (the two references differ by their linear tolerance, a few 1e-10,
# against true errors near 1e-7), on the hemisphere at divisions 8.
run=$work/hemisphere_cg-gamg_2
printed=$("$program" true-error "$source/examples/scenes/hemisphere.toml" --set mesh.divisions=8 --set time.steps=21 \
  --solution "$run/solution.h5" --quiet) || fail "true-error on the two ranks' solution: exit $?"
python3 - "$run/summary.json" "$printed" <<'PY' || fail "true-error against the two ranks' own true error"
import json, re, sys
ranks = json.load(open(sys.argv[1]))["error"]
one = float(re.search(r"^true error (\S+) ", sys.argv[2], re.M).group(1))
print(f"  true error on one process {one:.4e}, on the two ranks during the solve {ranks:.4e}")
sys.exit(0 if 0 < one <= 1e-6 and abs(one - ranks) <= 0.02 * ranks else 1)
PY

[ $failures -eq 0 ] && echo "every check held" || echo "$failures failures"
[ $failures -eq 0 ]
