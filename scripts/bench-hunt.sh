#!/usr/bin/env bash
# Hunting power on the fault zoo: the shipped hunt (config/planner_hunt.yaml with only its agent entry swapped), the
# hunt as it was before (commit 488355d's file, given as many matings) and random search at the same number of
# evaluations, against the zoo planner's eight planted faults, twelve planners with three of them at once (fault
# recall) and MRPT's wavefront planner, through roslaunch
# (scripts/bench_hunt.py says what is measured).
# Usage: scripts/bench-hunt.sh [--planners a,b] [--routes shipped,today,random] [--work DIR] [--config FILE]
#        scripts/bench-hunt.sh --table DIR/hunt_power.jsonl   (the table of a finished run)
#        scripts/bench-hunt.sh --separation [--work DIR]      (how well failure signatures tell the faults apart)
# (run scripts/build.sh first). One JSON line per planner and route; figures go in BENCHMARKS.md.
set -eo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
load_workspace
export ROS_HOME="${ROS_HOME:-$(mktemp -d)}"
echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'"
exec /usr/bin/python3 "$PPP_ROOT/scripts/bench_hunt.py" "$@"
