#!/usr/bin/env bash
# Installs the Debian packages of the given lists that are not yet installed.
#   install_deps.sh               all three lists: robot + workstation + test (make deps, make test)
#   install_deps.sh --workstation robot + workstation: build, demo, rviz (make build, make demo)
#   install_deps.sh --robot       only what the robot's computer needs (make deps-robot)
# Idempotent: does nothing (and needs no network) when every package is present.
set -euo pipefail
dir="$(dirname "$0")"
case "${1:-}" in
  "") lists=("$dir/debian_packages_robot.txt" "$dir/debian_packages.txt" "$dir/debian_packages_test.txt") ;;
  --workstation) lists=("$dir/debian_packages_robot.txt" "$dir/debian_packages.txt") ;;
  --robot) lists=("$dir/debian_packages_robot.txt") ;;
  *) echo "install_deps.sh: unknown argument '$1' (expected nothing, --workstation or --robot)" >&2; exit 2 ;;
esac
mapfile -t wanted < <(sed -e 's/#.*//' -e 's/[[:space:]]//g' "${lists[@]}" | grep . | sort -u)
missing=()
for pkg in "${wanted[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$pkg")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all ${#wanted[@]} Debian packages present (${lists[*]##*/})"
  exit 0
fi
echo "deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
# Two `make` runs at once (a build and a test, two checkouts) wait for each other's apt lock
# instead of failing: 10 minutes is longer than any install of these lists has taken.
lock=(-o DPkg::Lock::Timeout=600)
$SUDO apt-get "${lock[@]}" update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get "${lock[@]}" install -y -q --no-install-recommends "${missing[@]}"
