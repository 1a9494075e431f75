#!/usr/bin/env bash
# The main job: install the dependencies, build the program in Release (the test command,
# scripts/run_tests.sh, builds the rest: tests, examples, the Python module), solve the seed scene
# (examples/scenes/hemicylinder.toml), draw the figures, then compare every available strategy
# (work against precision, docs/compare.md).
# Results: results/hemicylinder/<solver>/, results/hemicylinder/figures/*.png and the report
# results/hemicylinder/compare/summary.md (with work_precision.csv, summary.csv, error_vs_*.png).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
build=${STC_BUILD_DIR:-$root/build}
cd "$root"
[ "$(id -u)" -eq 0 ] && scripts/install_deps.sh || echo "not root: skipping apt-get (see scripts/install_deps.sh)"
scripts/build.sh stcontact_cli
echo "== the program built, $SECONDS s after the start"
stc="$build/bin/stcontact"
scene=examples/scenes/hemicylinder.toml
out=results/hemicylinder

echo "== 1. the model"
"$stc" check "$scene"
echo "== 2. incremental reference solver"
"$stc" solve "$scene" --solver incremental --out "$out/incremental"
echo "== 3. the default solver (fas-apriori, the scene's [solver] name) and plain LATIN over the whole space-time grid (true error against the incremental solution)"
"$stc" solve "$scene" --out "$out/fas-apriori"
"$stc" solve "$scene" --solver latin --out "$out/latin"
echo "== 4. figures"
mkdir -p "$out/figures"
gnuplot -e "run='$out'" scripts/plots/seed_figures.gp
ls "$out"/figures/*.png
echo "== 5. work against precision: every available strategy, 3 timed repeats, medians; --tol 1e-8 so that each runs past true error 1e-6 (docs/compare.md)"
"$stc" compare "$scene" --repeats 3 --tol 1e-8 --out "$out/compare"
echo "results in $root/$out/ (open solution.xdmf in ParaView for the fields)"
echo "work-precision report: $root/$out/compare/summary.md (plots: $root/$out/compare/error_vs_*.png)"
