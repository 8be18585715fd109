#!/usr/bin/env bash
# Runs a command that must fail cleanly on bad input: a non-zero exit that is not a crash (no
# signal), exactly one line on stderr containing EXPECTED, and no file left in OUTDIR.
# usage: cli_expect_error.sh EXPECTED OUTDIR -- COMMAND [ARGS...]
set -u
expected=$1 outdir=$2
shift 3
rm -rf "$outdir"
stderr_file=$(mktemp)
"$@" >/dev/null 2>"$stderr_file"
status=$?
lines=$(wc -l <"$stderr_file")
message=$(cat "$stderr_file")
rm -f "$stderr_file"
fail() { echo "FAIL: $*"; echo "command: $*"; echo "stderr: $message"; exit 1; }
[ "$status" -ne 0 ] || fail "exit status 0 on bad input"
[ "$status" -lt 128 ] || fail "killed by a signal (status $status)"
[ "$lines" -eq 1 ] || fail "expected one line on stderr, got $lines"
case "$message" in *"$expected"*) ;; *) fail "stderr does not mention '$expected'";; esac
if [ -e "$outdir" ] && [ -n "$(ls -A "$outdir" 2>/dev/null)" ]; then fail "left output behind: $(ls -A "$outdir")"; fi
echo "ok: $message"
