#!/usr/bin/env bash
# The manual's streaming example (examples/stream_http.cpp) against a real server: a scan prepared
# --chunked, served by octopoint-serve on a free port of 127.0.0.1, stopped by its pid at the end.
# The example must get the whole view and draw it.
# usage: example_stream_test.sh PREPARE SERVE EXAMPLE SCAN WORKDIR
set -euo pipefail
prepare=$1 serve=$2 example=$3 scan=$4 work=$5
source "$(dirname "$0")/net_script_lib.sh"
rm -rf "$work" && mkdir -p "$work/models"
"$prepare" "$scan" -o "$work/models" --name sphere --depths 4,5,6,7 --chunked >/dev/null
start_octopoint_serve "$serve" "$work/models"
trap 'stop_pid $SERVE_PID' EXIT
output=$("$example" "http://127.0.0.1:$SERVE_PORT/sphere.oct" "$work/sphere.ppm") ||
  fail "stream_http failed: $output"
case "$output" in *"view complete, depth "[1-9]*) ;; *) fail "stream_http: '$output'" ;; esac
[ "$(head -c 15 "$work/sphere.ppm")" = "$(printf 'P6\n320 240\n255\n')" ] || fail "no 320x240 PPM"
echo "ok: $output"
