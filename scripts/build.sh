#!/usr/bin/env bash
# Configures and builds the whole catkin workspace (Release) into build/.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
mkdir -p "$PPP_BUILD_DIR"
cmake -S "$PPP_ROOT" -B "$PPP_BUILD_DIR" -DCMAKE_BUILD_TYPE=Release > "$PPP_BUILD_DIR/configure.log" 2>&1 || {
  cat "$PPP_BUILD_DIR/configure.log"
  exit 1
}
cmake --build "$PPP_BUILD_DIR" -j "$(nproc)"
