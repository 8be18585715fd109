#!/usr/bin/env bash
# End to end through the real programs: a scan prepared --chunked, served by octopoint-serve on a
# free port of 127.0.0.1, drawn by octopoint-render --url. The whole view equals the file's picture;
# --bytes N gives the same picture every time; --point-budget draws the same coarser picture from
# both; bad URLs fail with one line.
# usage: serve_render_test.sh PREPARE SERVE RENDER SCAN WORKDIR
set -euo pipefail
prepare=$1 serve=$2 render=$3 scan=$4 work=$5
source "$(dirname "$0")/net_script_lib.sh"
rm -rf "$work" && mkdir -p "$work/models"
"$prepare" "$scan" -o "$work/models" --name sphere --depths 4,5,6,7 --chunked >/dev/null
start_octopoint_serve "$serve" "$work/models"
trap 'stop_pid $SERVE_PID' EXIT
url="http://127.0.0.1:$SERVE_PORT/sphere.oct"
for view in "--yaw 0" "--yaw 30 --pitch -20" "--zoom 4 --yaw 10" "--zoom 0.5 --size 640x480"; do
  # shellcheck disable=SC2086
  "$render" --file "$work/models/sphere.oct" $view --no-fill -o "$work/file.png" >/dev/null
  # shellcheck disable=SC2086
  "$render" --url "$url" $view --no-fill -o "$work/url.png" >/dev/null
  cmp -s "$work/file.png" "$work/url.png" || fail "--url and --file differ for view '$view'"
done
# In perspective (docs/perspective.md, "Chunked models"): the stream follows the perspective view,
# and the whole view is the file's picture; a cut stream draws the same picture every time, each
# region at the finest depth it holds (tests/chunked/held_parts_test.cpp: without holes).
for view in "--perspective --yaw 30 --pitch 15" "--perspective --zoom 3 --fov 90 --size 400x300"; do
  # shellcheck disable=SC2086
  "$render" --file "$work/models/sphere.oct" $view -o "$work/file.png" >/dev/null
  # shellcheck disable=SC2086
  "$render" --url "$url" $view -o "$work/url.png" >"$work/url.out"
  cmp -s "$work/file.png" "$work/url.png" || fail "--url and --file differ for view '$view'"
  grep -q "view complete" "$work/url.out" || fail "--url $view: $(cat "$work/url.out")"
done
"$render" --file "$work/models/sphere.oct" --perspective --zoom 3 --point-budget 2000 -o "$work/file.png" >/dev/null
"$render" --url "$url" --perspective --zoom 3 --point-budget 2000 -o "$work/url.png" >"$work/url.out"
cmp -s "$work/file.png" "$work/url.png" || fail "--perspective --point-budget: --url and --file differ"
grep -q "point budget 2000" "$work/url.out" || fail "--perspective --point-budget: $(cat "$work/url.out")"
"$render" --url "$url" --perspective --zoom 3 --bytes 9000 -o "$work/cut_a.png" >/dev/null
"$render" --url "$url" --perspective --zoom 3 --bytes 9000 -o "$work/cut_b.png" >/dev/null
cmp -s "$work/cut_a.png" "$work/cut_b.png" || fail "--perspective --bytes 9000 drew two different pictures"
"$render" --url "$url" --perspective --zoom 3 -o "$work/all.png" >/dev/null
cmp -s "$work/cut_a.png" "$work/all.png" && fail "--perspective: 9000 bytes drew the complete picture"
"$render" --url "$url" --bytes 3000 -o "$work/bytes_a.png" >/dev/null
"$render" --url "$url" --bytes 3000 -o "$work/bytes_b.png" >/dev/null
cmp -s "$work/bytes_a.png" "$work/bytes_b.png" || fail "--bytes 3000 drew two different pictures"
"$render" --url "$url" -o "$work/all.png" >/dev/null
cmp -s "$work/bytes_a.png" "$work/all.png" && fail "3000 bytes drew the complete picture"
# A point budget: the file and the stream draw the same, coarser picture, and say so.
"$render" --file "$work/models/sphere.oct" --point-budget 3000 -o "$work/budget_file.png" >"$work/budget.out"
grep -q "one depth coarser for the point budget" "$work/budget.out" || fail "--point-budget 3000: $(cat "$work/budget.out")"
"$render" --url "$url" --point-budget 3000 -o "$work/budget_url.png" >/dev/null
cmp -s "$work/budget_file.png" "$work/budget_url.png" || fail "--point-budget: --url and --file differ"
"$render" --file "$work/models/sphere.oct" -o "$work/file.png" >/dev/null
cmp -s "$work/budget_file.png" "$work/file.png" && fail "--point-budget 3000 drew the whole picture"
message=$("$render" --point-budget 3000 -o "$work/bad.png" 2>&1 >/dev/null) && fail "--point-budget on a version-1 model did not fail"
case "$message" in *"applies to a chunked model"*) ;; *) fail "--point-budget on a version-1 model: '$message'";; esac
for bad in "http://127.0.0.1:$SERVE_PORT/nothere.oct|404" "http://127.0.0.1:$SERVE_PORT/../etc/passwd|403" \
           "ftp://127.0.0.1/x.oct|not an http:// URL"; do
  message=$("$render" --url "${bad%|*}" -o "$work/bad.png" 2>&1 >/dev/null) && fail "${bad%|*} did not fail"
  case "$message" in *"${bad#*|}"*) ;; *) fail "${bad%|*}: '$message' does not say '${bad#*|}'";; esac
  [ ! -e "$work/bad.png" ] || fail "${bad%|*} left a PNG"
done
echo "ok: octopoint-serve on port $SERVE_PORT, --url matches --file (also in perspective), --bytes is repeatable, --point-budget"
