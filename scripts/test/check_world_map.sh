#!/usr/bin/env bash
# A committed map drawn from a world file is what world_map draws from it today (so the
# e2e tests never localise on a stale map): regenerates it in a temporary folder and
# compares the PGM byte for byte and the YAML but for its image line.
# Usage: check_world_map.sh WORLD_MAP_BINARY WORLD_YAML MAP_YAML
set -euo pipefail
tool="$1" world="$2" map="$3"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fresh="$tmp/$(basename "$map")"
"$tool" --world "$world" --out "$fresh" >/dev/null
pgm="${map%.yaml}.pgm"
if ! cmp -s "$pgm" "${fresh%.yaml}.pgm"; then
  echo "$pgm differs from what world_map draws from $world today; regenerate it:" >&2
  echo "  rosrun amigobot_tracking world_map --world $world --out $map" >&2
  exit 1
fi
if ! diff <(grep -v '^image:' "$map") <(grep -v '^image:' "$fresh") >&2; then
  echo "$map differs from what world_map writes for $world today (above)" >&2
  exit 1
fi
echo "$map is world_map's drawing of $world"
