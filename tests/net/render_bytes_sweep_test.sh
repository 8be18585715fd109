#!/usr/bin/env bash
# octopoint-render --url --bytes N on a small chunked model (two stored depths, a few chunks),
# for N from 0 to past the file's size: every cut, including those that end inside the first
# requests, must draw what its bytes give (exit 0) or say in one line that the head did not fit
# (exit 1), and at once: each run has 10 s, where a sound one takes a fraction of a second.
set -uo pipefail
. "$(dirname "$0")/net_script_lib.sh"
prepare=$1 serve=$2 render=$3 scan=$4 work=$5
rm -rf "$work" && mkdir -p "$work"
serve_small_chunked_model "$prepare" "$serve" "$scan" "$work"
trap 'stop_pid "$SERVE_PID"' EXIT
url="http://127.0.0.1:$SERVE_PORT/small.oct"
size=$(stat -c %s "$work/models/small.oct")
[ "$size" -lt 200000 ] || fail "the model is $size bytes, not a small one"
# Every 997 bytes and a few around the size; smaller steps near the first requests, where the
# budget ends inside them. The stream itself is cut every 13 bytes in-process (ByteBudget in
# net_tests); here each cut is a whole octopoint-render run.
cuts=$( (seq 1 997 $((size + 500)); seq 3000 211 9000; echo $((size - 1)) "$size" $((size + 1))) |
  sort -nu)
drawn=0
for n in $cuts; do
  timeout 10 "$render" --url "$url" --bytes "$n" -o "$work/out.png" >"$work/out" 2>"$work/err"
  rc=$?
  [ "$rc" -ne 124 ] || fail "--bytes $n did not return within 10 s"
  lines=$(wc -l <"$work/err")
  case $rc in
    0) [ "$lines" -eq 0 ] || fail "--bytes $n: exit 0 with stderr: $(cat "$work/err")"
       drawn=$((drawn + 1)) ;;
    1) [ "$lines" -eq 1 ] || fail "--bytes $n: exit 1 with $lines lines on stderr"
       grep -q "the head did not arrive" "$work/err" || fail "--bytes $n: $(cat "$work/err")" ;;
    *) fail "--bytes $n: exit $rc: $(cat "$work/err")" ;;
  esac
done
[ "$drawn" -gt 5 ] || fail "only $drawn cuts drew a picture"
echo "ok: $(echo "$cuts" | wc -w) cuts of a $size-byte model, $drawn drew at once, none hung"
