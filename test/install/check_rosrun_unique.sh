#!/usr/bin/env bash
# rosrun finds every executable of the package exactly once: rosrun walks the package's folder
# (following links) as well as catkin's libexec folders, so a build or install tree inside the
# package made it ask "which of 7 copies?" and any script using rosrun stopped there.
# Usage: check_rosrun_unique.sh DEVEL_LIB_DIR   (devel/lib/amigobot_tracking; make test passes it)
set -uo pipefail
dir=${1:?usage: check_rosrun_unique.sh DEVEL_LIB_DIR}
failed=0 count=0
for exe in "$dir"/*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  name=$(basename "$exe")
  count=$((count + 1))
  # --prefix echo prints the command rosrun would run instead of running it; stdin closed so a
  # "non-unique executable" prompt fails at once instead of waiting.
  out=$(rosrun --prefix echo amigobot_tracking "$name" < /dev/null 2>&1)
  rc=$?
  if [ $rc -ne 0 ] || [ "$(printf '%s\n' "$out" | grep -c .)" -ne 1 ] || [[ "$out" != */"$name" ]]; then
    echo "FAILED: rosrun amigobot_tracking $name (exit $rc):"
    printf '%s\n' "$out" | head -n 12
    failed=1
  fi
done
[ $count -gt 0 ] || { echo "FAILED: no executables in $dir"; exit 1; }
[ $failed -eq 0 ] && echo "rosrun finds each of the $count executables in $dir exactly once"
exit $failed
