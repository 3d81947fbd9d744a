#!/usr/bin/env bash
# Builds the libFuzzer target for the .ppp parser with clang (ASan + UBSan) in build-fuzz/ and runs it for a
# bounded time: scripts/fuzz.sh [SECONDS] (default 30). Exits non-zero on any finding; crash inputs are written
# to build-fuzz/artifacts/. Reproduce one with: build-fuzz/ppp_parser_fuzz build-fuzz/artifacts/crash-...
set -euo pipefail

seconds="${1:-30}"
if ! [[ "${seconds}" =~ ^[1-9][0-9]*$ ]]; then
  echo "usage: $0 [SECONDS]  (a positive whole number of seconds, default 30)" >&2
  exit 2
fi

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "${repo}"

build_dir=build-fuzz
clangxx="$(command -v clang++ || true)"
if [[ -z "${clangxx}" ]]; then
  echo "fuzz.sh: clang++ not found (libFuzzer needs clang)" >&2
  exit 2
fi

cmake -S src -B "${build_dir}" -DCMAKE_CXX_COMPILER="${clangxx}" -DPPP_CORE_FUZZ=ON -DPPP_CORE_BENCHMARKS=OFF >/dev/null
cmake --build "${build_dir}" --target ppp_parser_fuzz -j2

corpus="${build_dir}/corpus"
artifacts="${build_dir}/artifacts"
mkdir -p "${corpus}" "${artifacts}"
cp src/fuzz/corpus/*.ppp "${corpus}/"

echo "fuzzing parsePpp for ${seconds} s (corpus ${corpus}, findings in ${artifacts})"
status=0
"${build_dir}/ppp_parser_fuzz" \
  -max_total_time="${seconds}" -timeout=5 -rss_limit_mb=2048 -max_len=65536 \
  -artifact_prefix="${artifacts}/" "${corpus}" || status=$?
if [[ ${status} -ne 0 ]]; then
  echo "fuzz.sh: FINDING (libFuzzer exit ${status}); inputs in ${artifacts}/:" >&2
  ls -l "${artifacts}" >&2 || true
  exit "${status}"
fi
echo "fuzz.sh: no findings in ${seconds} s"
