#!/usr/bin/env bash
# Part of check_install_space.sh, run in a clean environment:
#   run_from_install_space.sh PREFIX master:=PORT tcp_port:=PORT status_port:=PORT laser_port:=PORT
set -euo pipefail
PREFIX=$1; shift
declare -A port
for arg in "$@"; do port[${arg%%:=*}]=${arg##*:=}; done
set +u  # catkin's setup scripts read unset variables
source "$PREFIX/setup.bash"
set -u
export ROS_MASTER_URI=http://localhost:${port[master]} ROS_HOME=$(mktemp -d)
trap 'kill $(jobs -p) 2> /dev/null; wait 2> /dev/null; rm -rf "$ROS_HOME"' EXIT

pkg=$(rospack find amigobot_tracking)
case $pkg in "$PREFIX"/*) ;; *) echo "FAILED: rospack finds amigobot_tracking at $pkg, not in $PREFIX"; exit 1;; esac
echo "install space: roslaunch --nodes"
nodes=$(roslaunch --nodes amigobot_tracking sim.launch)
echo "$nodes"
[ -n "$nodes" ] || { echo "FAILED: roslaunch --nodes listed nothing"; exit 1; }

# roslaunch starts the master itself on ROS_MASTER_URI's port.
roslaunch amigobot_tracking sim.launch autostart:=true start_delay:=0.0 \
  tcp_port:="${port[tcp_port]}" status_port:="${port[status_port]}" laser_port:="${port[laser_port]}" \
  > "$ROS_HOME/sim.log" 2>&1 &
for _ in $(seq 60); do rostopic list > /dev/null 2>&1 && break; sleep 0.5; done
failed=0
for topic in /odom /scan /cmd_vel; do
  if timeout 60 rostopic echo -n 1 "$topic" > /dev/null 2>&1; then
    echo "install space: $topic flows"
  else
    echo "FAILED: no message on $topic within 60 s"; failed=1
  fi
done
[ $failed -eq 0 ] || { tail -n 40 "$ROS_HOME/sim.log"; exit 1; }
echo "install space: OK"
