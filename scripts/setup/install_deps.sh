#!/usr/bin/env bash
# Installs the Debian packages of the given lists that are not yet installed.
#   install_deps.sh               every list: robot + workstation + desktop + test (make deps, make test)
#   install_deps.sh --workstation robot + workstation + desktop: build, demo, rviz (make build)
#   install_deps.sh --build       robot + workstation: what compiling the package and its tests needs
#   install_deps.sh --desktop     desktop: rviz, plots, the demo's screen (make demo, beside its build)
#   install_deps.sh --robot       only what the robot's computer needs (make deps-robot)
# --check after the list's option: install nothing; print the missing packages and exit 1 if any.
# Idempotent: does nothing (and needs no network) when every package is present.
# Sourced (`source install_deps.sh`), it only defines its functions (test/scripts/test_install_deps.py).
set -euo pipefail

# The locks apt-get and dpkg take. Another package manager holding one (unattended-upgrades,
# a second `make`, a desktop updater) made apt-get fail at once; we wait for it, saying so.
APT_LOCKS=${AMIGOBOT_APT_LOCKS:-/var/lib/dpkg/lock-frontend /var/lib/dpkg/lock /var/lib/apt/lists/lock /var/cache/apt/archives/lock}
# 10 minutes is longer than any install of these lists has taken (and than a daily upgrade run).
APT_LOCK_WAIT=${AMIGOBOT_APT_LOCK_WAIT:-600}
APT_LOCK_POLL=${AMIGOBOT_APT_LOCK_POLL:-2}

# The PID holding a lock (flock or fcntl, as /proc/locks lists both) on FILE; empty when free.
lock_holder() {
  local file=$1 inode
  [ -e "$file" ] || return 0
  inode=$(stat -L -c %i "$file")
  awk -v inode="$inode" '{ n = split($6, id, ":"); if (id[n] == inode) { print $5; exit } }' /proc/locks
}

# Waits until no lock of APT_LOCKS is held, printing who holds which every 30 s; after
# APT_LOCK_WAIT seconds fails naming the lock and its holder.
wait_for_apt_locks() {
  local waited=0 file pid what said=-30
  while :; do
    pid="" what=""
    for file in $APT_LOCKS; do
      pid=$(lock_holder "$file")
      [ -n "$pid" ] && { what=$file; break; }
    done
    [ -z "$pid" ] && { [ "$waited" -gt 0 ] && echo "deps: the package manager's locks are free after ${waited} s"; return 0; }
    local name
    name=$(cat "/proc/$pid/comm" 2>/dev/null || echo "another process")
    if [ "$waited" -ge "$APT_LOCK_WAIT" ]; then
      echo "deps: $what is still held by PID $pid ($name) after ${APT_LOCK_WAIT} s; let it finish (or stop it) and run make again" >&2
      return 1
    fi
    if [ $((waited - said)) -ge 30 ]; then
      echo "deps: waiting for $what, held by PID $pid ($name): another package manager is running" \
           "(unattended upgrades?); waiting up to ${APT_LOCK_WAIT} s, ${waited} s so far"
      said=$waited
    fi
    sleep "$APT_LOCK_POLL"
    waited=$((waited + APT_LOCK_POLL))
  done
}

main() {
  local dir lists
  dir="$(dirname "$0")"
  local robot=$dir/debian_packages_robot.txt build=$dir/debian_packages.txt desktop=$dir/debian_packages_desktop.txt
  local check=false
  [ "${1:-}" = --check ] && { check=true; shift; }
  [ "${2:-}" = --check ] && check=true
  case "${1:-}" in
    "") lists=("$robot" "$build" "$desktop" "$dir/debian_packages_test.txt") ;;
    --workstation) lists=("$robot" "$build" "$desktop") ;;
    --build) lists=("$robot" "$build") ;;
    --desktop) lists=("$desktop") ;;
    --robot) lists=("$robot") ;;
    *) echo "install_deps.sh: unknown argument '$1' (expected nothing, --workstation, --build, --desktop or --robot, then --check)" >&2
       exit 2 ;;
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
  if $check; then
    echo "deps: ${#missing[@]} of ${#wanted[@]} missing (${lists[*]##*/}): ${missing[*]}"
    exit 1
  fi
  echo "deps: installing ${#missing[@]} missing packages: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  # Waiting here says who holds the lock; apt's own timeout covers one taken between our look
  # and apt-get's start (two `make` runs at once, say).
  lock=(-o DPkg::Lock::Timeout="$APT_LOCK_WAIT")
  wait_for_apt_locks
  $SUDO apt-get "${lock[@]}" update -q
  wait_for_apt_locks
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get "${lock[@]}" install -y -q --no-install-recommends "${missing[@]}"
}

if [ "${BASH_SOURCE[0]}" = "$0" ]; then
  main "$@"
fi
