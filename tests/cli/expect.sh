#!/usr/bin/env bash
# expect.sh [--absent PATH] CODE PATTERN PROGRAM ARGS...: run PROGRAM, require exit status CODE; for
# CODE 1 require exactly one line on stderr starting with "error:" and matching PATTERN (extended
# regex); for other codes require PATTERN in stdout+stderr.
# --absent PATH: PATH is removed before the run and must not exist after it (a refused run
# creates no output folder and no file, half-written or not).
set -u
absent=""
if [ "${1:-}" = "--absent" ]; then absent=$2; shift 2; rm -rf -- "$absent"; fi
code=$1; pattern=$2; shift 2
out=$(mktemp); err=$(mktemp)
trap 'rm -f "$out" "$err"' EXIT
"$@" >"$out" 2>"$err" </dev/null
status=$?
fail() { echo "FAIL: $*"; echo "--- stdout"; cat "$out"; echo "--- stderr"; cat "$err"; exit 1; }
[ "$status" -eq "$code" ] || fail "exit status $status, expected $code"
if [ "$code" -eq 1 ]; then
  [ "$(wc -l <"$err")" -eq 1 ] || fail "stderr must be exactly one line"
  grep -Eq '^error: ' "$err" || fail "stderr must start with 'error: '"
  grep -Eq -- "$pattern" "$err" || fail "stderr does not match /$pattern/"
else
  cat "$out" "$err" | grep -Eq -- "$pattern" || fail "output does not match /$pattern/"
fi
if [ -n "$absent" ] && [ -e "$absent" ]; then fail "$absent was created: $(find "$absent" | head -5 | tr '\n' ' ')"; fi
echo "ok: exit $status, /$pattern/ found${absent:+, $absent not created}"
