#!/usr/bin/env bash
# trust_checks.sh PROGRAM SOURCE_DIR WORK: the program's promises where users abuse it
# (docs/interface.md, "Output files", "Exit status"; docs/reliability.md):
#   - a run folder replaces only what a run wrote: a file of one's own in it (at its top, inside
#     vtu/, a folder of one's own, a nested run, a marker without its list) makes a run refuse,
#     naming it, before anything is computed, and keeps it; a refused run leaves no lock; a
#     symbolic link given as --out is followed; a folder without write permission is refused;
#   - every run stops on SIGINT, SIGTERM and SIGHUP, also where it runs no iteration (a long set-up):
#     exit 128 + the signal within the grace, nothing written, nothing left beside the folder;
#   - devices and pipes are refused by name, and so are sizes that only count cycles;
#   - messages name what is wrong: an unknown command, an empty name in --solvers, a time.end too
#     small, a 3D scene without `dimension = 3`, a control character in the name, a binary mesh.
# Exit 0 when every check held; each failure is printed.
set -uo pipefail
program=$(realpath "$1") source=$(realpath "$2") work=$3
seed=$source/examples/scenes/hemicylinder.toml
small=(--set mesh.arc_nodes=21 --set time.steps=21 --set output.frame_stride=10 --solver latin --quiet)
rm -rf "$work" && mkdir -p "$work"
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
# refuses NAME PATTERN COMMAND...: COMMAND exits 1 with an error line matching PATTERN.
refuses() {
  local name=$1 pattern=$2; shift 2
  local err; err=$("$@" 2>&1 >/dev/null); local status=$?
  [ $status -eq 1 ] || fail "$name: exit $status, expected 1 ($err)"
  grep -Eq -- "$pattern" <<<"$err" || fail "$name: message '$err' does not match '$pattern'"
}
nothing_beside() {  # nothing_beside DIR NAME: only NAME (if present) in DIR
  local left; left=$(ls -A "$1" | grep -v "^$2\$")
  [ -z "$left" ] || fail "left beside $1/$2: $left"
}

# --- A run folder replaces only what a run wrote.
out=$work/runs/r1
vtu=(--set 'output.format="vtu"')  # frames in a folder of the run's own, vtu/
"$program" solve "$seed" "${small[@]}" --out "$out" || fail "first run"
grep -q '^solution.h5$' "$out/.stcontact-run" && grep -q '^solution.xdmf$' "$out/.stcontact-run" ||
  fail "the marker does not list the run's solution file"
"$program" solve "$seed" "${small[@]}" "${vtu[@]}" --out "$out" || fail "a re-run into a run's own folder"
grep -q '^vtu/step_00000.vtu$' "$out/.stcontact-run" || fail "the marker does not list the run's files"
! test -e "$out/solution.xdmf" || fail "the previous run's solution.xdmf stayed"
for own in notes.txt vtu/mine.vtu mine/data.csv; do
  mkdir -p "$(dirname "$out/$own")" && echo keep > "$out/$own"
  named=$own; [ "$own" = mine/data.csv ] && named=mine  # a folder of one's own is named itself
  refuses "own file $own" "holds '$named', which its run did not write" "$program" solve "$seed" "${small[@]}" "${vtu[@]}" --out "$out"
  [ -f "$out/$own" ] || fail "own file $own was deleted"
  rm -rf "$out/$own"; [ "$own" = mine/data.csv ] && rmdir "$out/mine"
done
nothing_beside "$work/runs" r1
"$program" solve "$seed" "${small[@]}" --out "$out/nested" || fail "a nested run"
refuses "nested run" "holds 'nested', which its run did not write" "$program" solve "$seed" "${small[@]}" --out "$out"
[ -f "$out/nested/summary.json" ] || fail "the nested run was deleted"
mkdir -p "$work/handmade" && : > "$work/handmade/.stcontact-run" && echo keep > "$work/handmade/notes.txt"
refuses "marker without a list" "marker without the list of the run's files" \
  "$program" solve "$seed" "${small[@]}" --out "$work/handmade"
[ -f "$work/handmade/notes.txt" ] || fail "a folder with a bare marker was replaced"
[ ! -e "$work/.handmade.lock" ] || fail "a refused run left its lock"
mkdir -p "$work/linked/target" && ln -s "$work/linked/target" "$work/linked/link"
"$program" solve "$seed" "${small[@]}" --out "$work/linked/link" || fail "a symlinked --out"
[ -L "$work/linked/link" ] || fail "the symbolic link given as --out was replaced"
[ -f "$work/linked/target/summary.json" ] || fail "the run is not in the folder the link names"
mkdir -p "$work/locked/ro" && chmod a-w "$work/locked/ro"
if [ "$(id -u)" != 0 ]; then  # root writes anyway: the check is for users
  refuses "read-only --out" "is not writable" "$program" solve "$seed" "${small[@]}" --out "$work/locked/ro"
fi
chmod u+w "$work/locked/ro"

# --- Devices, pipes, sizes that only count cycles.
refuses "check /dev/zero" "is not a regular file" "$program" check /dev/zero
refuses "solve /dev/urandom" "is not a regular file" "$program" solve /dev/urandom --out "$work/urandom"
[ ! -e "$work/urandom" ] || fail "solve /dev/urandom created its folder"
refuses "mesh.file /dev/zero" "mesh file '/dev/zero' is not a regular file" \
  "$program" check "$source/examples/scenes/punch.toml" --set 'mesh.file="/dev/zero"'
timeout 20 "$program" check "$seed" --set 'dirichlet[0].times=[0.0, 0.2]' --set 'dirichlet[0].values=[0.0, 0.0]' \
  --set 'dirichlet[0].period=0.2' --set 'dirichlet[0].cycles=2000000000' >/dev/null ||
  fail "2e9 cycles of a periodic history did not check within 20 s"

# --- Every run stops, also where it runs no iteration.
for signal in TERM INT HUP; do
  target=$work/stopped_$signal
  "$program" solve "$source/examples/scenes/hemisphere.toml" --set mesh.divisions=24 --no-reference --quiet \
    --out "$target" &
  pid=$!
  sleep 1.5  # building the model of 180 075 dofs: no iteration yet
  start=$(date +%s.%N)
  kill -s "$signal" $pid
  wait $pid; status=$?
  took=$(awk -v a="$start" -v b="$(date +%s.%N)" 'BEGIN { printf "%.1f", b - a }')
  expected=$((128 + $(kill -l "$signal")))
  [ $status -eq $expected ] || fail "SIG$signal in the set-up: exit $status, expected $expected"
  awk -v t="$took" 'BEGIN { exit !(t < 5) }' || fail "SIG$signal in the set-up: stopped after $took s"
  [ ! -e "$target" ] || fail "SIG$signal in the set-up: $target was created"
  nothing_beside "$work" "[^.].*"
done

# --- Messages.
refuses "unknown command" "unknown command 'frobnicate' \\(the commands: check, solve" "$program" frobnicate
refuses "--solvers with a trailing comma" "--solvers: empty name in 'latin,'" \
  "$program" compare "$seed" --solvers 'latin,' --out "$work/trailing"
refuses "time.end too small" "choose a larger time.end" "$program" check "$seed" --set time.end=5e-324
refuses "subnormal time.end" "choose a larger time.end" "$program" check "$seed" --set time.end=1e-320
sed '/^dimension = 3/d; s|"../meshes/|"'"$source"'/examples/meshes/|' "$source/examples/scenes/half_ball_graded.toml" \
  > "$work/no_dimension.toml"
refuses "3D scene without dimension" "a 3D scene needs 'dimension = 3'" "$program" check "$work/no_dimension.toml"
sed '/^dimension = 3/d' "$source/examples/scenes/hemisphere.toml" > "$work/no_dimension_generator.toml"
refuses "3D generator without dimension" "a 3D scene needs 'dimension = 3'" "$program" check "$work/no_dimension_generator.toml"
sed 's/^name = .*/name = "a\\u0000b"/' "$seed" > "$work/nul_name.toml"
(cd "$work" && refuses "NUL in the name" "key 'name' = \"a\\\\x00b\" must be a plain file name" \
  "$program" solve "$work/nul_name.toml" "${small[@]}")
[ ! -e "$work/results" ] || fail "a scene named with a NUL created results/"
head -c 4096 /dev/urandom > "$work/binary.msh"
err=$("$program" check "$source/examples/scenes/punch.toml" --set "mesh.file=\"$work/binary.msh\"" 2>&1)
LC_ALL=C grep -q '[^[:print:][:space:]]' <<<"$err" && fail "a binary mesh's bytes reach the message: $err"

[ $failures -eq 0 ] && echo "every check held" || echo "$failures checks failed"
exit $((failures > 0))
