#!/usr/bin/env bash
# Generated sources compile for every name octopoint-prepare accepts, and nothing from outside
# reaches them unescaped (docs/robustness.md). Prepares a small scan, stored under a path full of
# characters that mean something to a compiler (a newline, a backslash at a line's end, quotes,
# "*/", "??/"), under names that are keywords elsewhere, library names or the generator's own
# helper names, in both emit styles, then compiles every generated source together with an app
# that includes the header beside the C library's headers (whose macros could clash).
# usage: compile_odd_inputs.sh PREPARE CXX SOURCE_DIR SCAN WORK
set -u
prepare=$1 cxx=$2 source_dir=$3 scan=$4 work=$5
rm -rf "$work"
mkdir -p "$work"
# Directories named "x *" and "??" put "*/" and "??/" into the path.
odd_scan="$work/dir"$'\n'"with a newline\\/x */ ??/scan \"quoted\" %41 é\\"$'\n'"int x = 1;.pcd"
mkdir -p "$(dirname "$odd_scan")"
cp "$scan" "$odd_scan" || exit 1

names=(final override import module main std octopoint models EmbeddedModel EmbeddedLevel kPalette
       kLevels palette levels uint8_t size_t a x1_2 Z9z x_depth3_nodes offsetof stdin)
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
prepare_as() {  # NAME EMIT OUTDIR
  "$prepare" "$odd_scan" -o "$3" --name "$1" --emit "$2" --depths 3,5 >"$work/log" 2>&1 ||
    { fail "octopoint-prepare refused --name $1: $(cat "$work/log")"; return 1; }
  # The odd path must not have opened a line of its own, nor spliced one into a comment.
  if grep -q '^int x = 1;' "$3"/*.h "$3"/*.cpp; then fail "$1: the path's newline reached the source"; fi
  if grep -q '\\$' "$3"/*.h "$3"/*.cpp; then fail "$1: a line ends in a backslash"; fi
}
# An app that includes the model's header beside the C library's (whose macros could clash).
write_app() {  # OUTDIR NAME...
  local out=$1
  shift
  {
    printf '#include <cerrno>\n#include <cmath>\n#include <cstddef>\n#include <cstdio>\n#include <cstdlib>\n'
    for name in "$@"; do printf '#include "%s.h"\n' "$name"; done
    printf 'int main() { return 0'
    for name in "$@"; do printf ' + (octopoint::models::%s.level_count == 2 ? 0 : 1)' "$name"; done
    printf '; }\n'
  } >"$out/app.cpp"
}
compile() {  # STD (-I DIR | FILE)...: -fsyntax-only, as strict as an app's build
  local std=$1
  shift
  "$cxx" -std="$std" -fsyntax-only -Wall -Wextra -Werror -I"$source_dir/include" "$@" >"$work/log" 2>&1
}
prepared=()
for name in "${names[@]}"; do
  out="$work/out_$name"
  prepare_as "$name" strings "$out" || continue
  prepared+=("$name")
  write_app "$out" "$name"
done
for std in c++20 gnu++20; do  # GNU mode predefines lower-case macros (linux, unix)
  # Each model's sources alone (their anonymous namespaces would clash in one unit), then one app
  # with every model's header after the C library's: a header parsed once instead of once a name.
  for name in "${prepared[@]}"; do
    out="$work/out_$name"
    sources=()
    for source in "$out"/*.cpp; do [ "$source" = "$out/app.cpp" ] || sources+=("$source"); done
    compile "$std" -I"$out" "${sources[@]}" ||
      fail "--name $name, -std=$std does not compile: $(head -5 "$work/log")"
  done
  mkdir -p "$work/all"
  write_app "$work/all" "${prepared[@]}"
  if ! compile "$std" "${prepared[@]/#/-I$work/out_}" "$work/all/app.cpp"; then
    together=$(head -5 "$work/log") failures_before=$failures
    for name in "${prepared[@]}"; do  # which header: each in an app of its own
      compile "$std" -I"$work/out_$name" "$work/out_$name/app.cpp" ||
        fail "--name $name, -std=$std: its header does not compile: $(head -5 "$work/log")"
    done
    [ "$failures" -gt "$failures_before" ] ||
      fail "-std=$std: the headers compile alone but not in one app: $together"
  fi
done
# Both emit styles, and two models whose names look like each other's arrays, linked into one app.
prepare_as x bytes "$work/two" && prepare_as x_depth3_nodes strings "$work/two" && {
  write_app "$work/two" x x_depth3_nodes
  "$cxx" -std=c++20 -Wall -Wextra -Werror -I"$source_dir/include" -I"$work/two" -o "$work/two/app" "$work/two"/*.cpp \
    >"$work/log" 2>&1 || fail "two models do not link together: $(head -5 "$work/log")"
  "$work/two/app" || fail "the linked app does not see both models"
}

# Names that would not compile are refused by the preparer, with one line naming the rule.
for name in class and not_eq char8_t co_await linux errno stdint features INT8_MAX NULL _x x_ a__b 9lives "a-b"; do
  if "$prepare" "$odd_scan" -o "$work/refused" --name "$name" >"$work/log" 2>&1; then
    fail "--name $name was accepted"
  elif [ "$(wc -l <"$work/log")" -ne 1 ] || ! grep -q "^octopoint-prepare: --name: " "$work/log"; then
    fail "--name $name: not one line naming --name: $(cat "$work/log")"
  fi
done
[ ! -e "$work/refused" ] || fail "a refused name left output behind"
rm -rf "$work"
[ "$failures" -eq 0 ] || exit 1
echo "all generated sources compile"
