# shellcheck shell=bash disable=SC2034  # the variables set here are read by the class files
# The hostile sweep's machinery (sourced by lab/scripts/hostile-sweep): runs one case under measure
# and judges it. A refusal passes when the tool
#   - exits with status 1 (not 0, not a signal, not the hang timeout),
#   - prints exactly one line on stderr, at most kMaxLine characters, that is not "out of memory"
#     (a cost left unbounded that ran into the sweep's safety cap) nor an internal error,
#   - names what the case expects (a piece of its message),
#   - uses at most kCpuLimit seconds of CPU and kMemoryLimitKB of memory, and at most
#     HOSTILE_WALL_LIMIT seconds of wall clock (default 2; raise it on a loaded machine: CPU time
#     is the load-independent measure of the cost),
#   - leaves the work folder exactly as it was: no new file, no temporary or staging folder, and
#     every FIFO, device or directory still what it was.

readonly kCpuLimit=2 kMemoryLimitKB=204800 kMaxLine=400
readonly kHangSeconds=10          # a case still running then is a hang
readonly kSafetyCapBytes=$((3 << 30))  # address space: a runaway must not take the machine down
wall_limit=${HOSTILE_WALL_LIMIT:-2}

declare -A class_title class_cases class_passed class_wall class_cpu class_kb
class_order=()
failures=()

# Defines a class: sweepClass ID "title".
sweepClass() {
  class_order+=("$1")
  class_title[$1]=$2
  class_cases[$1]=0 class_passed[$1]=0 class_wall[$1]=0 class_cpu[$1]=0 class_kb[$1]=0
}

sweepInit() {
  local build=$1
  quick=$2 verbose=$3
  RENDER=$build/tools/octopoint-render PREPARE=$build/tools/octopoint-prepare
  TRADEOFF=$build/lab/octopoint-tradeoff VIEW=$build/tools/octopoint-view
  local tool
  for tool in "$RENDER" "$PREPARE" "$TRADEOFF"; do
    [ -x "$tool" ] || { echo "hostile-sweep: $tool is not built (cmake --build --preset release)" >&2; return 1; }
  done
  [ -x "$VIEW" ] || VIEW=""
  # GNU time measures CPU and peak memory.
  "$(dirname "${BASH_SOURCE[0]}")/../../scripts/install-packages" time || return 1
  W=$(mktemp -d "${TMPDIR:-/tmp}/octopoint-hostile.XXXXXX") || return 1
  trap 'rm -rf "$W"' EXIT
  META=$W/meta IN=$W/work/in
  mkdir -p "$META" "$IN" "$W/work/out"
  can_mknod=0  # device nodes of our own (root, outside a container that forbids them)
  mknod "$META/null" c 1 3 2>/dev/null && can_mknod=1
  socket=""  # one UNIX socket, hard-linked wherever a case needs one
  if command -v python3 >/dev/null &&
    python3 -c 'import socket, sys; socket.socket(socket.AF_UNIX).bind(sys.argv[1])' "$META/socket"; then
    socket=$META/socket
  fi
  makeGoodInputs
}

# A unit sphere of N points as an ascii PCD (stdout).
spherePcd() {
  local n=$1
  printf 'VERSION 0.7\nFIELDS x y z\nSIZE 4 4 4\nTYPE F F F\nCOUNT 1 1 1\nWIDTH %d\nHEIGHT 1\n' "$n"
  printf 'VIEWPOINT 0 0 0 1 0 0 0\nPOINTS %d\nDATA ascii\n' "$n"
  awk -v n="$n" 'BEGIN { srand(1); for (i = 0; i < n; i++) { z = 2 * rand() - 1; t = 6.2831853 * rand();
    r = sqrt(1 - z * z); printf "%.5f %.5f %.5f\n", r * cos(t), r * sin(t), z } }'
}

makeGoodInputs() {
  spherePcd 3000 >"$IN/good.pcd"
  "$PREPARE" "$IN/good.pcd" -o "$META/model" --name ball --depths 5,6 >/dev/null ||
    { echo "hostile-sweep: cannot prepare the good model" >&2; return 1; }
  cp "$META/model/ball.oct" "$IN/good.oct"
  printf '{"yaw": [-30, 30], "pitch": [-20, 20], "depths": [5, 6]}\n' >"$IN/good.json"
}

# A fresh, empty output folder for the next case: sets OUT.
out() {
  OUT=$W/work/out/$1
  rm -rf "$OUT"
  mkdir -p "$OUT"
}

# Every entry under the work folder with its type, mode and size (FIFOs stay FIFOs).
snapshot() { find "$W/work" -printf '%y %m %s %P\n' | sort; }

# Runs a command measured; sets status, wall, cpu, kb, lines, message.
measure() {
  /usr/bin/time -f '%e %U %S %M' -o "$META/time" \
    timeout -k 2 "$kHangSeconds" prlimit --as="$kSafetyCapBytes" -- "$@" \
    >"$META/stdout" 2>"$META/stderr" </dev/null
  status=$?
  local u s
  read -r wall u s kb < <(tail -n 1 "$META/time")
  cpu=$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.2f", u + s }')
  lines=$(wc -l <"$META/stderr")
  message=$(head -c 2000 "$META/stderr" | tr '\n' '|')
}

# Records a case: recordCase CLASS NAME PROBLEMS (empty: passed).
recordCase() {
  local class=$1 name=$2 problems=$3
  class_cases[$class]=$((class_cases[$class] + 1))
  awk -v a="$wall" -v b="${class_wall[$class]}" 'BEGIN { exit !(a > b) }' && class_wall[$class]=$wall
  awk -v a="$cpu" -v b="${class_cpu[$class]}" 'BEGIN { exit !(a > b) }' && class_cpu[$class]=$cpu
  [ "$kb" -gt "${class_kb[$class]}" ] && class_kb[$class]=$kb
  if [ -z "$problems" ]; then
    class_passed[$class]=$((class_passed[$class] + 1))
    [ "$verbose" -eq 1 ] && printf 'ok   %-3s %-28s %ss %sMB %s\n' "$class" "$name" "$cpu" $((kb / 1024)) "$message"
  else
    failures+=("$class $name:$problems; stderr: $message")
    printf 'FAIL %-3s %-28s%s; stderr: %s\n' "$class" "$name" "$problems" "$message"
  fi
  return 0
}

# In --quick mode only cases named "q:..." run.
selected() { [ "$quick" -eq 0 ] || [[ $1 == q:* ]]; }

# The time, memory and leftover checks every case shares; appends to `problems`.
judgeCost() {
  [ "$status" -eq 124 ] || [ "$status" -eq 137 ] && problems+=" hung (killed after ${kHangSeconds} s)"
  awk -v a="$cpu" -v b="$kCpuLimit" 'BEGIN { exit !(a > b) }' && problems+=" ${cpu} s CPU (> ${kCpuLimit})"
  awk -v a="$wall" -v b="$wall_limit" 'BEGIN { exit !(a > b) }' && problems+=" ${wall} s wall (> ${wall_limit})"
  [ "$kb" -gt "$kMemoryLimitKB" ] && problems+=" $((kb / 1024)) MB (> $((kMemoryLimitKB / 1024)))"
  if [ "$(snapshot)" != "$before" ]; then
    problems+=" left the work folder changed: $(diff <(echo "$before") <(snapshot) | grep '^[<>]' | head -3 | tr '\n' ' ')"
  fi
}

# refuse CLASS NAME EXPECTED COMMAND...: the command must refuse (see the top of this file) with a
# message containing EXPECTED.
refuse() {
  local class=$1 name=$2 expected=$3
  shift 3
  selected "$name" || return 0
  before=$(snapshot)
  measure "$@"
  problems=""
  [ "$status" -eq 1 ] || problems+=" exit status $status (want 1)"
  [ "$lines" -eq 1 ] || problems+=" $lines lines on stderr (want 1)"
  [ "$(awk '{ if (length($0) > m) m = length($0) } END { print m + 0 }' "$META/stderr")" -le "$kMaxLine" ] ||
    problems+=" a line longer than $kMaxLine characters"
  grep -qiE 'out of memory|internal error|terminate called|std::' "$META/stderr" && problems+=" not a refusal by the tool"
  grep -qF -- "$expected" "$META/stderr" || problems+=" message lacks '$expected'"
  judgeCost
  recordCase "$class" "${name#q:}" "$problems"
}

sweepReport() {
  local class total=0 passed=0
  printf '\n%-4s %-58s %6s %6s %8s %8s %7s\n' class "what" cases passed "max CPU" "max wall" "max MB"
  for class in $(printf "%s\n" "${class_order[@]}" | sort -n); do
    [ "${class_cases[$class]}" -eq 0 ] && continue
    printf '%-4s %-58s %6d %6d %7ss %7ss %7d\n' "$class" "${class_title[$class]}" "${class_cases[$class]}" \
      "${class_passed[$class]}" "${class_cpu[$class]}" "${class_wall[$class]}" $((class_kb[$class] / 1024))
    total=$((total + class_cases[$class])) passed=$((passed + class_passed[$class]))
  done
  printf '%-4s %-58s %6d %6d\n' all "(limits: ${kCpuLimit} s CPU, ${wall_limit} s wall, $((kMemoryLimitKB / 1024)) MB)" \
    "$total" "$passed"
  if [ ${#failures[@]} -gt 0 ]; then
    printf '\n%d case(s) failed:\n' ${#failures[@]}
    printf '  %s\n' "${failures[@]}"
    return 1
  fi
  return 0
}
