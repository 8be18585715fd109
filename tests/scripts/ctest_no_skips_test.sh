#!/usr/bin/env bash
# scripts/ctest-no-skips on a small project of its own: a skipped test fails the run and is named,
# unless an --allow-skip pattern matches its whole name; a failed test still fails it; a clean run passes.
set -uo pipefail
script=$1 work=$2
fail() { echo "FAIL: $*" >&2; exit 1; }
rm -rf "$work" && mkdir -p "$work/project"
cat >"$work/project/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(skips NONE)
enable_testing()
add_test(NAME skips.one COMMAND sh -c "exit 77")
set_tests_properties(skips.one PROPERTIES SKIP_RETURN_CODE 77)
add_test(NAME passes.one COMMAND true)
add_test(NAME fails.one COMMAND false)
CMAKE
cmake -S "$work/project" -B "$work/build" >/dev/null || fail "could not configure"
run() { "$script" "$@" >"$work/out" 2>"$work/err"; }
run -- --test-dir "$work/build" -R 'skips|passes' && fail "a skipped test passed the run"
grep -q "ctest-no-skips: .*skips.one" "$work/err" || fail "the skipped test is not named"
run --allow-skip skips.one -- --test-dir "$work/build" -R 'skips|passes' ||
  fail "an allowed skip failed the run"
run --allow-skip 'skips\.[a-z]+' -- --test-dir "$work/build" -R 'skips|passes' ||
  fail "a pattern matching the skip failed the run"
run --allow-skip skips -- --test-dir "$work/build" -R 'skips|passes' &&
  fail "a pattern matching only part of the name allowed the skip"
run --allow-skip skips.one -- --test-dir "$work/build" && fail "a failed test passed the run"
run -- --test-dir "$work/build" -R passes || fail "a clean run failed"
echo "ok: skips fail unless allowed, failures fail, a clean run passes"
