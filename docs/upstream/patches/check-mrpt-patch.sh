#!/usr/bin/env bash
# Checks a patch of this directory against MRPT's source at a named revision, as its report records it: the patch
# applies there (git apply --check), and the regression test it adds to MRPT's own unit tests fails without the fix
# and passes with it, beside the unit test file's other tests. MRPT's tree is not built: the files the patch touches
# (library sources and headers, the unit test file) and the headers of those sources are taken from the revision
# and compiled against the MRPT installed here for the rest of the library (Debian 12: 2.5.8), with gtest.
# Usage: check-mrpt-patch.sh MRPT_GIT_DIR REVISION PATCH GTEST_FILTER
#   MRPT_GIT_DIR  a clone of https://github.com/MRPT/mrpt (any checkout; REVISION is read from its objects)
#   GTEST_FILTER  the regression tests the patch adds, e.g. 'PlannerSimple2D.targetOffTheMap*'; '-' for a patch
#                 that adds none (documentation): the unit test file and source of each header it touches are built
# Exits 0 when the patch applies, the regression tests fail before it and every test of the file passes after it
# (with '-': when the patch applies and every test of the file passes before and after it).
set -euo pipefail
[ $# -eq 4 ] || { sed -n '2,13p' "$0" | sed 's/^# \{0,1\}//'; exit 2; }
mrpt="$1" revision="$2" patch="$(realpath "$3")" filter="$4"
git -C "$mrpt" rev-parse --verify -q "$revision^{commit}" > /dev/null ||
  { echo "$mrpt: no revision '$revision'" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

mapfile -t touched < <(git apply --numstat "$patch" | cut -f3)
tests=() sources=() headers=()
for f in "${touched[@]}"; do
  case "$f" in
    *unittest*.cpp) tests+=("$f") ;;
    *.cpp) sources+=("$f") ;;
    */include/*.h) headers+=("$f") ;;
  esac
done
listing="$(git -C "$mrpt" ls-tree -r --name-only "$revision")"
if [ "$filter" = - ]; then
  [ ${#tests[@]} -eq 0 ] || { echo "$patch: adds tests; name them in GTEST_FILTER" >&2; exit 2; }
  for h in "${headers[@]}"; do
    stem="$(basename "$h" .h)"
    tests+=($(grep -E "/${stem}_unittest\.cpp$" <<< "$listing" || true))
    sources+=($(grep -E "/src/(.*/)?$stem\.cpp$" <<< "$listing" || true))
  done
fi
[ ${#tests[@]} -gt 0 ] || { echo "$patch: adds no test to MRPT's unit tests" >&2; exit 2; }
# The revision's header of each library source, and the datasets its tests load.
# And the library's private headers a source includes with quotes (2.x: "nav-precomp.h"), beside it or in its src/.
private=()
for f in "${sources[@]}"; do
  stem="$(basename "$f" .cpp)"
  headers+=($(grep -E "/include/.*/$stem\.h$" <<< "$listing" || true))
  for h in $(git -C "$mrpt" show "$revision:$f" | sed -n 's/^#include "\([^"]*\)".*/\1/p'); do
    private+=($(grep -xE "(${f%/*}|${f%%/src/*}/src)/$h" <<< "$listing" | head -1 || true))
  done
done
# What the revision has of them (a patch may add the test file), and the datasets the tests load, as patched.
extract=()
for f in "${touched[@]}" "${tests[@]}" "${sources[@]}" "${headers[@]}" "${private[@]}"; do
  grep -qxF "$f" <<< "$listing" && extract+=("$f")
done
for dataset in $( (git -C "$mrpt" show "$revision:${tests[0]}" 2> /dev/null || true; cat "$patch") |
                  grep -oE 'datasets/[A-Za-z0-9_.-]+' | sort -u); do
  extract+=($(grep -E "(^|/)$dataset$" <<< "$listing" | head -1))
done
mkdir "$work/before"
git -C "$mrpt" archive "$revision" -- $(printf '%s\n' "${extract[@]}" | sort -u) | tar -x -C "$work/before"
data_dir="$(find "$work/before" -type d -name datasets -printf '%h\n' | head -1)"
cp -r "$work/before" "$work/after"
echo "== $(basename "$patch") on MRPT $(git -C "$mrpt" rev-parse --short=12 "$revision^{commit}") ($revision)"
(cd "$work/after" && git apply --check "$patch" && git apply "$patch")
echo "applies: yes"
[ "$filter" = - ] || (cd "$work/before" && git apply --include='*unittest*' "$patch")

# A stand-in for MRPT's test_mrpt_common.h: the datasets of the revision.
mkdir -p "$work/shim"
printf '#pragma once\n#include <string>\nnamespace mrpt {\nstd::string UNITTEST_BASEDIR();\nstd::string mrpt_data_dir();\n}\n' \
  > "$work/shim/test_mrpt_common.h"
printf '#include "test_mrpt_common.h"\nstd::string mrpt::UNITTEST_BASEDIR() { return "%s"; }\nstd::string mrpt::mrpt_data_dir() { return "%s"; }\n' \
  "$work/before" "${data_dir:-/nonexistent}" > "$work/shim/test_mrpt_common.cpp"
# MRPT 3's name for the gzip stream 2.5.8 calls CFileGZInputStream (the unit tests load gzipped datasets with it).
mkdir -p "$work/shim/mrpt/io"
[ -e /usr/include/mrpt/io/include/mrpt/io/CCompressedInputStream.h ] ||
  printf '#pragma once\n#include <mrpt/io/CFileGZInputStream.h>\nnamespace mrpt::io {\nusing CCompressedInputStream = CFileGZInputStream;\n}\n' \
    > "$work/shim/mrpt/io/CCompressedInputStream.h"
cat > "$work/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.16)
project(mrpt_patch_check CXX)
foreach(module nav maps io serialization)
  find_package(mrpt-${module} REQUIRED)
endforeach()
find_package(GTest REQUIRED)
add_executable(unit_tests ${SOURCES} ${SHIM}/test_mrpt_common.cpp)
target_include_directories(unit_tests BEFORE PRIVATE ${OVERLAY} ${SHIM} ${PRIVATE})
target_link_libraries(unit_tests mrpt::nav mrpt::maps mrpt::io mrpt::serialization GTest::gtest_main)
target_compile_features(unit_tests PRIVATE cxx_std_17)
CMAKE

status=0
for side in before after; do
  tree="$work/$side" overlay="$work/$side.include"
  mkdir -p "$overlay"
  for h in "${headers[@]}"; do
    mkdir -p "$overlay/$(dirname "${h#*/include/}")" && cp "$tree/$h" "$overlay/${h#*/include/}"
  done
  list="$(printf "$tree/%s;" "${sources[@]}" "${tests[@]}")"
  # A header taken from the revision may include its neighbours with quotes: those installed, after it.
  private_dirs="$(for h in "${private[@]}"; do printf '%s;' "$tree/$(dirname "$h")"; done
                  for h in "${headers[@]}"; do
                    find /usr/include/mrpt -type d -path "*/include/$(dirname "${h#*/include/}")" -printf '%p;'
                  done)"
  if ! { cmake -S "$work" -B "$work/build-$side" -DSOURCES="${list%;}" -DOVERLAY="$overlay" -DSHIM="$work/shim" \
           -DPRIVATE="${private_dirs%;}" &&
         cmake --build "$work/build-$side"; } > "$work/build-$side.log" 2>&1; then
    echo "$side the fix: does not build against the installed MRPT:"; tail -20 "$work/build-$side.log"; exit 1
  fi
  regression=none
  if [ "$filter" != - ]; then
    "$work/build-$side/unit_tests" --gtest_filter="$filter" > "$work/$side.log" 2>&1 && regression=pass || regression=fail
  fi
  "$work/build-$side/unit_tests" > "$work/$side-all.log" 2>&1 && all=pass || all=fail
  echo "$side the fix: $([ "$filter" = - ] && echo 'no regression test' || echo "'$filter' $regression");\
 the file's tests: $(grep -E '^\[  (PASSED|FAILED)  \] [0-9]+ test' "$work/$side-all.log" | tr '\n' ' ')"
  # Each failed expectation with gtest's message, then the failed tests.
  awk '/: Failure$/ { shown = 1 } /^\[/ { shown = 0 } shown' "$work/$side-all.log" | sed "s|$work/||; s/^/  /"
  grep -E '^\[  FAILED  \] [A-Za-z][A-Za-z0-9_]*\.[A-Za-z0-9_]+$' "$work/$side-all.log" | sort -u | sed 's/^/  /' || true
  case "$side:$regression:$all" in
    before:fail:*|after:pass:pass|*:none:pass) ;;
    *) status=1 ;;
  esac
done
if [ "$status" -ne 0 ]; then echo "verdict: NOT as the report says"
elif [ "$filter" = - ]; then echo "verdict: applies; the file's tests pass before and after it"
else echo "verdict: fails without the fix, passes with it"; fi
exit "$status"
