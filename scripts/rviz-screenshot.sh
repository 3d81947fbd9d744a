#!/usr/bin/env bash
# Headless picture of a bag in rviz with the shipped view (launch/ppp.rviz):
#   scripts/rviz-screenshot.sh BAG OUT.png [SECONDS]
# Under a virtual X server (xvfb-run) it starts a private roscore on a free port, `rosbag play --clock -l BAG`
# and rviz, waits until rviz has subscribed to /map (at most 60 s), lets it render for SECONDS (default 5),
# grabs the screen with ImageMagick's import, and stops everything it started. A picture that does not show the
# map yet (scripts/check_screenshot.py: a loaded machine renders late) is grabbed again each second, at most 30
# times; the last one is kept either way. Needs: rviz xvfb xauth
# imagemagick (scripts/install-deps.sh). Check the picture with scripts/check_screenshot.py OUT.png.
# The set-up it shares with rviz-video.sh (xvfb-run, roscore, rviz, cleanup) is in rviz-headless.sh.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
source "$(dirname "${BASH_SOURCE[0]}")/rviz-headless.sh"
rviz_headless_name=rviz-screenshot

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

# Re-run this script inside a virtual X server; there: roscore, rviz, and the bag looped.
rviz_headless_xvfb "$bag" "$out" "$seconds"
rviz_headless_start
rosbag play --clock -l -q "$bag" > "$work/rosbag.log" 2>&1 &
rviz_headless_track "$!"
rviz_headless_wait_map

rviz_headless_sleep "$seconds"
for retry in $(seq 0 30); do
  [ "$retry" -eq 0 ] || rviz_headless_sleep 1
  /usr/bin/import -window root "$out"
  "$PPP_ROOT/scripts/check_screenshot.py" "$out" > /dev/null 2>&1 && break
done
[ -s "$out" ] || { echo "rviz-screenshot: no picture written to $out" >&2; exit 1; }
echo "rviz-screenshot: wrote $out"
