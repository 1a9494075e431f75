#!/usr/bin/env bash
# The main job: install the dependencies, build in Release, solve the seed scene
# (examples/scenes/hemicylinder.toml) with every available strategy, and draw the figures.
# Results: results/hemicylinder/<solver>/ and results/hemicylinder/figures/*.png
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_BUILD_DIR:-$root/build}
cd "$root"
[ "$(id -u)" -eq 0 ] && scripts/install_deps.sh || echo "not root: skipping apt-get (see scripts/install_deps.sh)"
scripts/build.sh
stc="$build/bin/stcontact"
scene=examples/scenes/hemicylinder.toml
out=results/hemicylinder

echo "== 1. the model"
"$stc" check "$scene"
echo "== 2. incremental reference solver"
"$stc" solve "$scene" --solver incremental --out "$out/incremental"
echo "== 3. LATIN over the whole space-time grid (true error against the incremental solution)"
"$stc" solve "$scene" --solver latin --out "$out/latin"
echo "== 4. figures"
mkdir -p "$out/figures"
gnuplot -e "run='$out'" scripts/plots/seed_figures.gp
ls "$out"/figures/*.png
echo "results in $root/$out/ (open solution.pvd in ParaView for the fields)"
