#!/usr/bin/env bash
# The main job: installs what is missing, builds, then runs the default experiment (config/experiment.yaml:
# three sets of 60 PPPs, two evolved and one hunted, ten agents with 1,000 runs each and four example planners
# with 3) through ROS:
# roslaunch launch/experiment.launch starts the config's graph: a generator node per set (the hunting one has the
# simulator play its candidates on the agent nodes), the simulator node and an agent node per built-in agent, all
# nodelets in one nodelet manager, and a bridge and a planner process per planner agent, on a private master. Results,
# report and bag go to results/experiment/. Rerunning resumes an interrupted experiment.
set -eo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"
scripts/install-deps.sh
mkdir -p "$PPP_BUILD_DIR"
echo "building (log: $PPP_BUILD_DIR/build.log)"
scripts/build.sh > "$PPP_BUILD_DIR/build.log" 2>&1 || { tail -50 "$PPP_BUILD_DIR/build.log"; exit 1; }
source "$PPP_BUILD_DIR/devel/setup.bash"  # before set -u: setup.bash reads unset variables
set -u
export PATH="/usr/bin:$PATH"

out="$PPP_ROOT/results/experiment"
log="$PPP_ROOT/results/experiment.roslaunch.log"  # beside, not in, the output directory
mkdir -p "$PPP_ROOT/results"
# ROS 1 has no authentication and roscpp's topic servers listen on every interface: the run gets a network
# namespace of its own with only loopback (scripts/loopback-only), where nothing can reach it.
isolate=(scripts/loopback-only)
port=11311
if ! scripts/loopback-only /bin/true; then
  echo "WARNING: running without a network namespace of its own: the nodes' topic ports are open to every" \
       "network this machine is on (see docs/how-to/isolated-network.md)" >&2
  isolate=()
  port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
fi
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1
echo "running the experiment with ROS (log: $log)"
# The whole output goes to the log; the terminal gets the phases and a progress line every few seconds. The
# filters ignore Ctrl-C, so roslaunch shuts its nodes down and its last words still reach the log.
"${isolate[@]}" roslaunch -p "$port" launch/experiment.launch output_dir:="$out" 2>&1 | (
  trap '' INT TERM
  tee "$log" |
    grep --line-buffered -E 'progress: |generating [0-9]+ PPPs|running [0-9]+ episodes|finishing|experiment done|ERROR|FATAL' |
    sed -u -e 's/\x1b\[[0-9;]*m//g' -e 's/^\[ *INFO\] \[[0-9.]*\]: /  /' -e 's/^\[ *\([A-Z]*\)\] \[[0-9.]*\]: /  \1: /'
) || true
# roslaunch's exit status says nothing about its nodes: the report is the verdict.
if [ ! -s "$out/report.md" ] || ! grep -q "experiment done" "$log"; then
  grep -E "FATAL|ERROR" "$log" | tail -10
  tail -5 "$log"
  echo "the experiment did not finish; rerun this command to resume it" >&2
  exit 1
fi
echo
sed -n '/^## Pass rates/,/^## Mann/p' "$out/report.md" | sed '$d'
echo "Report: $out/report.html (Markdown: $out/report.md); results: $out/results.csv; bag: $out/experiment.bag"
echo "Look at the bag in rviz: build/devel/env.sh roslaunch launch/inspect.launch bag:=$out/experiment.bag"
