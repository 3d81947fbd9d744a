#!/usr/bin/env bash
# Headless picture of a bag in rviz with the shipped view (launch/ppp.rviz):
#   scripts/rviz-screenshot.sh BAG OUT.png [SECONDS]
# Under a virtual X server (xvfb-run) it starts a private roscore on a free port, `rosbag play --clock -l BAG`
# and rviz, waits until rviz has subscribed to /map (at most 60 s), lets it render for SECONDS (default 5),
# grabs the screen with ImageMagick's import, and stops everything it started. Needs: rviz xvfb xauth
# imagemagick (scripts/install-deps.sh). Check the picture with scripts/check_screenshot.py OUT.png.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"

if [ $# -lt 2 ] || [ $# -gt 3 ]; then
  echo "usage: $0 BAG OUT.png [SECONDS]" >&2
  exit 2
fi
bag="$(realpath "$1")"
out="$(realpath -m "$2")"
seconds="${3:-5}"
[ -f "$bag" ] || { echo "rviz-screenshot: no bag at $1" >&2; exit 2; }
[[ "$seconds" =~ ^[0-9]+([.][0-9]+)?$ ]] || { echo "rviz-screenshot: SECONDS must be a number, got '$seconds'" >&2; exit 2; }
mkdir -p "$(dirname "$out")"

# Re-run this script inside a virtual X server (-a: a free display number).
if [ -z "${PPP_RVIZ_SCREENSHOT_IN_XVFB:-}" ]; then
  exec env PPP_RVIZ_SCREENSHOT_IN_XVFB=1 xvfb-run -a -s "-screen 0 1280x960x24" "$0" "$bag" "$out" "$seconds"
fi

work="$(mktemp -d)"
pids=()
cleanup() {
  local pid
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null || true; done
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -KILL "$pid" 2>/dev/null || true
    wait "$pid" 2>/dev/null || true
  done
  rm -rf "$work"
}
trap cleanup EXIT
trap 'exit 130' INT TERM

# A private master on a free loopback port; logs in a scratch ROS_HOME.
port="$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
export ROS_MASTER_URI="http://127.0.0.1:$port" ROS_IP=127.0.0.1 ROS_HOME="$work/ros"
roscore -p "$port" > "$work/roscore.log" 2>&1 &
pids=("$!" "${pids[@]}")
for _ in $(seq 100); do rosparam set /use_sim_time true 2>/dev/null && break; sleep 0.2; done
rosparam get /use_sim_time > /dev/null 2>&1 || { cat "$work/roscore.log" >&2; echo "rviz-screenshot: roscore did not start" >&2; exit 1; }

rviz -d "$PPP_ROOT/launch/ppp.rviz" > "$work/rviz.log" 2>&1 &
pids=("$!" "${pids[@]}")
rosbag play --clock -l -q "$bag" > "$work/rosbag.log" 2>&1 &
pids=("$!" "${pids[@]}")

ready=""
for _ in $(seq 300); do
  if rostopic info /map 2>/dev/null | sed -n '/^Subscribers:/,$p' | grep -q rviz; then ready=1; break; fi
  kill -0 "${pids[1]}" 2>/dev/null || break  # rviz died
  sleep 0.2
done
if [ -z "$ready" ]; then
  cat "$work/rviz.log" >&2
  echo "rviz-screenshot: rviz did not subscribe to /map within 60 s" >&2
  exit 1
fi
sleep "$seconds"
/usr/bin/import -window root "$out"
[ -s "$out" ] || { echo "rviz-screenshot: no picture written to $out" >&2; exit 1; }
echo "rviz-screenshot: wrote $out"
