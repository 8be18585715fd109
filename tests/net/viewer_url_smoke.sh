#!/usr/bin/env bash
# octopoint-view --url in a real X server (Xvfb), against octopoint-serve shaped to a slow link: the
# window shows a coarse picture early, and once the view's chunks are in, the fine frame is the
# file's own picture (pixel for pixel what octopoint-render --file draws); after m, what
# octopoint-render --file --splats smooth draws. Frames are read with the
# viewer's `s` key (xdotool). Where strace can trace it, the viewer runs under strace: no thread but
# the main one may write to the X server, and nothing may go on SDL's second X connection (a
# wake-up sent there can reach the server after the window is gone: BadWindow, exit 1 at SDL_Quit;
# tools/view_window.h, kWakePollMs); it quits while the file still streams in. Exits 77
# (skipped) without Xvfb or xdotool (scripts/viewer-smoke and scripts/test install them).
# usage: viewer_url_smoke.sh PREPARE SERVE VIEW RENDER SCAN WORKDIR
set -euo pipefail
prepare=$1 serve=$2 viewer=$3 render=$4 scan=$5 work=$6
source "$(dirname "$0")/net_script_lib.sh"
source "$(dirname "$0")/../viewer_script_lib.sh"
require_viewer_tools
rm -rf "$work" && mkdir -p "$work/models" "$work/run"
# Depths the test sphere samples densely (depth auto draws no finer one: depth 6 has 2.7x the
# voxels of depth 5).
"$prepare" "$scan" -o "$work/models" --name sphere --depths 3,4,5 --chunked >/dev/null
start_octopoint_serve "$serve" "$work/models" --rate 2000 --latency 100
start_xvfb_for_served_viewer
tracer=()
if command -v strace >/dev/null && strace -f -o /dev/null true 2>/dev/null; then
  tracer=(strace -f -o "$work/strace.log" -e trace=connect,close,write,writev,sendmsg)
fi
(cd "$work/run" && exec "${tracer[@]}" "$viewer" --url "http://127.0.0.1:$SERVE_PORT/sphere.oct" --size 320x240) >"$work/viewer.log" 2>&1 &
viewer_pid=$!
wait_for_viewer_window
save() {  # presses s and waits for the viewer to say it saved frame $1
  xdotool key s
  for _ in $(seq 100); do
    grep -q "^saved octopoint-view-$1.png " "$work/viewer.log" && return 0
    sleep 0.02
  done
  fail "s saved nothing: $(cat "$work/viewer.log")"
}
"$render" --file "$work/models/sphere.oct" --size 320x240 -o "$work/file.png" >/dev/null
differs() { compare -metric AE "$work/run/octopoint-view-$1.png" "$work/file.png" null: 2>&1 || true; }
# The file is about 7 kB at 2 kB/s: a frame soon after the head, then one a second until the
# frame is the file's (within 40 s).
for _ in $(seq 50); do save 1; [ -s "$work/run/octopoint-view-1.png" ] && break; done
early=$(differs 1)
final=$early n=1
while [ "$final" != 0 ] && [ "$n" -lt 41 ]; do
  sleep 1
  n=$((n + 1))
  save "$n"
  final=$(differs "$n")
done
[ "$final" = 0 ] || fail "after the stream, the viewer's frame differs from the file's in $final pixels"
# m: smooth splats, the file's picture as octopoint-render --splats smooth draws it (not the box's).
"$render" --file "$work/models/sphere.oct" --size 320x240 --splats smooth -o "$work/smooth.png" >/dev/null
[ "$(compare -metric AE "$work/smooth.png" "$work/file.png" null: 2>&1 || true)" != 0 ] ||
  fail "--splats smooth draws the test sphere as box does: m would not be seen"
xdotool key m
sleep 0.3
n=$((n + 1))
save "$n"
grep -q "^saved octopoint-view-$n.png (.): .* --splats smooth" "$work/viewer.log" ||
  fail "after m, s saved no smooth frame: $(grep "^saved octopoint-view-$n.png" "$work/viewer.log")"
smooth=$(compare -metric AE "$work/run/octopoint-view-$n.png" "$work/smooth.png" null: 2>&1 || true)
[ "$smooth" = 0 ] || fail "after m, the frame differs from --splats smooth's in $smooth pixels"
xdotool key q  # while the rest of the file is prefetched: the stream still wakes the window
for _ in $(seq 100); do kill -0 "$viewer_pid" 2>/dev/null || break; sleep 0.05; done
wait "$viewer_pid" || fail "the viewer exited with an error: $(cat "$work/viewer.log")"
viewer_pid=""
[ "$early" != 0 ] || fail "the early frame is already the final picture: the stream was not seen"
# What the viewer wrote to the X server (its sockets: connected to X11-unix until closed): writes
# by a thread other than the main one (the first line's: it loads the libraries before any thread
# starts), and SendEvent requests (opcode 25, "\31" in strace's octal: SDL's wake-ups), by any.
x_writes=""
if [ ${#tracer[@]} -gt 0 ]; then
  x_writes=$(awk 'NR == 1 { main = $1 }
    { call = $2; sub(/\(.*/, "", call); fd = $2; sub(/^[a-z]*\(/, "", fd); sub(/[,)].*/, "", fd) }
    call == "connect" && /X11-unix/ { x[fd] = 1 }
    call == "close" { delete x[fd] }
    (call == "write" || call == "writev" || call == "sendmsg") && (fd in x) {
      if ($1 != main) off_main++
      if (/(iov_base=|, )"\\31/) send_events++
    }
    END { print off_main + 0, send_events + 0 }' "$work/strace.log")
  [ "$x_writes" = "0 0" ] ||
    fail "the viewer wrote to the X server off its main thread, or sent it events (SDL's" \
      "wake-ups), $x_writes times: a wake-up can reach the server after the window is gone"
fi
echo "ok: the early frame differs from the file's picture in $early pixels, frame $n (after $((n - 1)) s) in none, and after m none from --splats smooth${x_writes:+; no wake-up sent to the X server}"
