#!/usr/bin/env bash
# Builds the libFuzzer targets of every parser with clang (ASan + UBSan) and runs each one.
#   run_fuzz.sh --seconds S [RESULTS_DIR] [TARGET...]  each target for S seconds (make test)
#   run_fuzz.sh --runs [RESULTS_DIR] [TARGET...]       each target for its RUNS below (make fuzz)
#   run_fuzz.sh --test-runs [RESULTS_DIR] [TARGET...]  each target for its TEST_RUNS (make test)
# With RESULTS_DIR, each target writes its own JUnit case there (fuzz-NAME.xml), pass or fail.
# Seeds come from the repository's real files (configs, worlds, maps, scenarios) where there
# are some, and a few well-formed messages for the wire protocols. A crash leaves its input
# in WS/fuzz/NAME/artifacts/ (replay: WS/fuzz/NAME/fuzz_NAME FILE).
set -uo pipefail
export PATH=/usr/bin:$PATH
MODE=${1:---seconds}
if [ "$MODE" = --seconds ]; then SECONDS_EACH=${2:-5}; shift 2 2>/dev/null || shift $#
elif [ "$MODE" = --runs ] || [ "$MODE" = --test-runs ]; then shift
else SECONDS_EACH=$MODE; MODE=--seconds; shift; fi  # the old form: run_fuzz.sh SECONDS [RESULTS]
RESULTS=${1:-}; shift 2>/dev/null
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
BASE=$("$ROOT/scripts/setup/workspace_dir.sh")/fuzz  # outside the package (workspace_dir.sh says why)

# make fuzz's split of its >= 10^7 inputs: the fast wire parsers get the most, the YAML
# loaders (yaml-cpp, ~1-5 k inputs/s under ASan) fewer.
declare -A RUNS=([packet_parser]=4000000 [scip]=1500000 [cola_a]=1500000 [rplidar]=1500000
  [status_line]=1000000 [param_value]=1000000 [world]=100000 [scenario]=100000 [map]=100000)  # 10.8 M
# make test's pass, run beside the tests at the lowest priority: about what 5 s of one core
# reached alone on a 2-core machine (scip 49 k, world 15 k, ...), less a quarter. A count, not a
# time, so a loaded machine takes longer instead of trying fewer inputs.
declare -A TEST_RUNS=([packet_parser]=30000 [scip]=40000 [cola_a]=40000 [rplidar]=75000
  [status_line]=600000 [param_value]=800000 [world]=10000 [scenario]=5000 [map]=10000)
[ "$MODE" = --test-runs ] && for name in "${!TEST_RUNS[@]}"; do RUNS[$name]=${TEST_RUNS[$name]}; done
ALL=(packet_parser scip cola_a rplidar status_line param_value world scenario map)
TARGETS=("$@"); [ ${#TARGETS[@]} -eq 0 ] && TARGETS=("${ALL[@]}")

# The link layer is taken whole (src/link/*.cpp: standard library and POSIX only), so a source
# added to it cannot leave a fuzzer unlinked (a missing system_clock_errors.cpp once failed CI).
sources() {  # the sources of target $1 besides test/fuzz/fuzz_$1.cpp
  case $1 in
    packet_parser) echo src/aria/packet.cpp src/aria/commands.cpp src/aria/sip.cpp ;;
    scip) echo src/sensors/scip.cpp ;;
    cola_a) echo src/sensors/cola_a.cpp ;;
    rplidar) echo src/sensors/rplidar.cpp ;;
    status_line) echo src/aria/emulator_status.cpp src/aria/transport.cpp src/link/*.cpp src/core/robot/diamond.cpp src/core/support/error_text.cpp ;;
    param_value) echo src/core/support/field_table.cpp ;;
    world) echo src/world/world.cpp src/core/support/input_file.cpp src/core/robot/diamond.cpp src/core/perception/obstacle_motion.cpp ;;
    scenario) echo src/sim/*.cpp src/core/*/*.cpp ;;
    map) echo src/localization/occupancy_map.cpp src/core/support/input_file.cpp ;;
  esac
}

flags() {  # the extra compiler and linker flags of target $1
  case $1 in
    world | map | scenario) echo -lyaml-cpp ;;
  esac
}

seed() {  # seed NAME BYTES (printf format)
  printf "$2" > "$CORPUS/seed_$1"
}

seeds() {  # fills $CORPUS for target $1
  case $1 in
    packet_parser)
      seed sync0 '\x01\x00\xfa\xfb\x03\x00\x00\x00'
      seed vel '\x05\xc8\xfa\xfb\x06\x0b\x3b\xc8\x00\xd3\x3b' ;;
    scip)
      seed md '\x05MD0044072501000\n99b\n\n'
      seed gd '\x07GD0000076801\n00P\n0Fa00\n0C\\0C\\0C\\e\n\n'
      seed vv '\x03VV\n00P\nVEND:Hokuyo;[\nPROT:SCIP 2.0;N\n\n' ;;
    cola_a)
      seed scan '\x10\x02sRA LMDscandata 1 1 89A27F 0 0 1 2 3 4 0 0 1388 168 0 1 DIST1 3F800000 0 FFF92230 1388 3 A 14 1E 0 0 0 0 0 0 0 0\x03'
      seed two '\x03junk\x02sSN LMDscandata 1 1 1 0 0 0 0 0 0 0 0 9C4 0 0 1 DIST1 40000000 0 0 D05 2 0 1 0 0 0 0 0 0 0 0\x03\x02sRA LMPscancfg 9C4 1 D05 FFFF3CB0 225510\x03' ;;
    rplidar)
      seed descriptor '\x05\xa5\x5a\x05\x00\x00\x40\x81'
      seed nodes '\x2d\x3e\x01\x00\x10\x04\x3c\x81\x02\x20\x04\x3c\x01\x05\x30\x04' ;;
    status_line)
      seed status '12.5 1.25 -0.5 0.75 0.2 -0.1 1 1 0'
      seed huge '1e+300 -1.7976931348623157e+308 2.2250738585072014e-308 0 0 0 0 1 1' ;;
    param_value)
      seed real '\x000.15'; seed exp '\x00-1.5e-3'; seed int '\x01100'; seed bool '\x02true'; seed text '\x03hokuyo' ;;
    world) cp "$ROOT"/config/worlds/*.yaml "$ROOT"/test/e2e/worlds/*.yaml "$CORPUS"/ 2>/dev/null
      rm -f "$CORPUS"/*_map.yaml ;;
    scenario) cp "$ROOT"/config/scenarios/*.yaml "$CORPUS"/ ;;
    map)
      for yaml in "$ROOT"/config/maps/lab.yaml "$ROOT"/test/e2e/worlds/*_map.yaml; do
        { sed 's/^image:.*/image: image.pgm/' "$yaml"; printf '\n#PGM\nP5\n# small\n4 2\n255\n\x00\xfe\xcd\x00\xfe\xfe\x00\xcd'; } \
          > "$CORPUS/$(basename "$yaml")"
      done
      { sed 's/^image:.*/image: image.pgm/' "$ROOT"/config/maps/lab.yaml; printf '\n#PGM\nP2\n3 2\n100\n0 50 100\n100 0 7\n'; } > "$CORPUS/ascii" ;;
  esac
}

junit() {  # junit NAME STATUS MESSAGE LOG
  [ -z "$RESULTS" ] && return 0
  mkdir -p "$RESULTS/amigobot_tracking"
  local body="" length=$([ "$MODE" != --seconds ] && echo "${RUNS[$1]}runs" || echo "${SECONDS_EACH}s")
  [ "$2" != ok ] && body="<failure message=\"$3\"><![CDATA[$(tail -n 40 "$4" 2>/dev/null | tr -d '\000')]]></failure>"
  cat > "$RESULTS/amigobot_tracking/fuzz-$1.xml" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="fuzz" tests="1" failures="$([ "$2" = ok ] && echo 0 || echo 1)" errors="0">
  <testcase classname="fuzz" name="${1}_${length}">$body</testcase>
</testsuite>
XML
}

# fuzz_one NAME: builds (when stale) and runs NAME's fuzzer; its summary line goes to stdout,
# its inputs count to $BASE/NAME/execs; exit 1 on a failure.
fuzz_one() {
  local name=$1
  local OUT=$BASE/$name CORPUS=$BASE/$name/corpus BIN=$BASE/$name/fuzz_$name LOG=$BASE/$name/fuzz.log
  mkdir -p "$CORPUS" "$OUT/artifacts"; rm -f "$OUT/execs"
  read -ra SRC <<< "test/fuzz/fuzz_$name.cpp $(cd "$ROOT" && echo $(sources "$name"))"
  # Rebuilt only when a source, a header or this script is newer than the binary.
  if [ ! -x "$BIN" ] || [ -n "$(cd "$ROOT" && find "${SRC[@]}" include test/fuzz "$0" -newer "$BIN" -print -quit)" ]; then
    if ! (cd "$ROOT" && nice clang++ -std=c++17 -O1 -g -fsanitize=fuzzer,address,undefined -fno-sanitize-recover=undefined \
          -ffunction-sections -Wl,--gc-sections -Wall -Wextra -Werror -Iinclude -isystem /usr/include/eigen3 \
          "${SRC[@]}" $(flags "$name") -o "$BIN") > "$LOG" 2>&1; then
      local why="clang and libclang-rt-14-dev installed?"
      grep -q "undefined reference" "$LOG" && why="a source is missing from sources() in $0"
      echo "fuzz $name: build failed ($why)"; tail -n 30 "$LOG"
      junit "$name" fail "build failed: $why" "$LOG"; return 1
    fi
  fi
  seeds "$name"  # seeds and seed write into this function's local CORPUS (bash scopes dynamically)
  local dict=(); [ "$name" = packet_parser ] && dict=(-dict="$ROOT/test/fuzz/aria.dict")
  local length=(-max_total_time="${SECONDS_EACH:-0}"); [ "$MODE" != --seconds ] && length=(-runs="${RUNS[$name]}")
  if (cd "$OUT" && "$BIN" "${length[@]}" "${dict[@]}" -max_len=4096 -rss_limit_mb=1024 -artifact_prefix="$OUT/artifacts/" \
       -print_final_stats=1 "$CORPUS") > "$LOG" 2>&1; then
    local execs rate
    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$LOG")
    rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$LOG")
    echo "$execs" > "$OUT/execs"
    echo "fuzz $name: OK, ${execs} inputs, ${rate} inputs/s, corpus $(ls "$CORPUS" | wc -l) files"
    junit "$name" ok "" "$LOG"
  else
    echo "fuzz $name: FAILED; the input is in $OUT/artifacts/"; tail -n 40 "$LOG"
    junit "$name" fail "crash or invariant violation" "$LOG"; return 1
  fi
}

# Each fuzzer is one single-threaded process (its build one clang): FUZZ_JOBS of them at a time
# (default: one per core), each target's lines printed together when it ends.
JOBS=${FUZZ_JOBS:-$(nproc)}
declare -A PIDS=()
failed=0 total=0
reap() {  # waits for one running target and prints its lines
  local pid rc=0
  wait -n -p pid || rc=$?
  cat "$BASE/${PIDS[$pid]}.out"; rm -f "$BASE/${PIDS[$pid]}.out"
  [ $rc -ne 0 ] && failed=$((failed + 1))
  unset "PIDS[$pid]"
}
mkdir -p "$BASE"
for name in "${TARGETS[@]}"; do
  [ ${#PIDS[@]} -ge "$JOBS" ] && reap
  fuzz_one "$name" > "$BASE/$name.out" 2>&1 &
  PIDS[$!]=$name
done
while [ ${#PIDS[@]} -gt 0 ]; do reap; done
for name in "${TARGETS[@]}"; do
  [ -f "$BASE/$name/execs" ] && total=$((total + $(cat "$BASE/$name/execs")))
done
echo "fuzz: ${#TARGETS[@]} targets, ${total} inputs in all, ${failed} failed"
[ "$failed" -eq 0 ]
