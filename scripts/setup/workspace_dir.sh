#!/usr/bin/env bash
# Prints the catkin workspace folder of this checkout: $AMIGOBOT_WS when set, otherwise a
# folder under ~/.cache named after the checkout (its folder name and a hash of its path).
# Why outside the package: rosrun and rospack walk the package's folder (following links),
# so a workspace inside it made every executable appear several times ("non-unique
# executable") and `find` loop through .ws/src/amigobot_tracking -> the package.
# The Makefile and the report scripts (--ws default) all ask this script: one rule.
set -euo pipefail
if [ -n "${AMIGOBOT_WS:-}" ]; then
  echo "$AMIGOBOT_WS"
  exit 0
fi
root=$(cd "$(dirname "$0")/../.." && pwd -P)
hash=$(printf '%s' "$root" | sha1sum | cut -c1-8)
echo "${XDG_CACHE_HOME:-$HOME/.cache}/amigobot_tracking/ws-$(basename "$root")-$hash"
