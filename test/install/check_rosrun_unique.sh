#!/usr/bin/env bash
# rosrun finds every executable of the package exactly once: rosrun walks the package's folder
# (following links) as well as catkin's libexec folders, so a build or install tree inside the
# package made it ask "which of 7 copies?" and any script using rosrun stopped there.
# Only the executables people start with rosrun or roslaunch (nodes and tools): the test
# binaries (test_*, and bench_ / fuzz_ when built) are found by rostest through the same lookup
# in every rostest, and checking each of the ~110 of them took 75 s of `make test`. Each rosrun
# costs about a second (it runs catkin_find twice), so four are asked at a time.
# Usage: check_rosrun_unique.sh DEVEL_LIB_DIR   (devel/lib/amigobot_tracking; make test passes it)
set -uo pipefail
dir=${1:?usage: check_rosrun_unique.sh DEVEL_LIB_DIR}

# check_one NAME: prints nothing when rosrun resolves NAME to one file in the package.
check_one() {
  local name=$1 out rc
  # --prefix echo prints the command rosrun would run instead of running it; stdin closed so a
  # "non-unique executable" prompt fails at once instead of waiting.
  out=$(rosrun --prefix echo amigobot_tracking "$name" < /dev/null 2>&1)
  rc=$?
  if [ $rc -ne 0 ] || [ "$(printf '%s\n' "$out" | grep -c .)" -ne 1 ] || [[ "$out" != */"$name" ]]; then
    echo "FAILED: rosrun amigobot_tracking $name (exit $rc):"
    printf '%s\n' "$out" | head -n 12
  fi
}
export -f check_one

names=()
for exe in "$dir"/*; do
  [ -f "$exe" ] && [ -x "$exe" ] || continue
  name=$(basename "$exe")
  case "$name" in test_* | bench_* | fuzz_*) continue ;; esac
  names+=("$name")
done
[ ${#names[@]} -gt 0 ] || { echo "FAILED: no executables in $dir"; exit 1; }
failures=$(printf '%s\n' "${names[@]}" | xargs -P 4 -I{} bash -c 'check_one "$1"' _ {})
if [ -n "$failures" ]; then
  printf '%s\n' "$failures"
  exit 1
fi
echo "rosrun finds each of the ${#names[@]} executables in $dir exactly once"
