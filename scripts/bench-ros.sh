#!/usr/bin/env bash
# ROS experiment speed: agent-steps per second through the ten separate agent processes at batch sizes
# 1, 10, 100, 1000, 2000 and 4000; the default experiment's built-in agents through roslaunch against `ppp experiment`;
# and the shipped default with the example planners, with episodes per second through planner_bridge_node.
# Usage: [PAIRS=N] scripts/bench-ros.sh [--skip-default]   (run scripts/build.sh first; PAIRS: how many
# roslaunch / ppp experiment pairs of the default experiment, 1 by default). Figures go in BENCHMARKS.md.
set -o pipefail
skip_default="${1:-}"
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$PPP_BUILD_DIR/devel/setup.bash"
set -u
export PATH="/usr/bin:$PATH"
cd "$PPP_ROOT"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export ROS_IP=127.0.0.1 ROS_HOME="$work/ros"
cp config/generator.yaml "$work/"
grep -v "type: planner" config/agents.yaml > "$work/agents.yaml"  # the ten built-in agents

# launch OUT RUNS BATCH RECORD: runs the default experiment with RUNS runs per agent per PPP; prints seconds.
launch() {
  sed "s/^runs: 1000 .*/runs: $2/" config/experiment.yaml > "$work/experiment.yaml"
  local start end port
  # A fresh master port per launch: the last master may still be shutting down on the old one.
  port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  export ROS_MASTER_URI="http://127.0.0.1:$port"
  start=$(date +%s.%N)
  roslaunch -p "$port" launch/experiment.launch output_dir:="$1" config:="$work/experiment.yaml" \
    args:="--batch-size $3 --record $4" > "$1.log" 2>&1
  end=$(date +%s.%N)
  awk "BEGIN { printf \"%.2f\", $end - $start }"
}
# The batch size experiment.launch uses when none is given.
default_batch="$(grep -o 'name="batch_size" default="[0-9]*"' launch/experiment.launch | grep -o '[0-9]*"$' | tr -d '"')"
steps() { awk -F, 'NR > 1 { s += $7 } END { print s }' "$1/results.csv"; }

echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'"
for pair in "1 1" "10 2" "100 20" "1000 200" "2000 200" "4000 200"; do
  set -- $pair
  seconds=$(launch "$work/b$1" "$2" "$1" false)
  total=$(steps "$work/b$1")
  echo "batch $1: $2 runs per agent per PPP, $total agent-steps in $seconds s (launch, generation and report included):" \
    "$(awk "BEGIN { printf \"%.0f\", $total / $seconds }") agent-steps/s"
done
if [ "$skip_default" != "--skip-default" ]; then
  # The ten built-in agents only, against `ppp experiment` (which runs no planner agents), in PAIRS pairs run
  # back to back (the VM's speed drifts, so each pair's ratio says more than two separate ranges).
  for pair in $(seq 1 "${PAIRS:-1}"); do
    rm -rf "$work/builtin" "$work/cli"
    seconds=$(launch "$work/builtin" 1000 "$default_batch" true)
    echo "default experiment, built-in agents, through roslaunch (batch $default_batch, bag recorded): $seconds s"
    start=$(date +%s.%N)
    "$PPP_BUILD_DIR/devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null
    end=$(date +%s.%N)
    cli=$(awk "BEGIN { printf \"%.2f\", $end - $start }")
    echo "default experiment, built-in agents, through ppp experiment: $cli s (ratio $(awk "BEGIN { printf \"%.2f\", $seconds / $cli }"))"
    cmp -s "$work/builtin/results.csv" "$work/cli/results.csv" && echo "results.csv identical" || echo "results.csv DIFFER"
  done
  # The shipped default: the same plus the example planners through planner_bridge_node (on the grid, and the two
  # local ones again in continuous motion).
  cp config/agents.yaml "$work/agents.yaml"
  seconds=$(launch "$work/full" 1000 "$default_batch" true)
  echo "default experiment with the example planners through roslaunch: $seconds s"
  grep -ho "agent '\(ompl\|optimistic\|mrpt\|mrpt_nd\|dwa\|mrpt_nd_continuous\|dwa_continuous\)': .*episodes/s)" "$work/full.log"
  # The planners alone (the built-in agent nodes idle): episodes per second through the bridge, unloaded.
  grep "type: planner" config/agents.yaml | sed '1i agents:' > "$work/agents.yaml"
  seconds=$(launch "$work/planners" 1000 "$default_batch" false)
  echo "the example planners alone, their runs per PPP each: $seconds s"
  grep -ho "agent '\(ompl\|optimistic\|mrpt\|mrpt_nd\|dwa\|mrpt_nd_continuous\|dwa_continuous\)': .*episodes/s)" "$work/planners.log"
fi
