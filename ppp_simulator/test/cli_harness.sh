# Shared harness of the `ppp` command-line tests; source it from a test script. It makes $work, a temporary
# directory removed on exit (background jobs still running then are killed), and counts checks:
#   pass / fail MESSAGE        count one check (fail prints MESSAGE)
#   expect_ok NAME COMMAND...  the command exits 0 (its output is in $work/out and $work/err)
#   expect_error NAME TEXT COMMAND...  the command exits non-zero and stderr contains TEXT
#   finish                     prints "N passed, N failed"; its status is the script's result
#   small_experiment RUNS      writes $work/experiment.yaml (and its agents.yaml): 2 evolved sets x 6 small PPPs
#                              x 3 agents x RUNS runs
#   same_sets DIR DIR          two set directories hold the same files, evaluations.csv's wall times aside
#   mount_tmpfs SIZE           mounts a tmpfs of SIZE (e.g. 16m) on $mnt=$work/mnt, unmounted on exit; where it
#                              cannot (no root), says the test is skipped and exits 77
work="$(mktemp -d)"
trap 'kill -9 $(jobs -p) 2>/dev/null; rm -rf "$work"' EXIT
passed=0
failed=0

pass() { passed=$((passed + 1)); }
same_sets() {
  diff -r -x evaluations.csv "$1" "$2" > /dev/null || return 1
  [ -f "$1/evaluations.csv" ] || [ ! -f "$2/evaluations.csv" ] || return 1
  [ ! -f "$1/evaluations.csv" ] || cmp -s <(cut -d, -f1,3- "$1/evaluations.csv") <(cut -d, -f1,3- "$2/evaluations.csv")
}
fail() { failed=$((failed + 1)); echo "FAIL: $*"; }

expect_ok() {
  local name="$1"; shift
  if "$@" > "$work/out" 2> "$work/err"; then pass; else fail "$name: exit $? $(tail -5 "$work/err")"; fi
}

expect_error() {
  local name="$1" text="$2"; shift 2
  if "$@" > "$work/out" 2> "$work/err"; then fail "$name: succeeded, expected an error"; return; fi
  if grep -qF -- "$text" "$work/err"; then pass; else fail "$name: error lacks '$text': $(cat "$work/err")"; fi
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" -eq 0 ]
}

small_experiment() {
  cat > "$work/agents.yaml" <<'YAML'
agents:
  - {name: random, type: random}
  - {name: explorer_memory_5x5, type: explorer, memory: 5x5}
  - {name: long_term_explorer, type: long_term_explorer}
YAML
  cat > "$work/experiment.yaml" <<YAML
seed: 9
runs: $1
threads: 2
hardest: 2
agents: agents.yaml
sets:
  - name: turns
    generator: {fitness: turns, population: 6, matings: 200, width: 14, height: 14, seed: 3}
  - name: difficulty
    generator: {fitness: difficulty, population: 6, matings: 200, width: 14, height: 14, seed: 4}
YAML
}

mount_tmpfs() {
  mnt="$work/mnt"
  mkdir "$mnt"
  if ! mount -t tmpfs -o "size=$1" ppp-test "$mnt" 2> "$work/mount.err"; then
    echo "SKIPPED: cannot mount a tmpfs here: $(cat "$work/mount.err")"
    rm -rf "$work"
    exit 77
  fi
  trap 'kill -9 $(jobs -p) 2>/dev/null; umount -R "$mnt"; rm -rf "$work"' EXIT
}
