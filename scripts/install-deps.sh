#!/usr/bin/env bash
# Installs, from Debian's own archive, whatever PPP Lab needs that is not yet installed. Idempotent:
# when everything is present it changes nothing and takes well under a second.
set -euo pipefail

packages=(
  # build tools
  cmake g++ make pkg-config
  # ROS 1 as Debian ships it: catkin, roscpp, rospy, rosbag, roslaunch, message generation
  ros-core-dev python3-rostest rosbash libtf2-ros-dev
  # nodelets: the headers and library (-dev), and the nodelet manager with the package.xml pluginlib needs to
  # find any nodelet (-tools, which the -dev package does not pull in)
  libnodeletlib-dev libnodeletlib-tools
  python3-diagnostic-msgs python3-nav-msgs python3-geometry-msgs python3-sensor-msgs
  python3-visualization-msgs python3-tf2-msgs
  # a local planner giving up (actionlib_msgs/GoalStatus on planner_status)
  libactionlib-msgs-dev python3-actionlib-msgs
  # the example planners: OMPL (sampling-based planning)
  libompl-dev
  # the MRPT example planner: MRPT's navigation library (its wavefront planner for circular robots)
  libmrpt-nav-dev
  # rviz, headless under a virtual X server, screenshots and their check
  rviz xvfb xauth imagemagick python3-pil
  # headless rviz videos of a bag (screen capture, encoding, ffprobe's checks)
  ffmpeg
  # libraries the core and the tools use
  libpng-dev libgif-dev libyaml-cpp-dev liboctomap-dev libeigen3-dev nlohmann-json3-dev libcli11-dev
  # a network namespace of its own for the main command (unshare, ip) and the sockets check (ss); the
  # multi-machine test's second host: ssh keys, and the library Debian's sshd (unpacked below) needs
  util-linux iproute2 openssh-client libwrap0
  # tests, benchmarks and the fuzzer; valgrind sees MRPT's out-of-bounds write
  libgtest-dev libbenchmark-dev clang libclang-rt-14-dev valgrind
  # peak memory in the scale benchmark (/usr/bin/time)
  time
  # scripts/seed_spread.py reads experiment YAML
  python3-yaml
)

# The multi-machine test runs Debian's sshd inside a network namespace of its own. Installing openssh-server
# would start an ssh service on the machine, so its package is only unpacked, into the build directory.
sshd_dir="${PPP_BUILD_DIR:-$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)/build}/sshd"
unpack_sshd() {
  [ -x "$sshd_dir/usr/sbin/sshd" ] && return 0
  local download
  download="$(mktemp -d)"
  chmod 755 "$download"  # apt fetches as its own user
  (cd "$download" && apt-get download -q openssh-server > /dev/null 2>&1) || \
    { apt-get update -q > /dev/null && (cd "$download" && apt-get download -q openssh-server > /dev/null); } || {
    echo "install-deps: cannot download openssh-server (for the multi-machine test)" >&2
    rm -rf "$download"
    return 1
  }
  mkdir -p "$sshd_dir"
  dpkg-deb -x "$download"/openssh-server_*.deb "$sshd_dir"
  rm -rf "$download"
  echo "install-deps: unpacked Debian's sshd into $sshd_dir (not installed as a service)"
}

missing=()
for package in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  unpack_sshd
  exit
fi

echo "install-deps: installing ${missing[*]}"
sudo_cmd=()
if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -q
"${sudo_cmd[@]}" apt-get install -y -q --no-install-recommends "${missing[@]}"
unpack_sshd
