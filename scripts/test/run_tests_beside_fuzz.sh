#!/usr/bin/env bash
# make test's run: the test command given after `--`, with a short pass of each named parser's
# fuzzer beside it at the lowest priority (the tests wait on emulated devices much of the time,
# and the fuzzers take only the CPU they leave idle).
#   run_tests_beside_fuzz.sh BUILD_DIR RESULTS FUZZ_RESULTS TARGET... -- COMMAND...
# Writes BUILD_DIR/run_tests.rc (the command's exit code, which count_test_results.py counts)
# and BUILD_DIR/fuzz.log (a fuzzer's failure is its JUnit case's). The fuzz JUnit files are written to FUZZ_RESULTS
# first and copied into RESULTS/amigobot_tracking at the end: catkin's run_tests empties
# RESULTS when it starts. Exits 0; the counts say what failed.
set -uo pipefail
if [ $# -lt 4 ]; then
  echo "usage: $0 BUILD_DIR RESULTS FUZZ_RESULTS TARGET... -- COMMAND..." >&2
  exit 2
fi
BUILD=$1 RESULTS=$2 FUZZ_RESULTS=$3
shift 3
targets=()
while [ $# -gt 0 ] && [ "$1" != -- ]; do targets+=("$1"); shift; done
if [ "${1:-}" != -- ] || [ $# -lt 2 ]; then
  echo "$0: expected '-- COMMAND...' after the fuzz targets" >&2
  exit 2
fi
shift
ROOT=$(cd "$(dirname "$0")/../.." && pwd)

rm -rf "$FUZZ_RESULTS"
(
  start=$(date +%s)
  nice -n 19 "$ROOT/scripts/test/run_fuzz.sh" --test-runs "$FUZZ_RESULTS" "${targets[@]}"
  echo "make: fuzz (beside the tests) took $(( $(date +%s) - start )) s"
) > "$BUILD/fuzz.log" 2>&1 &
fuzz=$!

"$@"
echo $? > "$BUILD/run_tests.rc"
echo "make: run_tests done; waiting for the fuzz pass"
wait "$fuzz"
cat "$BUILD/fuzz.log"
mkdir -p "$RESULTS/amigobot_tracking"
cp "$FUZZ_RESULTS"/amigobot_tracking/*.xml "$RESULTS/amigobot_tracking/" 2>/dev/null \
  || echo "make: the fuzz pass wrote no JUnit file (its log: $BUILD/fuzz.log)"
exit 0
