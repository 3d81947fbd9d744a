#!/usr/bin/env bash
# A real SIGINT or SIGTERM while `ppp experiment` writes its report: it stops within a second (exit 130) and
# leaves no half-written file; a rerun writes the report of an uninterrupted run, byte for byte. Also a SIGINT
# while a rerun reads a large results.csv to resume: it stops within a second and leaves the file as it was.
# Usage: report_signal_test.sh PATH_TO_PPP
set -u
ppp="$1"
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"

# Eighty 100x100 PPPs, each pictured and its failing run animated (the report's largest animated maps): the
# report takes some 2 s to replay, animate, render and write (the animations most of it), the runs (2 agents x
# 2 runs per PPP) next to nothing.
cat > "$work/experiment.yaml" <<'YAML'
seed: 2
runs: 2
threads: 2
hardest: 80
agents:
  - {name: random, type: random}
  - {name: explorer, type: explorer}
sets:
  - name: big
    generator: {fitness: turns, population: 80, matings: 40, width: 100, height: 100, seed: 3}
YAML
report_files="summary.csv report.md report.html plots pictures ppps"
expect_ok "uninterrupted experiment" "$ppp" experiment "$work/experiment.yaml" -o "$work/ref" --quiet
cp -r "$work/ref" "$work/d"

# signal_in_report SIGNAL DELAY: removes the report, reruns the finished experiment (which then only writes the
# report), signals it DELAY seconds after it says it writes the report; prints its exit status and the
# milliseconds from the signal to its exit.
signal_in_report() {
  local signal="$1" delay="$2"
  (cd "$work/d" && rm -rf $report_files)
  "$ppp" experiment "$work/experiment.yaml" -o "$work/d" > /dev/null 2> "$work/report.err" &
  local pid=$!
  for _ in $(seq 1 3000); do grep -q "^writing the report" "$work/report.err" && break; sleep 0.01; done
  sleep "$delay"
  local start; start=$(date +%s%N)
  kill "-$signal" "$pid"
  wait "$pid"
  local status=$?
  echo "$status $(( ($(date +%s%N) - start) / 1000000 ))"
}
for case in "INT 0.05" "TERM 0.15"; do
  read -r signal delay <<< "$case"
  read -r status ms <<< "$(signal_in_report "$signal" "$delay")"
  [ "$status" -eq 130 ] && pass || fail "SIG$signal $delay s into the report: exit status $status, expected 130"
  [ "$ms" -le 1000 ] && pass || fail "SIG$signal $delay s into the report: stopped $ms ms after the signal"
  [ ! -e "$work/d/report.html" ] && pass || fail "SIG$signal $delay s into the report: the report was finished"
  grep -q "Rerun the same command to resume" "$work/report.err" && pass \
    || fail "SIG$signal message: $(tail -2 "$work/report.err")"
  [ -z "$(find "$work/d" -name '*.tmp')" ] && pass || fail "SIG$signal left $(find "$work/d" -name '*.tmp')"
done

expect_ok "rerun after the signals" "$ppp" experiment "$work/experiment.yaml" -o "$work/d" --quiet
for f in results.csv $report_files; do
  diff -r "$work/ref/$f" "$work/d/$f" > /dev/null && pass || fail "$f after the interrupted reports differs"
done

# Two million rows to read before resuming (some 5 s); SIGINT half a second into reading them.
cp -r "$work/ref" "$work/big"
awk 'NR == 1 { print; next } NR == 2 { for (i = 0; i < 2000000; ++i) print }' "$work/ref/results.csv" \
  > "$work/big/results.csv"
printf 'half,a,row' >> "$work/big/results.csv"
cp "$work/big/results.csv" "$work/big.csv"
"$ppp" experiment "$work/experiment.yaml" -o "$work/big" > /dev/null 2> "$work/resume.err" &
pid=$!
for _ in $(seq 1 3000); do grep -q "^reading the runs already in" "$work/resume.err" && break; sleep 0.01; done
sleep 0.5
start=$(date +%s%N)
kill -INT "$pid"
wait "$pid"
status=$?
ms=$(( ($(date +%s%N) - start) / 1000000 ))
[ "$status" -eq 130 ] && pass || fail "SIGINT while reading results.csv: exit $status, expected 130 ($(tail -2 "$work/resume.err"))"
[ "$ms" -le 1000 ] && pass || fail "SIGINT while reading results.csv: stopped $ms ms after the signal"
echo "resume read: exit $status after $ms ms"
cmp -s "$work/big.csv" "$work/big/results.csv" && pass || fail "SIGINT while reading results.csv changed the file"

finish
