#!/usr/bin/env bash
# octopoint-prepare --threads N where the system refuses some of the threads (std::thread throws):
# - under a process limit (RLIMIT_NPROC of 1: no thread at all but the first, and of 4; as root
#   the limit binds only another user, so the run is made as nobody) it must run on the threads
#   that start and write the same model as one thread does;
# - under an address-space limit, where the started threads' stacks and malloc arenas leave
#   little room, the same model, or one line and status 1 ("out of memory"); never an abort.
# usage: threads_under_limit.sh PREPARE SCAN WORKDIR
set -u
prepare=$1 scan=$2 work=$3
rm -rf "$work"
mkdir -p "$work"
chmod 777 "$work"  # written by nobody below
"$prepare" "$scan" -o "$work/one" --name m --threads 1 >/dev/null || { echo "FAIL: one thread"; exit 1; }
failures=0
failed() { echo "FAIL: $*, stderr: $(head -c 300 "$work/stderr")"; failures=$((failures + 1)); }

as_other_user=()
user_threads=0
if [ "$(id -u)" -eq 0 ]; then
  as_other_user=(setpriv --reuid=nobody --regid=nogroup --clear-groups)
  user_threads=$(ps -L -u nobody --no-headers | wc -l)
else  # this user's own processes and threads count against the limit
  user_threads=$(ps -L -u "$(id -u)" --no-headers | wc -l)
fi
for more in 1 4; do
  nproc_limit=$((user_threads + more))
  for threads in 2 8 100 1024; do
    out=$work/nproc_${more}_$threads
    case_name="--threads $threads under a process limit of $more more"
    "${as_other_user[@]}" prlimit --nproc="$nproc_limit" -- "$prepare" "$scan" -o "$out" --name m \
      --threads "$threads" >/dev/null 2>"$work/stderr"
    status=$?
    if [ "$status" -ne 0 ]; then
      failed "$case_name: status $status"
    elif ! cmp -s "$out/m.oct" "$work/one/m.oct"; then
      failed "$case_name: another model"
    else
      echo "ok: $case_name"
    fi
  done
done

for threads in 2 64 100 400 700 1024; do
  for limit_mib in 512 1024; do
    out=$work/as_${threads}_$limit_mib
    case_name="--threads $threads under $limit_mib MiB of address space"
    prlimit --as=$((limit_mib << 20)) -- "$prepare" "$scan" -o "$out" --name m --threads "$threads" \
      >/dev/null 2>"$work/stderr"
    status=$?
    if [ "$status" -eq 0 ]; then
      cmp -s "$out/m.oct" "$work/one/m.oct" && echo "ok: $case_name" || failed "$case_name: another model"
    elif [ "$status" -eq 1 ] && [ "$(wc -l <"$work/stderr")" -eq 1 ] && [ ! -e "$out" ]; then
      echo "ok: $case_name refused: $(cat "$work/stderr")"
    else
      failed "$case_name: status $status"
    fi
  done
done
rm -rf "$work"
[ "$failures" -eq 0 ]
