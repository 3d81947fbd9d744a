# Sourced by the other scripts: repository root, Debian's python first on PATH, loopback-only ROS.
# shellcheck shell=bash
PPP_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
export PPP_ROOT
export PATH="/usr/bin:/bin:$PATH"
export PPP_BUILD_DIR="${PPP_BUILD_DIR:-$PPP_ROOT/build}"
export ROS_IP=127.0.0.1

# Sources the built workspace's setup script, in a function so that catkin's script sees none of the caller's
# arguments (sourced at the top level it would take `--help` ... as its own options).
load_workspace() {
  set +u  # setup.bash reads unset variables
  source "$PPP_BUILD_DIR/devel/setup.bash"
  set -u
}
