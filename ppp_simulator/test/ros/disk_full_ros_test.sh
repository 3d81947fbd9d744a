#!/usr/bin/env bash
# roslaunch launch/experiment.launch on an output directory that fills up mid-run (a small tmpfs): the simulator
# (a nodelet) logs the error naming results.csv and the system's reason and ends the experiment with status 1
# (roslaunch ends instead of hanging), results.csv holds whole rows only, and after space returns a rerun resumes to `ppp experiment`'s
# results. Needs root for the mount; exits 77 (skipped) where it cannot mount. Usage: disk_full_ros_test.sh DEVEL_DIR
source "$(dirname "${BASH_SOURCE[0]}")/ros_harness.sh"
mount_tmpfs 4m
out="$mnt/out"

# 6 PPPs x 2 agents x 300 runs: results.csv of 260 KB, of which about 170 KB fit.
cat > "$work/experiment.yaml" <<'YAML'
seed: 5
runs: 300
agents:
  - {name: astar, type: astar}
  - {name: explorer, type: explorer}
sets:
  - name: mine
    generator: {fitness: advances, population: 6, matings: 50, seed: 4}
YAML
launch() {
  timeout -s KILL 120 roslaunch -p "$port" "$root/launch/experiment.launch" output_dir:="$out" \
    config:="$work/experiment.yaml" args:="--record false" > "$1" 2>&1
}
avail=$(( $(stat -f -c '%a * %S' "$mnt") ))
head -c $((avail - 300000)) /dev/zero > "$mnt/filler"
launch "$work/full.log"
[ $? -ne 137 ] && pass || fail "roslaunch hung on a full disk"
grep -aq "\[FATAL\].*simulator: $out/results.csv: cannot append [0-9]* bytes: No space left on device" "$work/full.log" && pass \
  || fail "no error naming results.csv and the reason: $(grep -a "FATAL\|ERROR" "$work/full.log")"
# The simulator nodelet's status 1 is the launcher's (its manager exits 0 once the nodelet shut it down).
grep -aq "process has died \[pid [0-9]*, exit code 1, cmd [^ ]*experiment_launcher" "$work/full.log" && pass \
  || fail "the simulator did not end the experiment with status 1: $(grep -a "died" "$work/full.log")"
awk -F, 'NR == 1 { n = NF } NF != n { exit 1 } END { exit NR < 2 }' "$out/results.csv" && \
  [ "$(tail -c 1 "$out/results.csv" | od -An -c | tr -d ' ')" = '\n' ] && pass || fail "results.csv holds a torn row"
[ "$(wc -l < "$out/results.csv")" -lt 3601 ] && pass || fail "the disk filled too late to test anything"

rm "$mnt/filler"
launch "$work/rerun.log"
grep -aq "running [0-9]* episodes ([1-9][0-9]* already done" "$work/rerun.log" && pass \
  || fail "the rerun did not resume: $(grep -a "running\|FATAL" "$work/rerun.log")"
"$devel/lib/ppp_simulator/ppp" experiment "$work/experiment.yaml" -o "$work/cli" --quiet > /dev/null 2>&1
cmp -s "$work/cli/results.csv" "$out/results.csv" && pass || fail "results after the full disk differ from ppp experiment's"

finish
