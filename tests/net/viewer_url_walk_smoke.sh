#!/usr/bin/env bash
# octopoint-view --url in walk mode, in a real X server (Xvfb), against octopoint-serve shaped to a
# slow link: started with --eye, the stream follows the walk's perspective view, and once what it
# sees is held the fine frame is octopoint-render --url --eye's of the same eye, pixel for pixel;
# so is the frame after Tab to orbit mode and back, and after w held (a new eye). Esc quits with
# exit 0. Frames and views are read with the viewer's p key (xdotool). Exits 77 (skipped) without
# Xvfb or xdotool (scripts/viewer-smoke and scripts/test install them).
# usage: viewer_url_walk_smoke.sh PREPARE SERVE VIEW RENDER SCAN WORKDIR
set -euo pipefail
prepare=$1 serve=$2 viewer=$3 render=$4 scan=$5 work=$6
source "$(dirname "$0")/net_script_lib.sh"
source "$(dirname "$0")/../viewer_script_lib.sh"
require_viewer_tools
rm -rf "$work" && mkdir -p "$work/models" "$work/run"
"$prepare" "$scan" -o "$work/models" --name sphere --depths 3,4,5 --chunked >/dev/null
# An eye inside the cube, looking at the sphere: the one --perspective puts at zoom 2.
eye_line=$("$render" --file "$work/models/sphere.oct" --perspective --yaw 20 --pitch 10 --zoom 2 \
  --size 320x240 -o "$work/perspective.png")
eye=$(sed -n 's/.* eye \([^ ]*\) looking \([^ ]*\) .*/\1/p' <<<"$eye_line")
look=$(sed -n 's/.* eye \([^ ]*\) looking \([^ ]*\) .*/\2/p' <<<"$eye_line")
[ -n "$eye" ] && [ -n "$look" ] || fail "no eye in: $eye_line"
start_octopoint_serve "$serve" "$work/models" --rate 2000 --latency 100
url="http://127.0.0.1:$SERVE_PORT/sphere.oct"
start_xvfb_for_served_viewer
(cd "$work/run" && exec "$viewer" --url "$url" --eye "$eye" --look "$look" --fov 60 --size 320x240 \
  --walk-speed 0.5) >"$work/viewer.log" 2>&1 &
viewer_pid=$!
wait_for_viewer_window

# How many pixels the saved frame differs in from octopoint-render --url's of the options printed.
differs_from_render() {
  local line=$1 name
  name=$(file_of "$line")
  # shellcheck disable=SC2046 # the options are words
  "$render" --url "$url" $(options_of "$line") -o "$work/render_$name" >/dev/null ||
    fail "octopoint-render --url $url $(options_of "$line") failed"
  compare -metric AE "$work/run/$name" "$work/render_$name" null: 2>&1 || true
}

# 1. The start view: the stream follows it; within 40 s its fine frame is --url --eye's.
first=$(fine_view)
case "$first" in *" --eye "*) ;; *) fail "the viewer did not start in walk mode: $first" ;; esac
early=$(differs_from_render "$first")
final=$early n=0
while [ "$final" != 0 ] && [ "$n" -lt 40 ]; do
  sleep 1
  n=$((n + 1))
  line=$(fine_view)
  final=$(differs_from_render "$line")
done
[ "$final" = 0 ] || fail "after 40 s the walk frame differs from octopoint-render --url's in $final pixels"
[ "$early" != 0 ] || fail "the first walk frame is already the final picture: the stream was not seen"

# 2. Tab to orbit mode and back: walk mode again, at the orbit view's eye.
{ read -r orbit; read -r entered; } < <(orbit_and_back) || true
[ -n "$entered" ] || fail "Tab to orbit mode and back saved no walk frame"
[ "$(differs_from_render "$entered")" = 0 ] || fail "after Tab twice, $entered differs from octopoint-render's"

# 3. w held: a new eye, still the render's frame.
xdotool keydown w sleep 0.3 keyup w
sleep 0.3
walked=$(fine_view)
[ "$(options_of "$walked")" != "$(options_of "$entered")" ] || fail "w did not move the eye: $walked"
[ "$(differs_from_render "$walked")" = 0 ] || fail "after w, $walked differs from octopoint-render's"

# 4. Esc quits.
xdotool key Escape
for _ in $(seq 100); do kill -0 "$viewer_pid" 2>/dev/null || break; sleep 0.05; done
wait "$viewer_pid" || fail "the viewer exited with an error: $(cat "$work/viewer.log")"
viewer_pid=""
echo "ok: the first walk frame differs from octopoint-render --url --eye's in $early pixels, after $n s" \
  "in none; after Tab twice and after w, none either"
