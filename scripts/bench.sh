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
cmake --build build --target benchmarks -j "$(nproc)" > /dev/null
for bench in ppp_generator/upgma_bench ppp_generator/generator_bench ppp_agents/agent_step_bench \
  ppp_agents/planners_bench ppp_agents/continuous_step_bench ppp_agents/continuous_lockstep_bench ppp_agents/laser_bench \
  ppp_simulator/episode_bench \
  ppp_simulator/hunt_bench ppp_simulator/lockstep_bench; do
  echo "== ${bench}"
  "build/devel/lib/${bench}" \
    --benchmark_repetitions=3 \
    --benchmark_report_aggregates_only=true \
    --benchmark_format=console \
    --benchmark_out="${results_dir}/$(basename "${bench}").json" \
    --benchmark_out_format=json \
    "$@"
done

# The default experiment end to end (generation included), on 1 and on 2 worker threads.
for threads in 1 2; do
  out="$(mktemp -d)"
  start=$(date +%s.%N)
  scripts/ppp experiment config/experiment.yaml -o "${out}/experiment" --threads "${threads}" --quiet > /dev/null
  end=$(date +%s.%N)
  echo "== default experiment (3 x 60 PPPs x 10 built-in agents x 1000 runs), ${threads} thread(s): $(awk "BEGIN { printf \"%.1f\", ${end} - ${start} }") s"
  rm -rf "${out}"
done
echo "JSON results: ${repo}/${results_dir}/"
