# Sourced by scripts/sanitize.sh and scripts/fuzz.sh: how a sanitized test program reports.
# exitcode=86: a sanitizer report must not pass for one of the command line's own exit codes (0-3),
# so that the CLI contract tests fail on it too. llvm-14's symbolizer (else addr2line) puts
# file:line into the stack traces.
stc_sanitizer_common="exitcode=86"
if [ -x /usr/lib/llvm-14/bin/llvm-symbolizer ]; then
  stc_sanitizer_common+=":external_symbolizer_path=/usr/lib/llvm-14/bin/llvm-symbolizer"
fi
export ASAN_OPTIONS="$stc_sanitizer_common:detect_leaks=1:strict_string_checks=1:detect_stack_use_after_return=1${ASAN_OPTIONS:+:$ASAN_OPTIONS}"
export UBSAN_OPTIONS="$stc_sanitizer_common:print_stacktrace=1:halt_on_error=1${UBSAN_OPTIONS:+:$UBSAN_OPTIONS}"
