#!/usr/bin/env bash
# The install space works on its own: installs the already-built workspace (`cmake --install`
# of its build folder: no second build, so the check costs seconds, not a rebuild), then, in a
# clean environment with only the install prefix's setup.bash sourced, resolves sim.launch's
# nodes (roslaunch --nodes) and runs sim.launch headless for a short while: odom, scan and
# cmd_vel must flow.
# Usage: check_install_space.sh BUILD_DIR   (the catkin build folder; make test passes it)
set -euo pipefail
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BUILD=${1:?usage: check_install_space.sh BUILD_DIR}
[ -f "$BUILD/CMakeCache.txt" ] || { echo "FAILED: $BUILD has no CMakeCache.txt (not a configured build folder)"; exit 1; }
PREFIX=$(sed -n 's/^CMAKE_INSTALL_PREFIX:PATH=//p' "$BUILD/CMakeCache.txt")
[ -n "$PREFIX" ] || { echo "FAILED: no CMAKE_INSTALL_PREFIX in $BUILD/CMakeCache.txt"; exit 1; }
# Nothing of the calling workspace may leak in: a clean environment for every step.
clean_env=(env -i HOME="$HOME" PATH=/usr/bin:/bin LANG=C.UTF-8)

echo "install space: installing $BUILD into $PREFIX"
# Only a prefix of the workspace itself is emptied first (never one set elsewhere, e.g. /usr).
ws=$(cd "$BUILD/.." && pwd)
[ "$PREFIX" = "$ws/install" ] || { echo "FAILED: install prefix $PREFIX is not $ws/install: refusing to install there"; exit 1; }
rm -rf "$PREFIX"
"${clean_env[@]}" cmake --install "$BUILD" > "$BUILD/install_space.log" 2>&1 ||
  { tail -n 40 "$BUILD/install_space.log"; echo "FAILED: cmake --install"; exit 1; }

# Free ports for a private master and the emulator (the same helper as the rostests).
"${clean_env[@]}" /usr/bin/python3 "$ROOT/scripts/test/with_free_ports.py" master tcp_port status_port laser_port -- \
  bash "$ROOT/test/install/run_from_install_space.sh" "$PREFIX"
