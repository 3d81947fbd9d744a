#!/usr/bin/env bash
# The ROS experiment in a network namespace of its own (scripts/loopback-only, as scripts/run-main.sh runs it):
# while it runs, every listening socket of its master and nodes is in a namespace whose only interface is
# loopback, none is in the machine's own namespace, and the results equal `ppp experiment`'s.
# Usage: loopback_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"
# The namespace has ports of its own: the default master port is free there.
export ROS_MASTER_URI="http://127.0.0.1:11311"

cat > "$work/experiment.yaml" <<'YAML'
seed: 7
runs: 2000
agents:
  - {name: random, type: random}
  - {name: explorer, type: explorer}
sets:
  - name: mine
    generator: {fitness: turns, population: 10, matings: 100, seed: 2}
YAML
cp "$root/config/generator.yaml" "$work/"
"$root/scripts/loopback-only" timeout 300 roslaunch -p 11311 "$root/launch/experiment.launch" \
  output_dir:="$work/out" config:="$work/experiment.yaml" > "$work/launch.log" 2>&1 &
launcher=$!

# in_run: the pids of the processes in the run's namespace (the launcher's, once it has entered it).
own_ns="$(readlink /proc/self/ns/net)"
run_ns=""
in_run() {
  for p in /proc/[0-9]*; do
    [ "$(readlink "$p/ns/net" 2> /dev/null)" = "$run_ns" ] && echo "${p#/proc/}"
  done
}
# running_inside NAME: whether a process named NAME runs in the run's namespace (other tests may run their own
# simulators meanwhile, in other namespaces). Looking up the two names is quick even on a loaded machine, where
# reading every process's namespace each time could outlast the run.
running_inside() {
  local pid
  for pid in $(pgrep -x "$1"); do
    [ "$(readlink "/proc/$pid/ns/net" 2> /dev/null)" = "$run_ns" ] && return 0
  done
  return 1
}
seen=""
for _ in $(seq 1 3000); do
  run_ns="$(readlink "/proc/$launcher/ns/net" 2> /dev/null)"
  if [ -n "$run_ns" ] && [ "$run_ns" != "$own_ns" ]; then
    seen=""
    # The nodelet manager (the simulator and the agents run in it) and the nodelet loaders are `nodelet`.
    for name in nodelet; do running_inside "$name" && seen="$seen $name"; done
    # Every node is up once the episodes start.
    [ "$seen" = " nodelet" ] && grep -q "running [0-9]* episodes" "$work/launch.log" && break
  fi
  sleep 0.02
done
case "$seen" in
  *nodelet*) pass ;;
  *) fail "the simulator never ran in the run's namespace (seen: $seen): $(tail -5 "$work/launch.log")" ;;
esac

# Inside: the master's, the XML-RPC and the TCPROS listeners, in a namespace that has only loopback.
nsenter --net="/proc/$launcher/ns/net" ss -Hltn > "$work/inside.txt"
nsenter --net="/proc/$launcher/ns/net" ip -o link > "$work/links.txt"
[ "$(wc -l < "$work/links.txt")" -eq 1 ] && grep -q "^1: lo:" "$work/links.txt" && pass || \
  fail "the run's namespace has other interfaces: $(cat "$work/links.txt")"
grep -q "127.0.0.1:11311 " "$work/inside.txt" && pass || fail "no master listening inside: $(cat "$work/inside.txt")"
[ "$(wc -l < "$work/inside.txt")" -ge 6 ] && pass || fail "too few listeners inside: $(cat "$work/inside.txt")"
# Outside: no listening socket belongs to a process of the run.
pids="$(in_run | tr '\n' ' ')"
ss -Hltnp > "$work/outside.txt"
leaked=""
for pid in $pids; do grep -q "pid=$pid," "$work/outside.txt" && leaked="$leaked $pid"; done
[ -z "$leaked" ] && pass || fail "processes of the run listen in the machine's namespace:$leaked"

wait "$launcher"
"$devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null 2>&1
cmp -s "$work/out/results.csv" "$work/cli/results.csv" && pass || \
  fail "the isolated run differs from ppp experiment: $(tail -20 "$work/launch.log")"
finish
