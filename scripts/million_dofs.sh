#!/usr/bin/env bash
# The million-dof solve (docs/linear_solvers.md, "A million degrees of freedom"): the shallow press
# (examples/scenes/hemisphere_shallow.toml) at mesh.divisions D (44: 1.07M dofs) solved by fas-apriori
# to τ = 1e-6 with CG + GAMG on N ranks (one thread each), no reference, no frames. The progress goes
# to OUT.log as the run goes; at the end it prints one Markdown row of summary.json (wall time,
# relaxations, sparse solves, Krylov iterations, preparation, estimate, peak memory per rank).
#
#   scripts/million_dofs.sh [N] [D] [OUT]      (default 2, 44, results/million_dofs_d<D>_np<N>)
#
# SOLVER=incremental in the environment solves it with the incremental solver instead (--solver, its
# default OUT ending in _incremental): the competitor on the same engine, which on CG + GAMG (no
# trailing block) solves for the Delassus columns of the nodes that close, three Krylov solves each.
# FORM (solver.incremental_form, docs/scale.md "The whole-body form") with SOLVER=incremental: "auto"
# by default (the whole-body form on this scene past divisions 12), "interface" or "whole-body" (OUT
# ending in _incremental_interface or _incremental_whole_body).
# With REFERENCE=1 the incremental reference is computed first (--reference) and the row gets the
# true error at termination (the `error` of summary.json) beside the estimate. With TRUE_ERROR=1 the
# true error is measured after the run instead, on one process with the embedded CHOLMOD
# (`stcontact true-error`, docs/interface.md), where the direct factor fits (to about 4·10⁵ dofs here).
#
# Needs a build with PETSc and Open MPI's mpirun (docs/linear_solvers.md). As root, Open MPI asks for
# OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
ranks=${1:-2}
divisions=${2:-44}
solver=${SOLVER:-fas-apriori}
form=${FORM:-auto}
suffix=$([ "$solver" = fas-apriori ] || echo "_$solver")$([ "$form" = auto ] || echo "_${form//-/_}")
out=${3:-results/million_dofs_d${divisions}_np${ranks}${suffix}}
bin=${STC_BIN:-build/bin/stcontact}
reference=--no-reference
[ "${REFERENCE:-0}" = 1 ] && reference=--reference
mkdir -p "$(dirname "$out")"
mpirun -np "$ranks" --oversubscribe "$bin" solve examples/scenes/hemisphere_shallow.toml --solver "$solver" \
  --set "mesh.divisions=$divisions" --set 'solver.linear="cg-gamg"' --set "solver.incremental_form=\"$form\"" \
  --tol 1e-6 "$reference" \
  --set output.frames=false --threads 1 --out "$out" 2>&1 | tee "$out.log"
"${STC_PYTHON:-python3}" - "$out" <<'EOF'
import json, os, sys
s = json.load(open(os.path.join(sys.argv[1], "summary.json")))
error = s.get("error")
print("| dofs | ranks | termination | wall s | relaxations | sparse solves | Krylov its | preparing s | estimate |"
      + (" true error | reference s |" if error is not None else "") + " peak MB per rank |")
print("|---:|---:|---|---:|---:|---:|---:|---:|---:|" + ("---:|---:|" if error is not None else "") + "---|")
print("| %d | %d | %s | %.0f | %d | %d | %d | %.3g | %.2g |" % (
    s["n_dofs"], s["ranks"], s["termination"], s["wall_s"], s["relaxations"], s["sparse_solves"],
    s["krylov_iterations"], sum(p["seconds"] for p in s["preparations"]), s["error_estimate"])
    + (" %.2g | %.0f |" % (error, s["reference_s"]) if error is not None else "")
    + " %s |" % " / ".join("%d" % (b / 2**20) for b in s["peak_memory_bytes_per_rank"]))
EOF
if [ "${TRUE_ERROR:-0}" = 1 ]; then
  "$bin" true-error examples/scenes/hemisphere_shallow.toml --set "mesh.divisions=$divisions" --solution "$out/solution.h5" \
    --quiet | tee -a "$out.log"
fi
