#!/usr/bin/env bash
# Builds the packet-parser libFuzzer target with clang (ASan + UBSan) and runs it for a
# bounded time. Usage: run_fuzz.sh SECONDS [RESULTS_DIR]
# With RESULTS_DIR, writes a JUnit XML test case there so `make test` counts the run.
set -uo pipefail
export PATH=/usr/bin:$PATH
SECONDS_TO_RUN=${1:-30}
RESULTS=${2:-}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
OUT=$("$ROOT/scripts/setup/workspace_dir.sh")/fuzz  # outside the package (workspace_dir.sh says why)
mkdir -p "$OUT/corpus" "$OUT/artifacts"
BIN=$OUT/fuzz_packet_parser
LOG=$OUT/fuzz.log

junit() {  # junit STATUS MESSAGE
  [ -z "$RESULTS" ] && return 0
  mkdir -p "$RESULTS/amigobot_tracking"
  local body=""
  [ "$1" != ok ] && body="<failure message=\"$2\"><![CDATA[$(tail -n 40 "$LOG" 2>/dev/null)]]></failure>"
  cat > "$RESULTS/amigobot_tracking/fuzz-packet_parser.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="fuzz" tests="1" failures="$([ "$1" = ok ] && echo 0 || echo 1)" errors="0">
  <testcase classname="fuzz" name="packet_parser_${SECONDS_TO_RUN}s">$body</testcase>
</testsuite>
XML
}

SRC=(test/fuzz/fuzz_packet_parser.cpp src/aria/packet.cpp src/aria/commands.cpp src/aria/sip.cpp)
if ! (cd "$ROOT" && clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
      -Wall -Wextra -Werror -Iinclude "${SRC[@]}" -o "$BIN") > "$LOG" 2>&1; then
  echo "fuzz: build failed (clang and libclang-rt-14-dev installed?)"; cat "$LOG"
  junit fail "build failed"; exit 1
fi
# Seeds: a few well-formed packets so the run starts at the interesting states.
printf '\x01\x00\xfa\xfb\x03\x00\x00\x00' > "$OUT/corpus/seed_sync0"
printf '\x05\xc8\xfa\xfb\x06\x0b\x3b\xc8\x00\xd3\x3b' > "$OUT/corpus/seed_vel"
if "$BIN" -max_total_time="$SECONDS_TO_RUN" -dict="$ROOT/test/fuzz/aria.dict" -artifact_prefix="$OUT/artifacts/" \
     -print_final_stats=1 "$OUT/corpus" > "$LOG" 2>&1; then
  execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$LOG")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$LOG")
  echo "fuzz: packet parser OK for ${SECONDS_TO_RUN} s: ${execs} inputs, ${rate} execs/s, corpus $(ls "$OUT/corpus" | wc -l) files"
  junit ok ""
else
  echo "fuzz: packet parser FAILED; crash input in $OUT/artifacts/"; tail -n 40 "$LOG"
  junit fail "crash or invariant violation"; exit 1
fi
