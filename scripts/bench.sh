#!/usr/bin/env bash
# Builds the ppp_core benchmarks standalone (Release) in build-bench/ and the workspace (build/), and runs the
# core and generator benchmarks, 3 repetitions each.
# Console summary on stdout, JSON per binary in bench-results/. Extra arguments go to every benchmark binary
# (e.g. --benchmark_filter=Dpa). Figures in BENCHMARKS.md come from this script.
set -euo pipefail

repo="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "${repo}"

build_dir=build-bench
results_dir=bench-results
benchmarks=(dpa_bench visibility_bench evaluation_bench)

cmake -S src -B "${build_dir}" -DCMAKE_BUILD_TYPE=Release -DPPP_CORE_BENCHMARKS=ON >/dev/null
cmake --build "${build_dir}" --target "${benchmarks[@]}" -j2
mkdir -p "${results_dir}"

cpu_model="$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//' || true)"
echo "machine: nproc=$(nproc) cpu='${cpu_model:-unknown}' date=$(date -u +%Y-%m-%dT%H:%M:%SZ) commit=$(git rev-parse --short HEAD 2>/dev/null || echo none)"

for bench in "${benchmarks[@]}"; do
  echo "== ${bench}"
  "${build_dir}/${bench}" \
    --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true \
    --benchmark_format=console \
    --benchmark_out="${results_dir}/${bench}.json" \
    --benchmark_out_format=json \
    "$@"
done
# Generator benchmarks live in the catkin workspace (package ppp_generator).
PATH="/usr/bin:$PATH" scripts/build.sh > /dev/null
for bench in upgma_bench generator_bench; do
  echo "== ${bench}"
  "build/devel/lib/ppp_generator/${bench}" \
    --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true \
    --benchmark_format=console \
    --benchmark_out="${results_dir}/${bench}.json" \
    --benchmark_out_format=json \
    "$@"
done
echo "JSON results: ${repo}/${results_dir}/"
