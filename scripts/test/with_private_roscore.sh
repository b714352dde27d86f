#!/usr/bin/env bash
# Runs a command against a private ROS master on a free port, then stops that master
# (only the one started here, by its pid). Usage: with_private_roscore.sh CMD [ARGS...]
set -euo pipefail
export PATH=/usr/bin:$PATH
port=$(/usr/bin/python3 -c 'import socket; s = socket.socket(); s.bind(("", 0)); print(s.getsockname()[1])')
export ROS_MASTER_URI=http://localhost:$port
log=$(mktemp)
roscore -p "$port" >"$log" 2>&1 &
core=$!
trap 'kill -INT $core 2>/dev/null; wait $core 2>/dev/null || true; rm -f "$log"' EXIT
for _ in $(seq 1 100); do  # up to 20 s on a loaded machine
  rostopic list >/dev/null 2>&1 && break
  sleep 0.2
done
"$@"
