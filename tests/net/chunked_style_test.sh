#!/usr/bin/env bash
# A chunked model is drawn in colour only: every other --style, on a chunked file or over --url,
# is refused with one line and exit 1, and no picture is written (before, the colour picture was
# drawn and the style ignored). The chunked format stores no normals (octopoint-prepare refuses
# --chunked --normals), so no lit style can be drawn from it.
set -uo pipefail
. "$(dirname "$0")/net_script_lib.sh"
prepare=$1 serve=$2 render=$3 scan=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
serve_small_chunked_model "$prepare" "$serve" "$scan" "$work"
trap 'stop_pid "$SERVE_PID"' EXIT
refused() {  # $1: what is expected on stderr; the rest: the arguments
  local expected=$1
  shift
  rm -f "$work/out.png"
  "$render" "$@" -o "$work/out.png" >"$work/out" 2>"$work/err"
  local rc=$?
  [ "$rc" -eq 1 ] || fail "$*: exit $rc, not 1"
  [ "$(wc -l <"$work/err")" -eq 1 ] || fail "$*: not one line on stderr: $(cat "$work/err")"
  grep -qF -- "$expected" "$work/err" || fail "$*: $(cat "$work/err")"
  [ ! -e "$work/out.png" ] || fail "$*: wrote a picture"
}
for style in shaded lines toon outlined; do
  refused "--style $style: $work/models/small.oct: a chunked model is drawn in colour only" \
    --file "$work/models/small.oct" --style "$style"
  refused "--style $style: --url draws a chunked model, in colour only" \
    --url "http://127.0.0.1:$SERVE_PORT/small.oct" --style "$style"
done
"$render" --file "$work/models/small.oct" --style colour -o "$work/out.png" >/dev/null ||
  fail "--style colour on a chunked file was refused"
echo "ok: four styles refused on a chunked file and over --url, colour drawn"
