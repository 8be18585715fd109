#!/usr/bin/env bash
# octopoint-view's walk mode in a real X server (Xvfb), driven by xdotool's real key and mouse
# events (docs/perspective.md, "The viewer's walk mode"):
# 1. started with --eye/--look/--fov, the fine frame is octopoint-render --eye's of the same eye,
#    pixel for pixel;
# 2. w held for 1 s walks forward at --walk-speed: the eye moves level (y unchanged) along the
#    look's yaw by speed x 1 s .. speed x the xdotool run's wall time, +-50 ms of speed; the frames
#    are L's while it is held, and the fine frame after is octopoint-render --eye's again;
# 3. e held rises (y grows: the default model's scan is y-up), x and z unchanged;
# 4. a drag of 48 pixels to the right with the left button turns the eye right by 48 x fov /
#    frame height degrees;
# 5. Tab switches to orbit mode (s saves an orbit view) and back: the eye enters where
#    octopoint-render --perspective of that orbit view puts it, and draws its frame;
# 1b. Between 1 and 2, c steps through the styles (shaded, lines, toon, outlined, colour): each walk
# frame is octopoint-render --eye --style's of the same eye, pixel for pixel.
# 6. Esc quits.
# Frames and views are read with the viewer's p key ("saved NAME (L|H): --size WxH --eye ...").
# Exits 77 (skipped) without Xvfb or xdotool (scripts/viewer-smoke installs them).
# usage: view_walk_smoke.sh VIEW RENDER WORKDIR
set -euo pipefail
viewer=$(realpath "$1") render=$(realpath "$2") work=$(realpath -m "$3")
source "$(dirname "$0")/viewer_script_lib.sh"
require_viewer_tools
rm -rf "$work" && mkdir -p "$work/run"
xvfb_pid="" viewer_pid=""
cleanup() {
  if [ -n "$viewer_pid" ]; then kill "$viewer_pid" 2>/dev/null || true; fi
  if [ -n "$xvfb_pid" ]; then kill "$xvfb_pid" 2>/dev/null || true; fi
}
trap cleanup EXIT
fail() {
  echo "view_walk_smoke: $*" >&2
  [ -s "$work/viewer.log" ] && sed 's/^/  viewer: /' "$work/viewer.log" >&2
  exit 1
}

start_xvfb

speed=0.1  # scan units (metres) per second
fov=70
size=320x240
(cd "$work/run" && exec "$viewer" --eye 0.05,0.1,-0.45 --look -5,-20 --fov $fov --size $size \
  --walk-speed $speed) >"$work/viewer.log" 2>&1 &
viewer_pid=$!
wait_for_viewer_window

coordinate() { cut -d, -f"$1" <<<"$(field eye "$2")"; }
# The saved frame against octopoint-render's of the options the viewer printed: identical.
same_as_render() {
  local line=$1 name
  name=$(file_of "$line")
  # shellcheck disable=SC2046 # the options are words
  "$render" $(options_of "$line") -o "$work/render_$name" >/dev/null ||
    fail "octopoint-render $(options_of "$line") failed"
  differ=$(compare -metric AE "$work/run/$name" "$work/render_$name" null: 2>&1 || true)
  [ "$differ" = 0 ] || fail "$name differs from octopoint-render $(options_of "$line") in $differ pixels"
}
within() { awk -v v="$1" -v l="$2" -v h="$3" 'BEGIN { exit !(v >= l && v <= h) }'; }

# 1. The start view.
start=$(fine_view)
[ "$(field size "$start")" = $size ] || fail "the first frame is not $size: $start"
same_as_render "$start"

# 1b. The styles in walk mode.
for style in shaded lines toon outlined; do
  xdotool key c
  styled=$(fine_view)
  [ "$(field style "$styled")" = $style ] || fail "c did not make the style $style: $styled"
  same_as_render "$styled"
done
xdotool key c
[ -z "$(field style "$(fine_view)")" ] || fail "c after outlined did not go back to colour"

# 2. w held for 1 s walks forward, level.
before_ns=$(date +%s%N)
held_number=$(($(saves) + 1))
xdotool keydown w sleep 0.5 key p sleep 0.5 keyup w
after_ns=$(date +%s%N)
held=$(grep "^saved octopoint-view-$held_number.png " "$work/viewer.log" || true)
case "$held" in *" (L): "*) ;; *) fail "while w was held, the frame was not L's: $held" ;; esac
walked=$(fine_view)
same_as_render "$walked"
[ "$(coordinate 2 "$walked")" = "$(coordinate 2 "$start")" ] || fail "w moved the eye up or down: $walked"
distance=$(awk -v x0="$(coordinate 1 "$start")" -v z0="$(coordinate 3 "$start")" \
  -v x1="$(coordinate 1 "$walked")" -v z1="$(coordinate 3 "$walked")" \
  'BEGIN { printf "%.5f", sqrt((x1 - x0)^2 + (z1 - z0)^2) }')
read -r low high < <(awk -v s=$speed -v ns=$((after_ns - before_ns)) \
  'BEGIN { printf "%.5f %.5f\n", s * 0.95, s * ns / 1e9 + s * 0.05 }')
within "$distance" "$low" "$high" || fail "w held for 1 s walked $distance, not $low..$high"
# Along the look's yaw (-5 degrees: the scan is y-up, so forward is -z, and left of it is -x).
awk -v x0="$(coordinate 1 "$start")" -v z0="$(coordinate 3 "$start")" \
  -v x1="$(coordinate 1 "$walked")" -v z1="$(coordinate 3 "$walked")" \
  'BEGIN { a = atan2(x1 - x0, -(z1 - z0)) * 180 / 3.14159265358979; exit !(a > -5.1 && a < -4.9) }' ||
  fail "w did not walk along the yaw of -5 degrees: from $start to $walked"

# 3. e held rises.
xdotool keydown e sleep 0.5 keyup e
risen=$(fine_view)
[ "$(coordinate 1 "$risen")" = "$(coordinate 1 "$walked")" ] &&
  [ "$(coordinate 3 "$risen")" = "$(coordinate 3 "$walked")" ] || fail "e moved the eye sideways: $risen"
within "$(awk -v a="$(coordinate 2 "$walked")" -v b="$(coordinate 2 "$risen")" 'BEGIN { print b - a }')" \
  $(awk -v s=$speed 'BEGIN { print s * 0.45, s * 0.8 }') || fail "e held for 0.5 s: from $walked to $risen"

# 4. A drag to the right turns the eye right.
xdotool mousemove --window "$window" 100 120 mousedown 1 mousemove_relative --sync 48 0 mouseup 1
sleep 0.3
turned=$(fine_view)
same_as_render "$turned"
yaw0=$(cut -d, -f1 <<<"$(field look "$risen")") yaw1=$(cut -d, -f1 <<<"$(field look "$turned")")
within "$(awk -v a="$yaw0" -v b="$yaw1" 'BEGIN { print b - a }')" \
  $(awk -v f=$fov 'BEGIN { t = 48 * f / 240; print t - 0.01, t + 0.01 }') ||
  fail "a drag of 48 pixels turned the eye from $yaw0 to $yaw1 degrees, not by 48 x $fov / 240"

# 5. Tab: orbit mode, then walk mode again from the orbit view's eye.
{ read -r orbit; read -r entered; } < <(orbit_and_back) || true
[ -n "$entered" ] || fail "Tab to orbit mode and back saved no walk frame"
same_as_render "$entered"
perspective=$("$render" --size $size --yaw "$(field yaw "$orbit")" --pitch "$(field pitch "$orbit")" \
  --zoom "$(field zoom "$orbit")" --perspective --fov "$(field fov "$entered")" -o "$work/orbit.png")
compare -metric AE "$work/orbit.png" "$work/run/$(file_of "$entered")" null: 2>/dev/null ||
  fail "walk mode entered from the orbit view does not show --perspective's frame: $entered; $perspective"

# 6. Esc quits.
xdotool key Escape
for _ in $(seq 100); do kill -0 "$viewer_pid" 2>/dev/null || break; sleep 0.05; done
kill -0 "$viewer_pid" 2>/dev/null && fail "the viewer did not quit on Esc"
wait "$viewer_pid" || fail "the viewer exited with an error"
viewer_pid=""
echo "view_walk_smoke: ok (w held 1 s walked $distance of $low..$high; drag turned $yaw0 -> $yaw1;" \
  "five fine frames identical to octopoint-render's)"
