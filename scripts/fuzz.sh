#!/usr/bin/env bash
# Builds the libFuzzer targets of the parsers with clang (ASan + UBSan) in build-fuzz/ (ppp_simulator/fuzz's
# project) and runs each for a bounded time: scripts/fuzz.sh [SECONDS] [TARGET...] (default 30 s each, every
# target), or for a number of executions: scripts/fuzz.sh --runs N [TARGET...] (the long campaigns in
# BENCHMARKS.md). Targets: ppp_parser (.ppp files), map_yaml (map_server YAML + PGM), movingai_map (MovingAI .map grid
# maps), movingai_scen (MovingAI .scen scenario lists), newick (taxonomy trees), generator_yaml (generator options),
# set_csv (a set directory's set.csv), agents_yaml (agents lists), experiment_yaml (experiment configs), results_csv
# (the results a resume reads), and the batch protocol's scan_batch (ROS-serialised ScanBatch messages as the agent
# node decodes and answers them) and move_batch (MoveBatch messages as the simulator decodes and applies them), which
# need the ppp_msgs headers of the workspace build ($PPP_BUILD_DIR/devel/include: scripts/build.sh). Each has a seed
# corpus in its package's fuzz/corpus/TARGET/. Inputs are at most 4096 bytes (configs, CSV files, messages and maps
# far larger than their seeds, which keeps the YAML readers fast), 65536 for the .ppp, .map and Newick readers (large
# grids and trees).
# Exits non-zero on any finding; crash inputs are written to build-fuzz/artifacts/TARGET/. Reproduce one with:
# build-fuzz/TARGET_fuzz build-fuzz/artifacts/TARGET/crash-...
set -euo pipefail

all_targets=(ppp_parser map_yaml movingai_map movingai_scen newick generator_yaml set_csv agents_yaml experiment_yaml
  results_csv scan_batch move_batch)
ros_targets=(scan_batch move_batch)
usage="usage: $0 [SECONDS | --runs N] [TARGET...]  (a positive whole number of seconds, default 30, or of
  executions per target; targets: ${all_targets[*]})"
runs=""
if [[ "${1:-}" == "--runs" ]]; then
  runs="${2:-}"
  if ! [[ "${runs}" =~ ^[1-9][0-9]*$ ]]; then
    echo "${usage}" >&2
    exit 2
  fi
  shift 2
  limit=(-runs="${runs}")
  budget="${runs} executions"
else
  seconds="${1:-30}"
  if ! [[ "${seconds}" =~ ^[1-9][0-9]*$ ]]; then
    echo "${usage}" >&2
    exit 2
  fi
  shift || true
  limit=(-max_total_time="${seconds}")
  budget="${seconds} s"
fi
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=("${all_targets[@]}")

source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "${PPP_ROOT}"

build_dir=build-fuzz
clangxx="$(command -v clang++ || true)"
if [[ -z "${clangxx}" ]]; then
  echo "fuzz.sh: clang++ not found (libFuzzer needs clang)" >&2
  exit 2
fi

# corpus_of TARGET: its seed corpus directory.
corpus_of() { ls -d src/fuzz/corpus/"$1" ppp_*/fuzz/corpus/"$1" 2> /dev/null | head -1; }
for target in "${targets[@]}"; do
  if [ -z "$(corpus_of "${target}")" ]; then
    echo "fuzz.sh: unknown target '${target}'; targets: ${all_targets[*]}" >&2
    exit 2
  fi
done
# The protocol targets decode messages with the headers catkin generates from ppp_msgs/msg.
msgs_include="${PPP_BUILD_DIR}/devel/include"
[ -f "${msgs_include}/ppp_msgs/ScanBatch.h" ] || msgs_include=""
for target in "${targets[@]}"; do
  if [[ " ${ros_targets[*]} " == *" ${target} "* && -z "${msgs_include}" ]]; then
    echo "fuzz.sh: ${target} needs the generated ppp_msgs headers, and ${PPP_BUILD_DIR}/devel/include/ppp_msgs/" \
      "holds none: build the workspace first (scripts/build.sh)" >&2
    exit 2
  fi
done
# max_len_of TARGET: the largest input it is given.
max_len_of() { case "$1" in ppp_parser | movingai_map | newick) echo 65536 ;; *) echo 4096 ;; esac; }
if [ -f "${build_dir}/CMakeCache.txt" ] && ! grep -q "CMAKE_PROJECT_NAME:STATIC=ppp_fuzz" "${build_dir}/CMakeCache.txt"; then
  rm -rf "${build_dir}"  # an older build of the core alone
fi
cmake -S ppp_simulator/fuzz -B "${build_dir}" -DCMAKE_CXX_COMPILER="${clangxx}" -DCMAKE_BUILD_TYPE=Release \
  -DCMAKE_CXX_FLAGS_RELEASE="-O1 -DNDEBUG" \
  -DPPP_MSGS_INCLUDE_DIR="${msgs_include}" >/dev/null
cmake --build "${build_dir}" --target $(printf '%s_fuzz ' "${targets[@]}") -j2

# fuzz_one TARGET: runs it for the budget and prints its figures; on a finding, the end of its log and the inputs,
# and fails with libFuzzer's status.
fuzz_one() {
  local target="$1" corpus="${build_dir}/corpus/$1" artifacts="${build_dir}/artifacts/$1" status=0
  mkdir -p "${corpus}" "${artifacts}"
  cp "$(corpus_of "${target}")"/* "${corpus}/"
  echo "fuzzing ${target} for ${budget} (corpus ${corpus}, findings in ${artifacts})"
  # Without allocation stacks in the reports (about a third more executions of the allocation-heavy YAML readers);
  # reproducing a finding (see the top of this file) shows them.
  ASAN_OPTIONS="malloc_context_size=0${ASAN_OPTIONS:+:${ASAN_OPTIONS}}" "${build_dir}/${target}_fuzz" \
    "${limit[@]}" -timeout=5 -rss_limit_mb=2048 -max_len="$(max_len_of "${target}")" \
    -print_final_stats=1 -artifact_prefix="${artifacts}/" "${corpus}" 2> "${build_dir}/${target}.log" || status=$?
  grep -E "stat::(number_of_executed_units|average_exec_per_sec)" "${build_dir}/${target}.log" | sed "s/^/${target}: /" || true
  if [[ ${status} -ne 0 ]]; then
    tail -40 "${build_dir}/${target}.log"
    echo "fuzz.sh: FINDING in ${target} (libFuzzer exit ${status}); inputs in ${artifacts}/:"
    ls -l "${artifacts}" || true
  fi
  return "${status}"
}

# As many targets at once as there are cores (each fuzzer is one process): every target still gets its whole
# budget on a core of its own. Each target's output is shown when it ends, a finding's on stderr.
pids=()
for target in "${targets[@]}"; do
  while [ "$(jobs -rp | wc -l)" -ge "$(nproc)" ]; do wait -n || true; done
  fuzz_one "${target}" > "${build_dir}/${target}.out" 2>&1 &
  pids+=($!)
done
first_status=0
for i in "${!targets[@]}"; do
  status=0
  wait "${pids[$i]}" || status=$?
  if [[ ${status} -eq 0 ]]; then
    cat "${build_dir}/${targets[$i]}.out"
  else
    cat "${build_dir}/${targets[$i]}.out" >&2
    [[ ${first_status} -ne 0 ]] || first_status=${status}
  fi
done
[[ ${first_status} -eq 0 ]] || exit "${first_status}"
echo "fuzz.sh: no findings in ${budget} per target (${targets[*]})"
