# Shared start of the ROS command-line tests: sources the workspace (DEVEL_DIR, the script's first argument),
# the cli_harness, and points ROS at a private master on a free port with ROS_HOME in $work; sets $devel and
# $root (the repository) and $port, and defines started LOG.
devel="$1"
source "$devel/setup.bash"  # before set -u: setup.bash reads unset variables
set -u
source "$(dirname "${BASH_SOURCE[0]}")/../cli_harness.sh"
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/../../.." && pwd)"
export PATH="/usr/bin:$PATH"
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1 ROS_HOME="$work/ros"

# started LOG: the processes roslaunch started (both the entry's and the experiment graph's), sorted.
started() { sed -n 's/.*process\[\([A-Za-z0-9_]*\)-[0-9]*\]: started with pid.*/\1/p' "$1" | sort | tr '\n' ' '; }
