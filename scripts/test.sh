#!/usr/bin/env bash
# The test command: installs what is missing, builds everything and runs every test.
# Exits non-zero if any step or any test fails.
set -uo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
cd "$PPP_ROOT"

failures=()
passed_steps=0
step() {
  local name="$1"; shift
  local started=$SECONDS
  echo "=== $name"
  if "$@"; then
    echo "=== $name: ok in $((SECONDS - started)) s"
    passed_steps=$((passed_steps + 1))
  else
    echo "=== $name: FAILED in $((SECONDS - started)) s"
    failures+=("$name")
  fi
}

scripts/install-deps.sh || { echo "install failed"; exit 1; }
echo "=== install what is missing: ok in $SECONDS s"
step "build workspace" scripts/build.sh
step "build tests" cmake --build "$PPP_BUILD_DIR" --target tests -j "$(nproc)"
# One test more than there are cores: two at a time left the CPU idle 18 % of the time while tests waited (a
# planner's timeout, a late node, a network namespace's link, roslaunch starting).
step "workspace tests (ctest)" ctest --test-dir "$PPP_BUILD_DIR" --output-on-failure -j "$(($(nproc) + 1))"

# The core must build and pass its tests with no ROS at all: catkin is never looked for, and
# #error stand-ins for ROS headers come first on the include path.
core_dir="$PPP_ROOT/build-core"
step "configure core without ROS" cmake -S src -B "$core_dir" -DPPP_CORE_FORBID_ROS=ON -DPPP_CORE_BENCHMARKS=OFF \
  -DCMAKE_BUILD_TYPE=Release
step "build core without ROS" cmake --build "$core_dir" -j "$(nproc)"
step "core tests without ROS (ctest)" ctest --test-dir "$core_dir" --output-on-failure -j "$(nproc)"

step "fuzz every parser target (20 s each)" scripts/fuzz.sh 20

echo
[ ${#failures[@]} -eq 0 ] || echo "test.sh: FAILED steps: ${failures[*]}"
echo "test.sh: $passed_steps passed, ${#failures[@]} failed in $SECONDS s"
[ ${#failures[@]} -eq 0 ]
