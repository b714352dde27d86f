#!/usr/bin/env bash
# Installs the Debian packages listed in scripts/debian_packages.txt that are not yet installed.
# Idempotent: does nothing (and needs no network) when every package is present.
set -euo pipefail
list="$(dirname "$0")/debian_packages.txt"
missing=()
while read -r pkg; do
  [ -z "$pkg" ] && continue
  status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
  [ "$status" = "install ok installed" ] || missing+=("$pkg")
done < <(sed -e 's/#.*//' -e 's/[[:space:]]//g' "$list")

if [ ${#missing[@]} -eq 0 ]; then
  echo "deps: all $(sed -e 's/#.*//' "$list" | grep -c '[^[:space:]]') Debian packages present"
  exit 0
fi
echo "deps: installing ${#missing[@]} missing packages: ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
