#!/usr/bin/env bash
# The incremental solver's two forms on CG + GAMG, and the one "auto" chooses (solver.incremental_form,
# src/incremental/form_choice.hpp and form_switch.hpp; docs/scale.md, "The whole-body form"): the
# fretting history at divisions 8 (2001 instants), the shallow and the deep press at divisions 12
# (201 instants) on one process, the shallow press at divisions 20 and the fretting history at
# divisions 12 on 201 instants on two ranks, each in the three settings in turn
# (the order rotated from scene to scene), τ = 1e-6, one thread per rank, no reference, no frames.
# Prints a Markdown table of summary.json: instants m, the interface form's column solves d |Z| as
# "auto" weighed them, its choice, and each form's wall time and Krylov iterations.
#
#   scripts/incremental_forms.sh [OUT]        (default results/incremental_forms)
#
# Needs a build with PETSc and Open MPI's mpirun (docs/linear_solvers.md). As root, Open MPI asks for
# OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 in the environment.
set -euo pipefail
cd "$(dirname "$0")/.."
out=${1:-results/incremental_forms}
bin=${STC_BIN:-build/bin/stcontact}
mkdir -p "$out"
forms=(auto interface whole-body)
turn=0
for case in "hemisphere_fretting 8 1" "hemisphere_shallow 12 1" "hemisphere 12 1" "hemisphere_shallow 20 2" \
  "hemisphere_fretting 12 2 201"; do
  read -r scene divisions ranks steps <<<"$case"
  instants=()
  [ -n "$steps" ] && instants=(--set "time.steps=$steps")
  for i in 0 1 2; do
    form=${forms[$(((i + turn) % 3))]}
    mpirun -np "$ranks" --oversubscribe "$bin" solve "examples/scenes/$scene.toml" --solver incremental \
      --set "mesh.divisions=$divisions" "${instants[@]}" --set 'solver.linear="cg-gamg"' \
      --set "solver.incremental_form=\"$form\"" \
      --tol 1e-6 --no-reference --set output.frames=false --quiet --threads 1 \
      --out "$out/$scene-d$divisions${steps:+-m$steps}-np$ranks-$form"
  done
  turn=$((turn + 1))
done
"${STC_PYTHON:-python3}" - "$out" <<'PY'
import glob, json, os, re, sys
def run(prefix, form):
    return json.load(open(os.path.join(prefix + "-" + form, "summary.json")))
print("| scene | divisions | dofs | ranks | instants m | column solves d·\\|Z\\| | auto chooses | auto s | interface s / Krylov its | whole-body s / Krylov its |")
print("|---|---:|---:|---:|---:|---:|---|---:|---|---|")
for prefix in sorted({f.rsplit("-", 1)[0] for f in glob.glob(os.path.join(sys.argv[1], "*-np*-auto"))}):
    a, i, w = (run(prefix, f) for f in ("auto", "interface", "whole-body"))
    weighed = re.search(r"auto\): ([a-z-]+); (\d+) instants .* against (\d+) column solves", a["message"])
    switched = re.search(r"whole-body form for the first (\d+) instants", a["message"])
    chose = weighed.group(1) if weighed else "–"
    if switched:
        chose += ", interface after %s instants" % switched.group(1)
    print("| %s | %s | %d | %d | %d | %s | %s | %.3g | %.3g / %d | %.3g / %d |" % (
        os.path.basename(prefix).split("-d")[0], prefix.rsplit("-d", 1)[1].split("-")[0], a["n_dofs"], a["ranks"],
        a["n_steps"], weighed.group(3) if weighed else "–", chose, a["wall_s"],
        i["wall_s"], i["krylov_iterations"], w["wall_s"], w["krylov_iterations"]))
PY
