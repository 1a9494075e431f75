#!/usr/bin/env bash
# Speed-up of whole solves on 2 threads against 1 (docs/threads.md): the solve's
# wall time as summary.json records it (wall_s: from the start of the iterations, the factorisation
# and the incremental reference excluded), for each solver and mesh size, REPEATS runs per thread
# count, alternating 1 and 2 threads so that a change of the machine's load hits both alike.
#
#   scripts/threads_speedup.sh [STCONTACT_BINARY]        # default: build/bin/stcontact
#
# Environment: REPEATS (runs per case, default 5), SOLVERS (default "fas-apriori latin"),
#              ARC_NODES (mesh sizes, default "101 401"), STC_TS_OUT (scratch, default a temp folder).
# Prints one markdown row per case: median wall time on 1 and 2 threads, their ratio, the spread
# (min–max) and the load average before and after; iterations must agree (threads change no result).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
bin=${1:-build/bin/stcontact}
[[ -x $bin ]] || { echo "error: stcontact binary '$bin' not found (build it, or pass its path)" >&2; exit 1; }
repeats=${REPEATS:-5}
solvers=${SOLVERS:-"fas-apriori latin"}
sizes=${ARC_NODES:-"101 401"}
out=${STC_TS_OUT:-$(mktemp -d)}
scene=examples/scenes/hemicylinder.toml

# wall_s and iterations of one run: "seconds iterations".
run() {  # solver arc_nodes threads index
  local dir=$out/$1_$2_t$3_$4
  "$bin" solve "$scene" --solver "$1" --set mesh.arc_nodes="$2" --set output.frames=false --no-reference --quiet \
    --threads "$3" --out "$dir" || [[ $? == 2 ]]
  local wall iterations
  wall=$(grep -o '"wall_s": [0-9.e+-]*' "$dir/summary.json" | head -1 | awk '{print $2}')
  iterations=$(grep -o '"iterations": [0-9]*' "$dir/summary.json" | head -1 | awk '{print $2}')
  echo "$wall $iterations"
}

median() { sort -g | awk '{a[NR]=$1} END {print (NR % 2) ? a[(NR+1)/2] : (a[NR/2] + a[NR/2+1]) / 2}'; }
range() { sort -g | awk 'NR==1{lo=$1} {hi=$1} END {printf "%.3g–%.3g", lo, hi}'; }

echo "| solver | arc_nodes | 1 thread (s) | 2 threads (s) | speed-up | spread 1 / 2 (s) | iterations | load before → after |"
echo "|---|---|---|---|---|---|---|---|"
for solver in $solvers; do
  for n in $sizes; do
    load_before=$(cut -d' ' -f1-3 /proc/loadavg)
    : > "$out/t1"; : > "$out/t2"; : > "$out/it"
    for ((i = 0; i < repeats; i++)); do
      order="1 2"; ((i % 2)) && order="2 1"
      for t in $order; do
        read -r wall iterations < <(run "$solver" "$n" "$t" "$i")
        echo "$wall" >> "$out/t$t"; echo "$iterations" >> "$out/it"
      done
    done
    t1=$(median < "$out/t1"); t2=$(median < "$out/t2")
    its=$(sort -u "$out/it" | paste -sd/)
    echo "| $solver | $n | $t1 | $t2 | $(awk -v a="$t1" -v b="$t2" 'BEGIN{printf "%.2f", a/b}') |" \
         "$(range < "$out/t1") / $(range < "$out/t2") | $its | $load_before → $(cut -d' ' -f1-3 /proc/loadavg) |"
  done
done
