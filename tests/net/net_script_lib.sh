# Shared by the transport scripts (sourced, not run): servers on 127.0.0.1 and a free port,
# started in the background and stopped by their pid.

fail() { echo "FAIL: $*" >&2; exit 1; }

# A TCP port on 127.0.0.1 that nobody listens on right now.
free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1]); s.close()'
}

# Waits until something accepts connections on 127.0.0.1:$1 (at most 10 s).
wait_for_port() {
  for _ in $(seq 1 100); do
    (exec 3<>"/dev/tcp/127.0.0.1/$1") 2>/dev/null && return 0
    sleep 0.1
  done
  fail "nothing listens on 127.0.0.1:$1"
}

# Stops the process $1 (TERM, then KILL after 5 s) and waits for it.
stop_pid() {
  kill -TERM "$1" 2>/dev/null || return 0
  for _ in $(seq 1 50); do
    kill -0 "$1" 2>/dev/null || { wait "$1" 2>/dev/null; return 0; }
    sleep 0.1
  done
  kill -KILL "$1" 2>/dev/null
  wait "$1" 2>/dev/null
}

# Starts octopoint-serve ($1) on folder $2 with any further arguments; sets SERVE_PID and
# SERVE_PORT (from the line it prints once listening).
start_octopoint_serve() {
  local serve=$1 folder=$2 log
  shift 2
  log=$(mktemp)
  "$serve" "$folder" --port 0 "$@" >"$log" 2>&1 &
  SERVE_PID=$!
  for _ in $(seq 1 100); do
    SERVE_PORT=$(sed -n 's|.*http://127\.0\.0\.1:\([0-9]*\)/.*|\1|p' "$log")
    [ -n "$SERVE_PORT" ] && { rm -f "$log"; return 0; }
    kill -0 "$SERVE_PID" 2>/dev/null || fail "octopoint-serve exited: $(cat "$log")"
    sleep 0.1
  done
  fail "octopoint-serve did not say where it listens: $(cat "$log")"
}

# Prepares a small chunked model from scan $3 with octopoint-prepare ($1) into $4/models/small.oct
# (two stored depths, a few chunks) and serves that folder with octopoint-serve ($2): sets
# SERVE_PID and SERVE_PORT like start_octopoint_serve.
serve_small_chunked_model() {
  local prepare=$1 serve=$2 scan=$3 work=$4
  "$prepare" "$scan" -o "$work/models" --name small --depths 4,6 --chunked >/dev/null ||
    fail "could not prepare the model"
  start_octopoint_serve "$serve" "$work/models"
}
