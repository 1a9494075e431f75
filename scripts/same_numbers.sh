#!/usr/bin/env bash
# Description: checks that two builds of the program give the same numbers (a refactoring's
# promise: "behaviour, output files and numbers unchanged"). Runs the same solves with both
# programs and compares every output file, leaving out what legitimately differs from run to run:
# wall times (history.csv's wall_s, summary.json's times, its sub_grid's, its peak memory and version, run.log, the timing
# columns of the reports) and the messages' seconds. Everything else must be byte-identical: iterations,
# relaxations, indicators, true errors, estimates, ranks, reactions, contact tables, VTU series.
# Sample run:
#   scripts/same_numbers.sh OLD/bin/stcontact build/bin/stcontact            # about 3 minutes
#   scripts/same_numbers.sh OLD/bin/stcontact build/bin/stcontact --quick    # the seed scene only
# Exit status: 0 every file agrees, 1 a difference (each printed as a unified diff), 2 bad usage.
set -uo pipefail
[ $# -ge 2 ] || { echo "usage: $0 OLD_PROGRAM NEW_PROGRAM [--quick]" >&2; exit 2; }
old=$(realpath "$1"); new=$(realpath "$2"); quick=${3:-}
for bin in "$old" "$new"; do [ -x "$bin" ] || { echo "error: $bin is not a program" >&2; exit 2; }; done
root=$(cd "$(dirname "$0")/.." && pwd)
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT
scenes=$root/examples/scenes
solvers="latin latin-pgd fas-aposteriori fas-apriori incremental"
status=0

# timed_columns SEPARATOR: awk that blanks every column whose header names a time, a speed ratio
# or a memory figure (wall_s, time_to_1e-4_s, time_ratio_*, peak_rss_mb, "solve s", ...).
timed_columns() {
  awk -F"$1" -v OFS="$1" 'NR == 1 || /^\| case/ {
      for (i = 1; i <= NF; i++) drop[i] = ($i ~ /(_s$|_s_|time|(^|_)ratio|rss|memory| s *$)/) }
    { for (i = 1; i <= NF; i++) if (drop[i]) $i = "#"; print }'
}

# h5_digest FILE: every dataset of an HDF5 file with a digest of its values, and the file's
# attributes, but the times (the attribute and history column "wall_s", the message's seconds) and the version.
h5_digest() {
  /usr/bin/python3 - "$1" <<'PY'
import hashlib, re, sys
import h5py
with h5py.File(sys.argv[1], "r") as f:
    for key, value in sorted(f.attrs.items()):
        if key not in ("wall_s", "version"):  # the message's seconds blanked as in summary.json
            print("@%s = %s" % (key, re.sub(r"[0-9.e+-]+ s\)", "# s)", str(value))))
    def show(name, item):
        if isinstance(item, h5py.Dataset) and name != "history/wall_s":
            print(name, item.dtype, item.shape, hashlib.sha256(item[()].tobytes()).hexdigest())
    f.visititems(show)
PY
}

# normalise FILE [BOTH]: the file without what differs between two runs of the same build. A
# summary.json keeps its "preparations" (the operators the run prepared, without their seconds) only
# when BOTH programs write them (BOTH = 1): a program from before they were listed writes none.
normalise() {
  case $1 in
    */summary.json)
      sed -E '/^ +"peak_memory_bytes_per_rank": \[/,/^ +\],?$/d; /^ +"(wall_s|reference_s|write_s|run_s|version|seconds|peak_memory_bytes)":/d
              s/[0-9.e+-]+ s\)/# s)/g' "$1" |
        if [ "${2:-1}" = 1 ]; then cat; else sed '/^  "preparations": \[/,/^  \],$/d'; fi ;;
    *.csv) timed_columns , < "$1" ;;
    *.md|*.png|*.gp|*/run.log) echo "(not compared: times and figures)" ;;
    *.vtu) cat "$1" ;;  # binary frames: compared byte for byte
    *.h5) h5_digest "$1" ;;
    *) sed -E 's/[0-9.]+ s\)/# s)/g' "$1" ;;
  esac
}

# compare NAME: every file of $work/old/NAME against $work/new/NAME.
compare() {
  local a=$work/old/$1 b=$work/new/$1
  local files; files=$( (cd "$a" && find . -type f; cd "$b" && find . -type f) | sort -u)
  for f in $files; do
    if [ ! -f "$a/$f" ] || [ ! -f "$b/$f" ]; then
      echo "DIFF $1/$f: present in one run only"; status=1; continue
    fi
    local both=1
    if [ "$(grep -c '"preparations"' "$a/$f")" != "$(grep -c '"preparations"' "$b/$f")" ]; then both=0; fi
    if ! diff -u <(normalise "$a/$f" $both) <(normalise "$b/$f" $both) > "$work/diff" 2>&1; then
      echo "DIFF $1/$f"; head -20 "$work/diff"; status=1
    fi
  done
  echo "checked $1 ($(echo "$files" | wc -w) files)"
}

# run NAME ARGS...: the same command with both programs, outputs in $work/{old,new}/NAME.
run() {
  local name=$1; shift
  for side in old new; do
    local bin=$old; [ $side = new ] && bin=$new
    mkdir -p "$work/$side/$name"
    "$bin" "$@" --out "$work/$side/$name" > "$work/$side/$name.log" 2>&1
    echo "exit $?" > "$work/$side/$name/exit_status"
  done
  compare "$name"
}

seed=(--set output.frame_stride=50)
for s in $solvers; do run "seed_$s" solve "$scenes/hemicylinder.toml" --solver "$s" "${seed[@]}" --quiet; done
if [ "$quick" != --quick ]; then
  small3d=(--set mesh.divisions=4 --set time.steps=41 --set output.frame_stride=20)
  for s in $solvers; do run "hemisphere_$s" solve "$scenes/hemisphere.toml" --solver "$s" "${small3d[@]}" --quiet; done
  for s in $solvers; do
    run "punch_$s" solve "$scenes/punch.toml" --solver "$s" --set time.steps=41 --set output.frames=false --quiet
  done
  run slab_apriori solve "$scenes/slab.toml" --set time.steps=41 --set output.frames=false --quiet
  run seed_nested solve "$scenes/hemicylinder.toml" --set time.steps=801 --set output.frames=false --quiet
  run seed_whole_interface solve "$scenes/hemicylinder.toml" --set solver.reduce_interface=false \
    --set solver.coarse_zone=false --set output.frames=false --quiet
  run seed_mismatch solve "$scenes/hemicylinder.toml" --solver fas-aposteriori --set solver.coarse_start=mismatch \
    --set solver.safeguard_growth=2 --set output.frames=false --quiet
  run seed_relaxed solve "$scenes/hemicylinder.toml" --solver latin-pgd --set solver.relaxation=0.8 \
    --set solver.pgd_gap_share=0.1 --set output.frames=false --quiet
  run sweep sweep "$scenes/hemicylinder.toml" --set-range contact.friction=0.1:0.3:3 --set mesh.arc_nodes=41 \
    --set time.steps=41 --quiet
  run compare compare "$scenes/hemicylinder.toml" --set mesh.arc_nodes=31 --set time.steps=31 --repeats 1 --quiet
  for side in old new; do
    bin=$old; [ $side = new ] && bin=$new
    bash "$root/scripts/hard_cases.sh" --small --bin "$bin" --out "$work/$side/hard" --report "$work/$side/hard.md" \
      > /dev/null 2>&1
    grep '^|' "$work/$side/hard.md" | timed_columns '|' > "$work/$side/hard_table.txt"
  done
  if ! diff -u "$work/old/hard_table.txt" "$work/new/hard_table.txt"; then status=1; fi
  echo "checked the hard-case table at small settings"
fi
[ $status = 0 ] && echo "same numbers" || echo "DIFFERENCES (above)"
exit $status
