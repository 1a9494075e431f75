#!/usr/bin/env bash
# The fretting history (examples/scenes/hemisphere_fretting.toml) at mesh.divisions D solved to
# τ = 1e-6 by the incremental solver and fas-apriori on every linear backend: CHOLMOD on one rank,
# MUMPS and CG + GAMG on one rank and on two (one thread each), no reference, no frames. Prints a
# Markdown table of summary.json (wall time, relaxations, solves, Krylov iterations, preparation,
# peak memory per rank, Newton iterations) and keeps the run folders in OUT for
# scripts/scaling_model.py --check (docs/scale.md).
#
#   scripts/solves_on_ranks.sh [D] [OUT]        (default 12, results/solves_on_ranks_d<D>)
#
# Needs a build with PETSc and Open MPI's mpirun (docs/linear_solvers.md). As root, Open MPI asks for
# OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
divisions=${1:-12}
out=${2:-results/solves_on_ranks_d$divisions}
bin=${STC_BIN:-build/bin/stcontact}
scene=(examples/scenes/hemisphere_fretting.toml --set "mesh.divisions=$divisions" --no-reference
       --set output.frames=false --quiet --tol 1e-6 --threads 1)
mkdir -p "$out"
for backend in cholmod mumps cg-gamg; do
  for solver in incremental fas-apriori; do
    "$bin" solve "${scene[@]}" --solver "$solver" --set "solver.linear=\"$backend\"" --out "$out/$solver-$backend-np1"
    [[ $backend == cholmod ]] && continue  # one process only
    mpirun -np 2 --oversubscribe "$bin" solve "${scene[@]}" --solver "$solver" --set "solver.linear=\"$backend\"" \
      --out "$out/$solver-$backend-np2"
  done
done
"${STC_PYTHON:-python3}" - "$out" <<'EOF'
import glob, json, os, re, sys
print("| solver | backend | ranks | wall s | relaxations | sparse solves | Krylov its | preparing s | peak MB per rank | Newton its |")
print("|---|---|---:|---:|---:|---:|---:|---:|---|---:|")
for folder in sorted(glob.glob(os.path.join(sys.argv[1], "*-np*"))):
    s = json.load(open(os.path.join(folder, "summary.json")))
    newton = re.search(r"(\d+) Newton iterations", s["message"])
    print("| %s | %s | %d | %.3g | %d | %d | %d | %.3g | %s | %s |" % (
        s["solver"], s["parameters"]["solver"]["linear"], s["ranks"], s["wall_s"], s["relaxations"],
        s["sparse_solves"], s["krylov_iterations"], sum(p["seconds"] for p in s["preparations"]),
        " / ".join("%d" % (b / 2**20) for b in s["peak_memory_bytes_per_rank"]),
        newton.group(1) if newton else "–"))
EOF
