#!/usr/bin/env bash
# Description: what a run's outputs cost beside its solve (docs/interface.md, "What writing costs"):
# `stcontact solve SCENE --no-reference` with the default outputs, REPEATS times; per run the whole
# process's wall time (as the shell measures it: start, solve, writing, exit), the solver's wall_s,
# the writer's write_s (summary.json) and the run folder's size (du -sb); then the medians and the
# ratio process / wall_s.
# Sample run:
#   scripts/output_overhead.sh build/bin/stcontact examples/scenes/hemisphere_fretting.toml 3
#   scripts/output_overhead.sh build/bin/stcontact examples/scenes/hemisphere_fretting.toml 3 --set mesh.divisions=8
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: $0 PROGRAM SCENE REPEATS [--set KEY=VALUE]..." >&2; exit 2; }
program=$1 scene=$2 repeats=$3
shift 3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
echo "run,process_s,wall_s,write_s,folder_bytes"
for r in $(seq "$repeats"); do
  out=$work/run
  start=$(date +%s.%N)
  "$program" solve "$scene" --no-reference --quiet --out "$out" "$@" > /dev/null
  end=$(date +%s.%N)
  read -r wall write < <(/usr/bin/python3 -c "import json, sys; s = json.load(open(sys.argv[1])); print(s['wall_s'], s['write_s'])" "$out/summary.json")
  echo "$r,$(awk -v a="$start" -v b="$end" 'BEGIN { printf "%.3f", b - a }'),$wall,$write,$(du -sb "$out" | cut -f1)"
  rm -rf "$out"
done | tee "$work/rows.csv"
/usr/bin/python3 - "$work/rows.csv" <<'PY'
import csv, statistics, sys
rows = list(csv.DictReader(open(sys.argv[1]), fieldnames=["run", "process_s", "wall_s", "write_s", "folder_bytes"]))
median = lambda key: statistics.median(float(r[key]) for r in rows)
ratios = [float(r["process_s"]) / float(r["wall_s"]) for r in rows]
print("median: process %.3f s, wall_s %.3f s, write_s %.3f s, folder %.1f MB; process / wall_s %.2f (runs %s)" % (
    median("process_s"), median("wall_s"), median("write_s"), median("folder_bytes") / 1e6, statistics.median(ratios),
    ", ".join("%.2f" % r for r in ratios)))
PY
