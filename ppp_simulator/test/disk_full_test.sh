#!/usr/bin/env bash
# `ppp experiment` on an output directory that fills up or turns read-only mid-experiment (a small tmpfs, a
# read-only bind mount): each fault stops it with an error naming the file and the system's reason, no signal,
# no hang, no torn row in results.csv; once the space or the write access is back, a rerun resumes and ends
# with the results.csv, summary and report of an uninterrupted run. Needs root for the mounts; exits 77
# (skipped) where it cannot mount. Usage: disk_full_test.sh PATH_TO_PPP
set -u
ppp="$1"
source "$(dirname "${BASH_SOURCE[0]}")/cli_harness.sh"
mount_tmpfs 16m
out="$mnt/out"

# 2 sets x 6 PPPs x 3 agents x 1000 runs: results.csv of about 3 MB, appended in 36 blocks of 1000 rows.
small_experiment 1000
# The same with 5 runs: results.csv (16 KB) smaller than the report, so the disk can fill while it is written.
sed 's/^runs: 1000$/runs: 5/' "$work/experiment.yaml" > "$work/small.yaml"

expect_ok "reference run" "$ppp" experiment "$work/experiment.yaml" -o "$work/ref" --quiet
expect_ok "small reference run" "$ppp" experiment "$work/small.yaml" -o "$work/ref_small" --quiet

# Bytes a file takes on the tmpfs (whole 4 KiB pages), summed over the files given.
pages() { local total=0 f; for f in "$@"; do total=$((total + ($(stat -c %s "$f") + 4095) / 4096 * 4096)); done; echo "$total"; }
# leave_free BYTES: a filler file takes all of the tmpfs's free space but BYTES.
leave_free() {
  rm -f "$mnt/filler"
  local avail=$(( $(stat -f -c '%a * %S' "$mnt") ))
  head -c $((avail - $1)) /dev/zero > "$mnt/filler"
}
# The experiment's own files before the episodes (the sets, experiment.yaml).
before_results=$(pages "$work/ref/experiment.yaml" $(find "$work/ref/sets" -type f))
results_bytes=$(stat -c %s "$work/ref/results.csv")
small_results=$(pages "$work/ref_small/results.csv")

# attempt NAME CONFIG: runs the experiment on $out (killed after 120 s: a hang fails), output in $work/err.
attempt() {
  timeout -s KILL 120 "$ppp" experiment "$2" -o "$out" > "$work/out" 2> "$work/err"
  echo $?
}
# expect_fault NAME STATUS PATH_PATTERN REASON: a clean failure (exit status 1-127: no signal, no core) whose
# error names a file matching PATH_PATTERN (an extended regex, under $out) and the system's reason.
expect_fault() {
  local name="$1" status="$2" file="$3" reason="$4"
  [ "$status" -ge 1 ] && [ "$status" -lt 128 ] && pass || fail "$name: exit status $status, expected an error exit"
  grep -qE "^ppp: error: $out/$file: .*$reason" "$work/err" && pass \
    || fail "$name: error does not name $out/$file and '$reason': $(tail -3 "$work/err")"
}
# expect_whole_rows: results.csv (if any) holds whole rows only: it ends in a line break, every line has the
# header's fields.
expect_whole_rows() {
  local file="$out/results.csv"
  [ -f "$file" ] || { pass; return; }
  [ ! -s "$file" ] || [ "$(tail -c 1 "$file" | od -An -c | tr -d ' ')" = '\n' ] && pass \
    || fail "$1: results.csv ends in a torn row: $(tail -c 80 "$file")"
  awk -F, 'NR == 1 { n = NF } NF != n { exit 1 }' "$file" && pass || fail "$1: results.csv holds a torn row"
}
# expect_resumed NAME CONFIG REFERENCE [RESUMING]: a rerun ends with the reference's files; with RESUMING, it
# says it resumes runs already done.
expect_resumed() {
  local name="$1" config="$2" ref="$3" resuming="${4:-}"
  local status; status=$(attempt "$name" "$config")
  [ "$status" -eq 0 ] && pass || fail "$name: rerun exit status $status: $(tail -3 "$work/err")"
  [ -z "$resuming" ] || grep -q "^resuming: [0-9]* runs already done" "$work/err" && pass \
    || fail "$name: rerun did not resume: $(head -5 "$work/err")"
  local f
  for f in results.csv summary.csv report.md report.html sets/turns/set.csv sets/difficulty/set.csv; do
    cmp -s "$ref/$f" "$out/$f" && pass || fail "$name: $f differs from an uninterrupted run's"
  done
}

# 1. The disk fills while results.csv is appended: about half of its rows fit.
leave_free $((before_results + results_bytes / 2))
status=$(attempt "full while appending" "$work/experiment.yaml")
expect_fault "full while appending" "$status" "results.csv" "No space left on device"
expect_whole_rows "full while appending"
rows=$(wc -l < "$out/results.csv")
[ "$rows" -gt 1 ] && [ "$rows" -lt 36001 ] && pass || fail "full while appending: $rows lines in results.csv, expected part of 36001"
# 1b. Then the directory is read-only: the rerun fails on its first file, touching nothing.
rm "$mnt/filler"
cp "$out/results.csv" "$work/partial.csv"
mount --bind "$out" "$out" && mount -o remount,bind,ro "$out" || fail "cannot make $out read-only"
status=$(attempt "read-only directory" "$work/experiment.yaml")
expect_fault "read-only directory" "$status" "experiment.yaml" "Read-only file system"
umount "$out"
cmp -s "$work/partial.csv" "$out/results.csv" && pass || fail "the refused rerun changed results.csv"
expect_resumed "resume after a full disk" "$work/experiment.yaml" "$work/ref" resuming

# 2. The disk fills while the first set is written (experiment.yaml fits, the set does not).
rm -rf "$out"
leave_free 8192
status=$(attempt "full while writing a set" "$work/experiment.yaml")
expect_fault "full while writing a set" "$status" "sets/turns.partial/[a-z_0-9]+\.(csv|ppp|yaml)" "No space left on device"
[ ! -e "$out/sets/turns/set.csv" ] && [ ! -e "$out/results.csv" ] && pass || fail "full while writing a set: a set or results were written"
rm "$mnt/filler"
expect_resumed "resume after a full disk in a set" "$work/experiment.yaml" "$work/ref"

# 3. The disk fills while the summary and report are written: results.csv and its rewrite fit, the report not.
rm -rf "$out"
leave_free $((before_results + 2 * small_results + 8192))
status=$(attempt "full while writing the report" "$work/small.yaml")
expect_fault "full while writing the report" "$status" "(summary.csv|plots/.*|pictures/.*|ppps/.*|report.md|report.html)" \
  "No space left on device"
expect_whole_rows "full while writing the report"
rm "$mnt/filler"
expect_resumed "resume after a full disk in the report" "$work/small.yaml" "$work/ref_small" resuming

# 4. The directory turns read-only mid-episodes: runs already open results.csv go on (writing it in canonical
# order, so finishing leaves it alone), the first file written afterwards (summary.csv) fails.
rm -rf "$out"
"$ppp" experiment "$work/experiment.yaml" -o "$out" > "$work/out" 2> "$work/err" &
pid=$!
for _ in $(seq 1 1500); do
  [ -f "$out/results.csv" ] && [ "$(wc -l < "$out/results.csv")" -gt 4000 ] && break
  sleep 0.01
done
mount --bind "$out" "$out" && mount -o remount,bind,ro "$out" || fail "cannot make $out read-only"
timeout -s KILL 120 tail --pid="$pid" -f /dev/null
wait "$pid"
status=$?
expect_fault "read-only mid-episodes" "$status" "(results.csv|summary.csv)" "Read-only file system"
expect_whole_rows "read-only mid-episodes"
umount "$out"
expect_resumed "resume after a read-only directory" "$work/experiment.yaml" "$work/ref" resuming

finish
