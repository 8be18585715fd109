# Shared by the scripts that drive octopoint-view in Xvfb with xdotool (sourced, not run):
# tests/view_walk_smoke.sh, tests/net/viewer_url_smoke.sh, tests/net/viewer_url_walk_smoke.sh.
# They set `work` (its viewer.log is the viewer's output, run/ its directory) and define `fail`.

# Exits 77 (ctest: skipped) unless Xvfb, xdotool and ImageMagick's compare are installed.
require_viewer_tools() {
  for tool in Xvfb xdotool compare; do
    command -v "$tool" >/dev/null || { echo "$tool is not installed: skipped"; exit 77; }
  done
}

# Starts Xvfb on a free display: sets xvfb_pid and exports DISPLAY.
start_xvfb() {
  Xvfb -displayfd 3 -screen 0 800x600x24 -nolisten tcp 3>"$work/display" 2>"$work/xvfb.log" &
  xvfb_pid=$!
  # The number is written, with its newline, once Xvfb listens; a client may still be refused for
  # a moment on a loaded machine (a viewer once failed with "x11 not available"), so the display
  # counts as up once xdotool can talk to it.
  for _ in $(seq 100); do [ "$(wc -l <"$work/display")" -ge 1 ] && break; sleep 0.05; done
  [ "$(wc -l <"$work/display")" -ge 1 ] || fail "Xvfb did not start: $(cat "$work/xvfb.log")"
  DISPLAY=:$(head -1 "$work/display")
  export DISPLAY
  for _ in $(seq 100); do xdotool getdisplaygeometry >/dev/null 2>&1 && return 0; sleep 0.05; done
  fail "Xvfb on $DISPLAY did not answer: $(cat "$work/xvfb.log")"
}

# start_xvfb for a viewer of octopoint-serve $SERVE_PID (tests/net/net_script_lib.sh): on exit the
# viewer $viewer_pid (once set), Xvfb and the server are stopped.
start_xvfb_for_served_viewer() {
  xvfb_pid="" viewer_pid=""
  trap 'stop_served_viewer' EXIT
  start_xvfb
}
stop_served_viewer() {
  [ -n "$viewer_pid" ] && stop_pid "$viewer_pid"
  [ -n "$xvfb_pid" ] && stop_pid "$xvfb_pid"
  stop_pid "$SERVE_PID"
}

# Waits for the window of the viewer $viewer_pid (at most 10 s), sets `window` and focuses it.
wait_for_viewer_window() {
  window=""
  for _ in $(seq 200); do
    window=$(xdotool search --onlyvisible --name '^octopoint-view$' 2>/dev/null | head -1) &&
      [ -n "$window" ] && break
    kill -0 "$viewer_pid" 2>/dev/null || fail "the viewer exited: $(cat "$work/viewer.log")"
    sleep 0.05
  done
  [ -n "$window" ] || fail "no viewer window appeared"
  timeout 10 xdotool windowfocus --sync "$window" || fail "cannot focus the viewer's window"
}

saves() { grep -c '^saved ' "$work/viewer.log" || true; }
# Presses KEY (p in walk mode, s in orbit mode) and prints the line it makes the viewer print
# ("saved NAME (L|H): OPTIONS").
save_view() {
  local key=$1 number=$(($(saves) + 1))
  xdotool key "$key"
  for _ in $(seq 100); do
    line=$(grep "^saved octopoint-view-$number.png " "$work/viewer.log" || true)
    [ -n "$line" ] && { echo "$line"; return; }
    sleep 0.02
  done
  fail "$key printed nothing"
}
# Saves (KEY, default p) until the frame saved is H's.
fine_view() {
  for _ in $(seq 20); do
    line=$(save_view "${1:-p}")
    case "$line" in *" (H): "*) echo "$line"; return ;; esac
    sleep 0.1
  done
  fail "H drew no frame: $line"
}
options_of() { sed 's/^saved [^:]*: //' <<<"$1"; }
file_of() { sed 's/^saved \([^ ]*\) .*/\1/' <<<"$1"; }
field() { sed -n "s/.*--$1 \([^ ]*\).*/\1/p" <<<"$2"; }

# Tab to orbit mode (s saves its fine view) and Tab back to walk mode: prints the orbit view's line,
# then the fine walk frame's (p) on the next line.
orbit_and_back() {
  local orbit
  xdotool key Tab
  sleep 0.3
  orbit=$(fine_view s)
  case "$orbit" in *" --yaw "*) ;; *) fail "after Tab, s saved no orbit view: $orbit" ;; esac
  xdotool key Tab
  sleep 0.3
  echo "$orbit"
  fine_view
}
