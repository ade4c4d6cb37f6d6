#!/usr/bin/env bash
# make fuzz: builds the libFuzzer target (clang, ASan + UBSan) and runs it for
# FUZZ_SECONDS (default 300) from the examples and the regression corpus, with the key
# dictionary. Every input that fails (crash, sanitizer report, oracle finding, hang over
# 10 s, memory over 2 GB) is copied into tests/fuzz_regressions/ and counted by class.
set -euo pipefail
cd "$(dirname "$0")/.."
FUZZ_SECONDS=${FUZZ_SECONDS:-300}
BUILD=${FUZZ_BUILD_DIR:-build-fuzz}
bash scripts/install-deps.sh --fuzz
CC=clang CXX=clang++ cmake -S . -B "$BUILD" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBEMCONTACT_BUILD_FUZZ=ON \
  -DBEMCONTACT_BUILD_TESTS=OFF -DBEMCONTACT_BUILD_BENCH=OFF > "$BUILD.configure.log" 2>&1 || { cat "$BUILD.configure.log"; exit 1; }
cmake --build "$BUILD" -j 2 --target fuzz_problem -- --no-print-directory | grep -v '^\[' || true
corpus="$BUILD/corpus"
findings="$BUILD/findings"
mkdir -p "$corpus" "$findings"
log="$BUILD/fuzz.log"
echo "fuzz: $FUZZ_SECONDS s; log in $log"
# Fork mode keeps going after a finding; each finding is written to $findings.
ASAN_OPTIONS=detect_leaks=0:allocator_may_return_null=0 UBSAN_OPTIONS=print_stacktrace=1 \
  "$BUILD/fuzz_problem" -fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1 \
  -max_total_time="$FUZZ_SECONDS" -timeout=10 -rss_limit_mb=2048 -max_len=8192 \
  -dict=fuzz/problem.dict -artifact_prefix="$findings/" "$corpus" examples tests/fuzz_regressions > "$log" 2>&1 || true
count() { find "$findings" -maxdepth 1 -name "$1-*" | wc -l; }
crashes=$(count crash); timeouts=$(count timeout); ooms=$(count oom); leaks=$(count leak)
oracle=$(grep -c "ORACLE FAILURE" "$log" || true)
runs=$(grep -o "#[0-9]*" "$log" | tail -1 | tr -d '#' || true)
echo "fuzz: ${runs:-?} runs; crashes $crashes (of which oracle findings $oracle), hangs $timeouts, out of memory $ooms, leaks $leaks"
for f in "$findings"/*; do
  [ -f "$f" ] || continue
  cp "$f" "tests/fuzz_regressions/$(basename "$f")"
done
grep "ORACLE FAILURE" "$log" | sort | uniq -c | sort -rn | head -20 || true
[ $((crashes + timeouts + ooms + leaks)) -eq 0 ]
