#!/usr/bin/env bash
# 50 clients against octopoint-serve for 30 s on loopback (tests/net/load_test.cpp): zero failed
# requests, no growth of the server's memory after the first seconds.
# usage: load_test.sh PREPARE SERVE LOAD_TEST SCAN WORKDIR [CLIENTS SECONDS]
set -euo pipefail
prepare=$1 serve=$2 load=$3 scan=$4 work=$5 clients=${6:-50} seconds=${7:-30}
source "$(dirname "$0")/net_script_lib.sh"
rm -rf "$work" && mkdir -p "$work/models"
"$prepare" "$scan" -o "$work/models" --name sphere --depths 4,5,6,7,8 --chunked >/dev/null
start_octopoint_serve "$serve" "$work/models" --max-connections 64
trap 'stop_pid $SERVE_PID' EXIT
"$load" "http://127.0.0.1:$SERVE_PORT/sphere.oct" "$SERVE_PID" "$clients" "$seconds"
