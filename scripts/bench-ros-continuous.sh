#!/usr/bin/env bash
# Continuous motion through ROS against `ppp experiment`: the A* control in continuous motion (a disc of 0.2
# cells, diff drive) on the default experiment's turns and difficulty sets (made once by its generators and given
# to both as directories), RUNS runs per PPP (1000, the default experiment's), through roslaunch (one nodelet
# manager, astar as one agent node per core) and in process, in PAIRS pairs run back to back (the VM's speed
# drifts, so each pair's ratio says more than two separate ranges); results.csv must be identical.
# Usage: [PAIRS=N] [RUNS=N] scripts/bench-ros-continuous.sh   (run scripts/build.sh first). Figures go in
# BENCHMARKS.md.
set -o pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$PPP_BUILD_DIR/devel/setup.bash"
set -u
export PATH="/usr/bin:$PATH"
cd "$PPP_ROOT"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export ROS_IP=127.0.0.1 ROS_HOME="$work/ros"
ppp="$PPP_BUILD_DIR/devel/lib/ppp_simulator/ppp"
cp config/generator.yaml "$work/"

# The default sets, made once by their generators (config/experiment.yaml's turns and difficulty).
cat > "$work/sets.yaml" <<EOF2
runs: 1
motion: continuous
robot_radius: 0.2
agents:
  - {name: astar, type: astar}
sets:
$(sed -n '/^  - name: turns/,/^  - name: hunted/p' config/experiment.yaml | grep -v 'name: hunted')
EOF2
"$ppp" experiment "$work/sets.yaml" -o "$work/made" --quiet > /dev/null
cat > "$work/experiment.yaml" <<EOF2
seed: 1
runs: ${RUNS:-1000}
motion: continuous
robot_radius: 0.2
agents:
  - {name: astar, type: astar}
sets:
  - {name: turns, directory: $work/made/sets/turns}
  - {name: difficulty, directory: $work/made/sets/difficulty}
EOF2

seconds() { awk "BEGIN { printf \"%.2f\", $2 - $1 }"; }
echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'"
for pair in $(seq 1 "${PAIRS:-1}"); do
  rm -rf "$work/ros_out" "$work/cli"
  port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  export ROS_MASTER_URI="http://127.0.0.1:$port"
  start=$(date +%s.%N)
  roslaunch -p "$port" launch/experiment.launch output_dir:="$work/ros_out" config:="$work/experiment.yaml" \
    > "$work/launch.log" 2>&1
  ros=$(seconds "$start" "$(date +%s.%N)")
  start=$(date +%s.%N)
  "$ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null
  cli=$(seconds "$start" "$(date +%s.%N)")
  periods=$(awk -F, 'NR > 1 { s += $7 } END { print s }' "$work/cli/results.csv")
  echo "pair $pair: $periods control periods; roslaunch $ros s, ppp experiment $cli s: ratio" \
    "$(awk "BEGIN { printf \"%.2f\", $ros / $cli }")"
  grep -o "agent 'astar'.*episodes/s)" "$work/launch.log"
  cmp -s "$work/ros_out/results.csv" "$work/cli/results.csv" && echo "results.csv identical" || echo "results.csv DIFFER"
done
