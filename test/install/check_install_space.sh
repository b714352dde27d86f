#!/usr/bin/env bash
# The install space works on its own: builds the package in a scratch workspace (tests off),
# runs `catkin_make install`, then, in a clean environment with only the install prefix's
# setup.bash sourced, resolves sim.launch's nodes (roslaunch --nodes) and runs sim.launch
# headless for a short while: odom, scan and cmd_vel must flow.
# Usage: check_install_space.sh [SCRATCH_DIR]   (default: .ws-install beside .ws)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
SCRATCH=${1:-$ROOT/.ws-install}
mkdir -p "$SCRATCH/src"
ln -sfn "$ROOT" "$SCRATCH/src/amigobot_tracking"
# Nothing of the calling workspace may leak in: a clean environment for every step.
clean_env=(env -i HOME="$HOME" PATH=/usr/bin:/bin LANG=C.UTF-8 CCACHE_BASEDIR="$ROOT" CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}")
launcher=()
command -v ccache > /dev/null && launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)

echo "install space: building into $SCRATCH/install"
"${clean_env[@]}" catkin_make -C "$SCRATCH" install -DCATKIN_ENABLE_TESTING=OFF -DCMAKE_BUILD_TYPE=Release \
  -DPYTHON_EXECUTABLE=/usr/bin/python3 -DCMAKE_INSTALL_PREFIX="$SCRATCH/install" "${launcher[@]}" -j2 \
  > "$SCRATCH/build.log" 2>&1 || { tail -n 40 "$SCRATCH/build.log"; echo "FAILED: catkin_make install"; exit 1; }

# Free ports for a private master and the emulator (the same helper as the rostests).
"${clean_env[@]}" /usr/bin/python3 "$ROOT/scripts/test/with_free_ports.py" master tcp_port status_port laser_port -- \
  bash "$ROOT/test/install/run_from_install_space.sh" "$SCRATCH/install"
