#!/usr/bin/env bash
# What a large map costs: scale_bench's step cost per agent configuration and mating cost per fitness at map
# sides 20, 100, 512 and 1000, then the peak memory (maximum resident set) and wall time of a small experiment at
# each side: one set evolved with `turns` (population 20, 20 matings) played by the default experiment's ten
# agents, 2 runs each. Usage: scripts/bench-scale.sh (after scripts/build.sh). Figures go in BENCHMARKS.md.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'" \
  "date=$(date -u +%Y-%m-%dT%H:%M:%SZ) commit=$(git rev-parse --short HEAD 2>/dev/null || echo none)"
cmake --build "$PPP_BUILD_DIR" --target scale_bench -j "$(nproc)" > /dev/null
"$PPP_BUILD_DIR/devel/lib/ppp_simulator/scale_bench" --benchmark_format=console

grep -v "type: planner" config/agents.yaml > "$work/agents.yaml"
for side in 20 100 512 1000; do
  cat > "$work/scale_$side.yaml" <<YAML
seed: 1
runs: 2
hardest: 1
agents: agents.yaml
sets:
  - name: turns
    generator: {fitness: turns, population: 20, matings: 20, width: $side, height: $side, seed: 1}
YAML
  /usr/bin/time -f "%M %e" -o "$work/time_$side" scripts/ppp experiment "$work/scale_$side.yaml" \
    -o "$work/out_$side" --quiet > /dev/null
  read -r kilobytes seconds < "$work/time_$side"
  echo "experiment at ${side}x${side} (20 PPPs x 10 agents x 2 runs): peak memory $((kilobytes / 1024)) MB," \
    "wall ${seconds} s, results.csv $(wc -l < "$work/out_$side/results.csv") lines"
done
