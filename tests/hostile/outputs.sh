# shellcheck shell=bash disable=SC2154,SC2034,SC2059  # lib.sh sets the variables; printf formats are built on purpose
# The hostile sweep's output classes (sourced by lab/scripts/hostile-sweep after tests/hostile/lib.sh):
# outputs that are not regular files, for every tool that writes (9), and signals
# while the preparer puts its files in place (10).

sweepClass 9 "outputs that are not regular files, every tool"
sweepClass 10 "a signal while the preparer writes: old set or new set, no staging"

# Special files made inside the case's output folder: never the system's own /dev nodes (as root
# a failure would destroy them). Each kind: how to make it at $1, and the message expected.
special_kinds=(fifo directory loop dangling link_to_fifo)
[ "$can_mknod" -eq 1 ] && special_kinds+=(char_device)
[ -n "$socket" ] && special_kinds+=(socket)
makeSpecial() {  # makeSpecial KIND PATH
  case $1 in
    fifo) mkfifo "$2" ;;
    directory) mkdir -p "$2" ;;
    loop) ln -s "$(basename "$2").b" "$2" && ln -s "$(basename "$2")" "$2.b" ;;
    dangling) ln -s nowhere "$2" ;;
    link_to_fifo) mkfifo "$2.fifo" && ln -s "$(basename "$2").fifo" "$2" ;;
    char_device) mknod "$2" c 1 3 ;;  # a null device of our own
    socket) ln "$socket" "$2" ;;
  esac
}
specialMessage() {
  case $1 in
    fifo | link_to_fifo) echo "is a FIFO" ;; directory) echo "is a directory" ;; loop) echo "symlink loop" ;;
    dangling) echo "dangling symbolic link" ;; char_device) echo "is a character device" ;;
    socket) echo "is a socket" ;;
  esac
}
# The same as an output directory: "exists and is not a directory: it is ..." for what exists.
directoryMessage() {
  case $1 in
    fifo | link_to_fifo) echo "it is a FIFO" ;; loop) echo "symlink loop" ;;
    dangling) echo "dangling symbolic link" ;; char_device) echo "it is a character device" ;;
    socket) echo "it is a socket" ;;
  esac
}

# --- 9: every output name of every tool taken by something that is not a regular file -----------
for kind in "${special_kinds[@]}"; do
  [ "$quick" -eq 1 ] && [ "$kind" != fifo ] && continue
  q=""
  [ "$kind" = fifo ] && q="q:"
  expected=$(specialMessage "$kind")
  out "render_$kind"
  makeSpecial "$kind" "$OUT/x.png"
  refuse 9 "${q}render_o_$kind" "$expected" "$RENDER" -o "$OUT/x.png"
  out "render_sheet_$kind"
  makeSpecial "$kind" "$OUT/x.png"
  refuse 9 "render_sheet_o_$kind" "$expected" "$RENDER" --sheet 2 -o "$OUT/x.png"
  for file in m.oct m.h m.cpp m_depth6.cpp; do
    out "prepare_$kind"
    makeSpecial "$kind" "$OUT/$file"
    refuse 9 "${q}prepare_${file}_$kind" "$expected" "$PREPARE" "$IN/good.pcd" -o "$OUT" --name m --depths 5,6
    q=""
  done
  for file in tradeoff.csv tradeoff.png tradeoff_reference.png; do
    out "tradeoff_$kind"
    makeSpecial "$kind" "$OUT/$file"
    refuse 9 "tradeoff_${file}_$kind" "$expected" "$TRADEOFF" "$IN/good.pcd" --depths 6 -o "$OUT"
  done
  for file in sweep.csv sweep.md; do
    out "sweep_$kind"
    makeSpecial "$kind" "$OUT/$file"
    refuse 9 "sweep_${file}_$kind" "$expected" "$TRADEOFF" "$IN/good.pcd" --sweep-views --sizes 64x48 \
      --zooms 1 --rounds 1 -o "$OUT"
  done
  [ "$kind" = directory ] && continue  # a directory is what an output directory should be
  expected=$(directoryMessage "$kind")
  out "prepare_dir_$kind"
  makeSpecial "$kind" "$OUT/o"
  refuse 9 "prepare_outdir_$kind" "$expected" "$PREPARE" "$IN/good.pcd" -o "$OUT/o" --name m --depths 5,6
  out "tradeoff_dir_$kind"
  makeSpecial "$kind" "$OUT/o"
  refuse 9 "tradeoff_outdir_$kind" "$expected" "$TRADEOFF" "$IN/good.pcd" --depths 6 -o "$OUT/o"
  out "pictures_dir_$kind"
  makeSpecial "$kind" "$OUT/pictures"
  refuse 9 "sweep_pictures_$kind" "$expected" "$TRADEOFF" "$IN/good.pcd" --sweep-views --pictures --sizes 64x48 \
    --zooms 1 --rounds 1 -o "$OUT"
done
out prepare_outdir_file
echo "a file" >"$OUT/o"
refuse 9 q:prepare_outdir_file "exists and is not a directory: it is a regular file" "$PREPARE" "$IN/good.pcd" \
  -o "$OUT/o" --name m
out render_missing_dir
refuse 9 render_missing_directory "does not exist" "$RENDER" -o "$OUT/no/such/dir/x.png"

# --- 10: SIGINT, SIGTERM, SIGHUP, SIGQUIT at spread moments of a preparer run over an earlier one --
# Passes when the process ends (by the signal, or done) within the limits and the output folder
# holds exactly the earlier set or exactly the new set, with no staging folder or temporary.
spherePcd 60000 >"$IN/big_sphere.pcd"
# The earlier set (another scan) and the new one, each made by the very command the cases run
# (the sources name it); the new run's duration spreads the signals over it.
interrupted=$W/work/out/interrupt
prepareInterrupted() { "$PREPARE" "$1" -o "$interrupted" --name m --depths 6,7,8 >/dev/null; }
setOf() { (cd "$1" && md5sum -- * | sort); }
rm -rf "$interrupted"
prepareInterrupted "$IN/good.pcd"
old_set=$(setOf "$interrupted")
mv "$interrupted" "$META/old_set"
run_start=$(date +%s%N)
prepareInterrupted "$IN/big_sphere.pcd"
run_ms=$((($(date +%s%N) - run_start) / 1000000))
new_set=$(setOf "$interrupted")
interruptCase() {  # interruptCase NAME SIGNAL DELAY_SECONDS
  selected "$1" || return 0
  OUT=$interrupted
  rm -rf "$OUT"
  cp -r "$META/old_set" "$OUT"
  local start=$SECONDS pid
  (ulimit -c 0 && exec /usr/bin/time -f '%e %U %S %M' -o "$META/time" "$PREPARE" "$IN/big_sphere.pcd" -o "$OUT" \
    --name m --depths 6,7,8 >/dev/null 2>"$META/stderr") &  # no core file from SIGQUIT
  pid=$!
  sleep "$3"
  pkill -"$2" -P "$pid" 2>/dev/null  # the preparer, child of time
  wait "$pid"
  status=$?
  local u s
  read -r wall u s kb < <(tail -n 1 "$META/time")
  cpu=$(awk -v u="$u" -v s="$s" 'BEGIN { printf "%.2f", u + s }')
  message=$(head -c 2000 "$META/stderr" | tr '\n' '|')
  problems=""
  local now
  now=$(cd "$OUT" && md5sum -- * 2>/dev/null | sort)
  local which="a mix"
  [ "$now" = "$old_set" ] && which="the old set"
  [ "$now" = "$new_set" ] && which="the new set"
  message="status $status, $which|$message"
  [ "$now" = "$old_set" ] || [ "$now" = "$new_set" ] || problems+=" a mix of old and new files: $(find "$OUT" -mindepth 1 -printf '%P ')"
  [ -z "$(find "$OUT" -name '.octopoint-staging-*' -o -name '.*.tmp-*')" ] || problems+=" staging or temporary left"
  awk -v a="$cpu" -v b=10 'BEGIN { exit !(a > b) }' && problems+=" ${cpu} s CPU"
  [ $((SECONDS - start)) -le "$kHangSeconds" ] || problems+=" took $((SECONDS - start)) s"
  recordCase 10 "${1#q:}_$2_at_$3s" "$problems"
  rm -rf "$OUT"
}
# Eight moments across the run, the last just before it ends (where the files are put in place).
for eighth in 1 2 3 4 5 6 7 8; do
  delay=$(awk -v ms="$run_ms" -v k="$eighth" 'BEGIN { printf "%.3f", ms * (k - 0.25) / 8 / 1000 }')
  q=""
  [ "$eighth" = 8 ] && q="q:"
  for signal in INT TERM HUP QUIT; do interruptCase "${q}interrupt" "$signal" "$delay"; q=""; done
done
