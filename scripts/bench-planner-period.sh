#!/usr/bin/env bash
# What a local planner's control period costs through ROS (BENCHMARKS.md, "Continuous motion at the planner's pace").
# 1. Messages alone (period_round_trip_bench, two processes, no bridge): ROUNDS rounds of each set of a period's
#    messages, from one small message there and back (the floor) to every message a period sent before.
# 2. Planners through the bridge: each AGENT alone in an experiment (roslaunch, two instances on the two cores) on
#    10 PPPs of a turns set, RUNS runs a PPP in continuous motion: control periods per second per instance, from
#    results.csv's steps and the simulator's lane times. Agents: echo (ppp_agents/echo_planner_node: answers at
#    once, standing still; a nodelet beside its bridge, as the experiment runs this repository's planners),
#    echo_process (the same, bridge and planner each a process of its own, on the bridge's clock), rospy_echo (a rospy planner that answers each period's odometry, scan and goal at once
#    with a zero velocity, written here as a user would and started by this script: one instance),
#    mrpt_nd_continuous, dwa_continuous (config/agents.yaml's).
# RESULTS=DIR keeps each agent's results.csv as DIR/AGENT.csv.
# Usage: [ROUNDS=N] [RUNS=N] [RESULTS=DIR] [AGENTS="echo ..."] [BRIDGE_ARGS="period_messages: all"] scripts/loopback-only
#        scripts/bench-planner-period.sh   (after scripts/build.sh)
set -o pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
load_workspace
cd "$PPP_ROOT"
work="$(mktemp -d)"; echo "work: $work"
trap 'kill $(jobs -p) 2> /dev/null; [[ -n "${KEEP:-}" ]] || rm -rf "$work"' EXIT
export ROS_HOME="$work/ros"
ppp="$PPP_BUILD_DIR/devel/lib/ppp_simulator/ppp"
bench="$PPP_BUILD_DIR/devel/lib/ppp_agents/period_round_trip_bench"
cmake --build "$PPP_BUILD_DIR" --target period_round_trip_bench -j "$(nproc)" > /dev/null
free_port() { python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'; }
echo "machine: nproc=$(nproc) cpu='$(grep -m1 '^model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')'"

if [[ -z "${SKIP_ROUNDS:-}" ]]; then
  port="$(free_port)"
  export ROS_MASTER_URI="http://127.0.0.1:$port"
  rosmaster --core -p "$port" > "$work/master.log" 2>&1 &
  master=$!
  sleep 2
  for topics in goal scan odom clock,goal map tf odom,scan odom,scan,clock map,tf,odom,scan,goal,clock; do
    "$bench" answer "$topics" &
    answerer=$!
    ANSWERER_PID=$answerer "$bench" ask "$topics" "${ROUNDS:-20000}"
    kill "$answerer"
    wait "$answerer" 2> /dev/null
  done
  kill "$master"
  wait "$master" 2> /dev/null
fi

# The rospy echo planner, as a user would write one to today's interface.
cat > "$work/rospy_echo.py" <<'PY'
#!/usr/bin/env python3
import rospy
from geometry_msgs.msg import PoseStamped, TwistStamped
from nav_msgs.msg import Odometry
from sensor_msgs.msg import LaserScan

newest = {}
answered = [rospy.Time()]


def keep(kind, message):
    newest[kind] = message
    stamps = {m.header.stamp for m in newest.values()}
    if len(newest) == 3 and len(stamps) == 1:
        stamp = stamps.pop()
        if stamp > answered[0]:
            answered[0] = stamp
            out = TwistStamped()
            out.header.stamp = stamp
            commands.publish(out)


rospy.init_node("rospy_echo")
commands = rospy.Publisher("cmd_vel", TwistStamped, queue_size=10)
for kind, topic, kind_type in (("odom", "odom", Odometry), ("scan", "scan", LaserScan),
                               ("goal", "move_base_simple/goal", PoseStamped)):
    rospy.Subscriber(topic, kind_type, lambda m, k=kind: keep(k, m), queue_size=10)
rospy.spin()
PY
chmod +x "$work/rospy_echo.py"

agent_entry() {
  local extra="${BRIDGE_ARGS:+, $BRIDGE_ARGS}"
  case "$1" in
    echo) echo "{name: echo, type: planner, motion: continuous, interface: cmd_vel, endless_proof: false, planner_node: ppp_agents/echo_planner_node$extra}" ;;
    echo_process) echo "{name: echo_process, type: planner, motion: continuous, interface: cmd_vel, endless_proof: false, process: own, planner_node: ppp_agents/echo_planner_node$extra}" ;;
    rospy_echo) echo "{name: rospy_echo, type: planner, motion: continuous, interface: cmd_vel, endless_proof: false, wakes_on: messages$extra}" ;;
    *) sed -n "s/^  - \({name: $1,.*\)}\$/\1$extra}/p" config/agents.yaml | sed "s/ runs: [0-9]*,//" ;;
  esac
}

cat > "$work/sets.yaml" <<EOF2
runs: 1
agents:
  - {name: astar, type: astar}
sets:
  - name: turns
    generator: {fitness: turns, population: 10, matings: 1000, seed: 1}
EOF2
"$ppp" experiment "$work/sets.yaml" -o "$work/made" --quiet > /dev/null
for agent in ${AGENTS:-echo echo_process rospy_echo mrpt_nd_continuous dwa_continuous}; do
  entry="$(agent_entry "$agent")"
  [[ -n "$entry" ]] || { echo "no agent '$agent'" >&2; exit 2; }
  cat > "$work/experiment.yaml" <<EOF2
seed: 1
runs: ${RUNS:-2}
agents:
  - $entry
sets:
  - {name: turns, directory: $work/made/sets/turns}
EOF2
  port="$(free_port)"
  export ROS_MASTER_URI="http://127.0.0.1:$port"
  rm -rf "$work/out"
  if [[ "$agent" == rospy_echo ]]; then  # a planner the user starts: one instance
    "$work/rospy_echo.py" __ns:=/rospy_echo/robot /clock:=/rospy_echo/robot/clock > "$work/rospy_echo.log" 2>&1 &
  fi
  start=$(date +%s.%N)
  roslaunch -p "$port" launch/experiment.launch output_dir:="$work/out" config:="$work/experiment.yaml" \
    > "$work/launch.log" 2>&1 || { tail -30 "$work/launch.log"; exit 1; }
  whole=$(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }")
  if [[ -n "${RESULTS:-}" ]]; then mkdir -p "$RESULTS" && cp "$work/out/results.csv" "$RESULTS/$agent.csv"; fi
  steps_column=$(head -1 "$work/out/results.csv" | tr ',' '\n' | grep -n '^steps$' | cut -d: -f1)
  periods=$(awk -F, -v c="$steps_column" 'NR > 1 { s += $c } END { print s }' "$work/out/results.csv")
  lanes=$(grep -o "agent '$agent'[^:]*: [0-9]* episodes in [0-9.]* s" "$work/launch.log" |
    awk '{ print $(NF - 1) }' | paste -sd' ')
  echo "$agent: $periods periods; lanes $lanes s; per instance $(echo "$lanes" |
    awk -v p="$periods" '{ t = 0; for (i = 1; i <= NF; i++) t += $i; printf "%.0f", p / t }') periods/s;" \
    "launch $whole s"
  grep -m1 "agent '$agent'.* episodes in" "$work/launch.log" > /dev/null || tail -20 "$work/launch.log"
done
