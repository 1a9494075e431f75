#!/usr/bin/env bash
# The mesh scripts of examples/meshes/ (Gmsh, Debian 12's python3-gmsh) make meshes the program
# reads: each script's small variant is run into a scratch folder, then `stcontact check` reads the
# scene that uses it with the new file (its groups, element types and sizes). Gmsh's output differs
# between its versions (the committed meshes were made with another one), so the check is that the
# mesh is read and has contact nodes, not its node count. Exit 77 (skipped) without the gmsh module.
#   check_mesh_scripts.sh PROGRAM SOURCE_DIR PYTHON
set -euo pipefail
program=$(realpath "$1") source_dir=$(realpath "$2") python=$3
"$python" -c "import gmsh" 2>/dev/null || { echo "no gmsh module for $python: skipped"; exit 77; }
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
meshes=$source_dir/examples/meshes scenes=$source_dir/examples/scenes
cd "$meshes"
"$python" half_ball_graded.py --pole 0.08 --far 0.3 --out "$work/half_ball.msh"
"$python" fretting_pad.py --h 0.02 --out "$work/fretting_pad.msh"
"$python" sphere_cap.py --h 0.08 --out "$work/sphere_cap.msh"
"$python" block.py --h 0.2 --out "$work/block.msh"
check() {  # check SCENE KEY FILE: the scene reads FILE for KEY and has contact nodes
  local out; out=$("$program" check "$scenes/$1" --set "$2=\"$3\"")
  echo "$out"
  grep -Eq '^contact nodes +[1-9]' <<<"$out" || { echo "FAIL: $1 with $3 has no contact nodes"; exit 1; }
}
check half_ball_graded.toml mesh.file "$work/half_ball.msh"
check fretting_pad.toml mesh.file "$work/fretting_pad.msh"
check on_sphere_surface.toml obstacle.file "$work/sphere_cap.msh"
check block.toml mesh.file "$work/block.msh"
# docs/meshing.md's own mesh, solved: every part of a scene of one's own works with it.
"$program" solve "$scenes/block.toml" --set "mesh.file=\"$work/block.msh\"" --set time.steps=21 \
  --set output.frames=false --no-reference --quiet --out "$work/block_run"
grep -q '"termination": "converged"' "$work/block_run/summary.json" || { echo "FAIL: block.toml did not converge"; exit 1; }
echo "every mesh script made a mesh the program reads"
