#!/usr/bin/env bash
# The experiment across two hosts, as ROS's own multi-machine roslaunch runs it: the test makes two network
# namespaces joined by a veth pair, "master" (the master, the launcher, the generator and simulator nodes) and
# "agents" (an OpenSSH server, and through it every agent node and one planner with its bridge, started by
# roslaunch over ssh because the config names that host for them), with ROS_IP set per side. Then:
#   1. the experiment finishes and its built-in agents' rows of results.csv equal `ppp experiment`'s;
#   2. the link is cut mid-run (ip link set ... down): the lost runs are recorded (agent_lost or timeout) and
#      the experiment still completes;
#   3. the link comes back and a rerun plays the lost runs again: results.csv equals `ppp experiment`'s.
# Every address lives in the two namespaces the test makes; nothing leaves them. Without the privileges to make
# namespaces the test says it is skipped (exit 77). sshd is Debian's, unpacked into the build directory by
# scripts/install-deps.sh and run only inside the agents' namespace (with a private passwd and /run), so the
# machine gets no ssh service. Usage: multi_machine_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"
export PATH="/usr/sbin:$PATH"
sshd="$devel/../sshd/usr/sbin/sshd"

skip() { echo "SKIPPED: $*"; exit 77; }
[ "$(id -u)" -eq 0 ] || skip "making network namespaces needs root"
[ -x "$sshd" ] || { echo "FAIL: no sshd at $sshd (scripts/install-deps.sh unpacks it)"; exit 1; }

master_ns="ppp_mm_master_$$" agents_ns="ppp_mm_agents_$$"
master_ip=10.77.0.1 agents_ip=10.77.0.2
master_link="pmm$$m" agents_link="pmm$$a"
cleanup() {
  for ns in "$master_ns" "$agents_ns"; do
    pids="$(ip netns pids "$ns" 2> /dev/null)"
    [ -n "$pids" ] && kill -9 $pids 2> /dev/null
    ip netns del "$ns" 2> /dev/null
  done
  kill -9 $(jobs -p) 2> /dev/null
  rm -rf "$work"
}
trap cleanup EXIT
ip netns add "$master_ns" 2> /dev/null || skip "cannot make a network namespace here (ip netns add failed)"
ip netns add "$agents_ns"
ip link add "$master_link" netns "$master_ns" type veth peer name "$agents_link" netns "$agents_ns"
in_master() { ip netns exec "$master_ns" "$@"; }
in_agents() { ip netns exec "$agents_ns" "$@"; }
in_master ip addr add "$master_ip/24" dev "$master_link"
in_agents ip addr add "$agents_ip/24" dev "$agents_link"
for ns in "$master_ns" "$agents_ns"; do ip -n "$ns" link set lo up; done
in_master ip link set "$master_link" up
in_agents ip link set "$agents_link" up

# The agents' host: sshd on its address, accepting the test's key for root; sessions get ROS_IP and ROS_HOME.
mkdir -p "$work/ssh" "$work/home/.ssh" "$work/privsep" "$work/ros_agents"
ssh-keygen -q -t ed25519 -N '' -f "$work/ssh/host_key"
ssh-keygen -q -t ed25519 -N '' -f "$work/home/.ssh/id_ed25519"
cp "$work/home/.ssh/id_ed25519.pub" "$work/ssh/authorized_keys"
echo "$agents_ip $(cut -d' ' -f1,2 "$work/ssh/host_key.pub")" > "$work/home/.ssh/known_hosts"
cp /etc/passwd "$work/ssh/passwd"
getent passwd sshd > /dev/null || echo "sshd:x:64999:65534::/run/sshd:/usr/sbin/nologin" >> "$work/ssh/passwd"
cat > "$work/ssh/sshd_config" <<EOF
ListenAddress $agents_ip:22
HostKey $work/ssh/host_key
AuthorizedKeysFile $work/ssh/authorized_keys
PermitRootLogin prohibit-password
StrictModes no
UsePAM no
PidFile none
SetEnv ROS_IP=$agents_ip ROS_HOME=$work/ros_agents
EOF
in_agents unshare --mount /bin/bash -c "mount --bind '$work/ssh/passwd' /etc/passwd && mount -t tmpfs tmpfs /run \
  && mkdir -m 755 /run/sshd && exec '$sshd' -D -e -f '$work/ssh/sshd_config'" > "$work/sshd.log" 2>&1 &
for _ in $(seq 1 100); do in_agents ss -Hltn | grep -q "$agents_ip:22 " && break; sleep 0.05; done
in_agents ss -Hltn | grep -q "$agents_ip:22 " && pass || { fail "sshd did not start: $(cat "$work/sshd.log")"; finish; exit; }

# A small experiment: one evolved set, every agent (and a planner with its bridge) on the agents' host.
cat > "$work/experiment.yaml" <<EOF
seed: 11
runs: 300
agents:
  - {name: astar, type: astar, host: $agents_ip}
  - {name: explorer, type: explorer, host: $agents_ip}
  - {name: wall_follower_left, type: wall_follower_left, host: $agents_ip}
  - {name: optimistic, type: planner, host: $agents_ip, planner_node: ppp_agents/optimistic_planner_node, runs: 1}
sets:
  - name: mine
    generator: {fitness: turns, population: 8, matings: 100, seed: 6}
EOF
cp "$root/config/generator.yaml" "$work/"
"$devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null 2>&1
built_in_rows=$((8 * 3 * 300))
planner_rows=8

# launch DIR: the experiment through roslaunch in the master's namespace, in the background ($launched).
launch() {
  local dir="$1"; shift
  in_master env HOME="$work/home" ROS_HOME="$work/ros_master" ROS_IP="$master_ip" \
    ROS_MASTER_URI="http://$master_ip:11311" timeout 600 roslaunch -p 11311 "$root/launch/experiment.launch" \
    output_dir:="$dir" config:="$work/experiment.yaml" args:="--batch-size 100 --step-timeout 2" > "$dir.log" 2>&1 &
  launched=$!
}
# built_in DIR: DIR/results.csv without the planner's rows.
built_in() { grep -v ",optimistic," "$1/results.csv"; }
# lost DIR: how many rows of DIR/results.csv are runs lost to the link.
lost() { grep -c ",agent_lost,[01],\|,timeout,[01]," "$1/results.csv"; }

# 1. Across the link: the agents' processes run in the agents' namespace, the results are ppp experiment's.
launch "$work/whole"
remote=""
for _ in $(seq 1 1200); do
  remote="$(for pid in $(ip netns pids "$agents_ns"); do cat "/proc/$pid/comm" 2> /dev/null; done | sort | uniq -c \
    | tr -s ' ' | tr '\n' ' ')"
  case "$remote" in *"3 agent_node"*optimistic_plan*planner_bridge*) break ;; esac
  sleep 0.05
done
case "$remote" in
  *"3 agent_node"*optimistic_plan*planner_bridge*) pass ;;
  *) fail "the agents' nodes did not start in the agents' namespace (there: $remote): $(tail -20 "$work/whole.log")" ;;
esac
wait "$launched"
built_in "$work/whole" | cmp -s - "$work/cli/results.csv" && pass || \
  fail "the run across the link differs from ppp experiment: $(grep -i "error\|fail" "$work/whole.log" | head)"
[ "$(grep -c ",optimistic,.*,goal_reached,[01]," "$work/whole/results.csv")" -eq "$planner_rows" ] && pass || \
  fail "the planner did not pass its $planner_rows runs: $(grep ",optimistic," "$work/whole/results.csv")"

# 2. The link is cut once the first results are in: the lost runs are recorded and the experiment completes.
launch "$work/cut"
for _ in $(seq 1 2400); do
  [ -f "$work/cut/results.csv" ] && [ "$(wc -l < "$work/cut/results.csv")" -gt 50 ] && break
  sleep 0.05
done
in_agents ip link set "$agents_link" down
cut_at=$(($(wc -l < "$work/cut/results.csv") - 1))
cut_time=$(date +%s.%N)
for _ in $(seq 1 1200); do
  grep -q "experiment done" "$work/cut.log" && break
  sleep 0.1
done
grep -q "experiment done" "$work/cut.log" && pass || fail "the experiment did not complete without its agents: $(tail -20 "$work/cut.log")"
done_time=$(date +%s.%N)
# roslaunch's shutdown of the agents' host waits for the link: bring it back for that.
in_agents ip link set "$agents_link" up
wait "$launched"
mv "$work/cut.log" "$work/cut_first.log"
rows=$(($(wc -l < "$work/cut/results.csv") - 1))
[ "$rows" -eq $((built_in_rows + planner_rows)) ] && pass || \
  fail "the cut run recorded $rows rows, expected $((built_in_rows + planner_rows)) (cut after $cut_at)"
lost_runs=$(lost "$work/cut")
[ "$lost_runs" -gt 0 ] && [ "$cut_at" -lt $((built_in_rows + planner_rows)) ] && pass || \
  fail "the cut came too late: $cut_at rows before it, $lost_runs lost"
echo "cut after $cut_at of $rows runs: $lost_runs recorded as lost; the experiment completed" \
  "$(awk -v a="$cut_time" -v b="$done_time" 'BEGIN { printf "%.1f", b - a }') s after the cut"

# 3. The link is back: the rerun plays the lost runs again and completes the results.
launch "$work/cut"
wait "$launched"
grep -q "$lost_runs lost to the agent link played again" "$work/cut.log" && pass || \
  fail "the rerun did not play the $lost_runs lost runs again: $(grep "running" "$work/cut.log")"
[ "$(lost "$work/cut")" -eq 0 ] && pass || fail "runs still lost after the rerun: $(lost "$work/cut")"
built_in "$work/cut" | cmp -s - "$work/cli/results.csv" && pass || \
  fail "the resumed run differs from ppp experiment: $(tail -20 "$work/cut.log")"
[ "$(grep -c ",optimistic," "$work/cut/results.csv")" -eq "$planner_rows" ] && pass || \
  fail "the planner's rows: $(grep -c ",optimistic," "$work/cut/results.csv"), expected $planner_rows"
finish
