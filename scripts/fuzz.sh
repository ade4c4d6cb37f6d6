#!/usr/bin/env bash
# make fuzz: builds the libFuzzer target (clang, ASan + UBSan; FUZZ_SANITIZE=0 for a plain
# optimised build, which runs more inputs per second) and runs it for FUZZ_SECONDS
# (default 300) from the examples and the regression corpus, with the key dictionary.
# Every input that fails (crash, sanitizer report, oracle finding, hang, memory over 2 GB)
# is copied into tests/fuzz_regressions/ and counted by class. A hang is a run over 10 s,
# or over 60 s in the sanitized build, which runs the bundled examples 10 to 30 times
# slower than the optimised one.
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS=${FUZZ_SECONDS:-300}
SANITIZE=${FUZZ_SANITIZE:-1}
if [ "$SANITIZE" = 1 ]; then BUILD=${FUZZ_BUILD_DIR:-build-fuzz}; else BUILD=${FUZZ_BUILD_DIR:-build-fuzz-release}; fi
bash scripts/install-deps.sh --fuzz
CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBEMCONTACT_BUILD_FUZZ=ON \
  -DBEMCONTACT_FUZZ_SANITIZE=$([ "$SANITIZE" = 1 ] && echo ON || echo OFF) \
  -DBEMCONTACT_BUILD_TESTS=OFF -DBEMCONTACT_BUILD_BENCH=OFF > "$BUILD.configure.log" 2>&1 || { cat "$BUILD.configure.log"; exit 1; }
cmake --build "$BUILD" -j 2 --target fuzz_problem > "$BUILD.build.log" 2>&1 || { cat "$BUILD.build.log"; exit 1; }
corpus="$BUILD/corpus"
findings="$BUILD/findings"
mkdir -p "$corpus" "$findings"
log="$BUILD/fuzz.log"
echo "fuzz: $FUZZ_SECONDS s; log in $log"
# Fork mode keeps going after a finding; each finding is written to $findings.
ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=0 UBSAN_OPTIONS=print_stacktrace=1 \
  "$BUILD/fuzz_problem" -fork="${FUZZ_JOBS:-2}" -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_total_time="$FUZZ_SECONDS" -timeout="$([ "$SANITIZE" = 1 ] && echo 60 || echo 10)" -report_slow_units=100000 -rss_limit_mb=2048 -max_len=8192 \
  -dict=fuzz/problem.dict -artifact_prefix="$findings/" "$corpus" examples tests/fuzz_regressions \
  $(ls -d build-fuzz*/corpus 2>/dev/null | grep -v "^$corpus$") > "$log" 2>&1 || true
# Replay every finding once to sort it into its class.
declare -A classes=()
for f in "$findings"/*; do
  [ -f "$f" ] || continue
  case "$(basename "$f")" in
    slow-unit-*) rm -f "$f"; continue ;;  # slow but finished: not a finding
    timeout-*) class="hang" ;;
    oom-*) class="out of memory" ;;
    leak-*) class="leak" ;;
    *)
      replay=$(ASAN_OPTIONS=detect_leaks=0 timeout 60 "$BUILD/fuzz_problem" "$f" 2>&1 || true)
      if grep -q "ORACLE FAILURE: input error without" <<<"$replay"; then class="message without file/line/key"
      elif grep -q "ORACLE FAILURE: geometry error naming" <<<"$replay"; then class="message without file/line/key"
      elif grep -q "non-finite" <<<"$replay"; then class="NaN or inf in an output"
      elif grep -q "ORACLE FAILURE: std::bad_alloc" <<<"$replay"; then class="out of memory"
      elif grep -q "ORACLE FAILURE" <<<"$replay"; then class="unexpected exception"
      elif grep -q "runtime error:" <<<"$replay"; then class="undefined behaviour (UBSan)"
      elif grep -q "AddressSanitizer" <<<"$replay"; then class="memory error (ASan)"
      else class="crash (signal)"
      fi ;;
  esac
  classes[$class]=$(( ${classes[$class]:-0} + 1 ))
  cp "$f" "tests/fuzz_regressions/$(basename "$f")"
  echo "fuzz: $class: tests/fuzz_regressions/$(basename "$f")"
done
runs=$(grep -o "^#[0-9]*" "$log" | tail -1 | tr -d '#' || true)
total=0
for class in "${!classes[@]}"; do total=$((total + classes[$class])); done
echo "fuzz: ${runs:-?} runs in $FUZZ_SECONDS s, $total findings"
for class in "${!classes[@]}"; do echo "  $class: ${classes[$class]}"; done
[ "$total" -eq 0 ]
