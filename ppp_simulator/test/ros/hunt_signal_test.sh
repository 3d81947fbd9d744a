#!/usr/bin/env bash
# A hunt through ROS (launch/hunt.launch: the generator hunting through the simulator in hunt mode and an agent,
# nodelets in one manager) shut down mid-hunt by a real SIGINT to roslaunch, which sends SIGINT to the nodes: the
# manager exits within a second of it, no set is written, and a rerun writes the set `ppp generate`
# writes in process. Usage: hunt_signal_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"

# About 80 evaluation requests of 16 PPPs x 10 runs: some 6 s of hunting through the agent node.
cat > "$work/hunt.yaml" <<'YAML'
seed: 1
runs: 1
agents:
  - {name: explorer, type: explorer}
sets:
  - name: h
    generator: {fitness: failure, agents: [explorer], runs_per_eval: 10, population: 16, matings: 600, width: 20,
                height: 20, seed: 7}
YAML
hunt=(roslaunch -p "$port" "$root/launch/hunt.launch" output_dir:="$work/out" set:=h config:="$work/hunt.yaml")
# pid_of LOG NODE: the pid roslaunch started NODE with.
pid_of() { sed -n "s/.*process\[$2-[0-9]*\]: started with pid \[\([0-9]*\)\].*/\1/p" "$1" | tail -1; }

"${hunt[@]}" > "$work/launch.log" 2>&1 &
launch=$!  # roslaunch itself: SIGINT reaches it as Ctrl-C would
# The simulator logs its first evaluation at once (then a progress line every few seconds).
for _ in $(seq 1 3000); do grep -q "progress: hunt: " "$work/launch.log" && break; sleep 0.01; done
grep -q "progress: hunt: " "$work/launch.log" && pass || fail "the hunt did not get going: $(tail -20 "$work/launch.log")"
# The generator and the simulator run as nodelets in the manager: the manager's end is theirs.
manager=$(pid_of "$work/launch.log" nodelet_manager)
[ -n "$manager" ] && pass || fail "no pid of the nodelet manager in the log"
start=$(date +%s%N)
kill -INT "$launch"
stopped_ms=""
for _ in $(seq 1 3000); do
  if ! kill -0 "$manager" 2>/dev/null; then stopped_ms=$(( ($(date +%s%N) - start) / 1000000 )); break; fi
  sleep 0.01
done
[ "${stopped_ms:-99999}" -le 1000 ] && pass \
  || fail "the manager (generator and simulator) stopped ${stopped_ms:-never} ms after roslaunch's SIGINT: $(tail -20 "$work/launch.log")"
timeout -s KILL 60 tail --pid="$launch" -f /dev/null
grep -q "escalating to SIG" "$work/launch.log" && fail "roslaunch had to escalate: $(grep escalating "$work/launch.log")" || pass
grep -q "600/600 matings" "$work/launch.log" && fail "the hunt went on after the signal" || pass
[ ! -e "$work/out/set.csv" ] && pass || fail "the interrupted hunt wrote a set"

timeout 300 "${hunt[@]}" > "$work/rerun.log" 2>&1
[ -s "$work/out/set.csv" ] && pass || fail "the rerun wrote no set: $(tail -20 "$work/rerun.log")"
"$devel/lib/ppp_simulator/ppp" generate --config "$work/out/generator.yaml" -o "$work/cli" > /dev/null 2>&1
same_sets "$work/out" "$work/cli" && pass || fail "the set hunted after the interruption differs from ppp generate's"

finish
