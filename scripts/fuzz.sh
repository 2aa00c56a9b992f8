#!/usr/bin/env bash
# Fuzzes the scan readers (scanners/io) with libFuzzer.
#
#   scripts/fuzz.sh [SECONDS_PER_TARGET]        (default 60)
#
# Builds the targets in $BUILD_DIR (default build-fuzz) with clang, AddressSanitizer
# and UndefinedBehaviorSanitizer (-DBESPOKE_FUZZ=ON -DBESPOKE_SANITIZE=ON),
# generates a seed corpus of small valid files of every format and encoding
# (tests/fuzz/make_fuzz_seeds.cc), then runs each target for SECONDS_PER_TARGET
# seconds, one after the other. A finding is any crash, sanitizer report,
# uncaught exception other than InputError, leak, input taking over 10 s, or a
# single allocation over 512 MB (inputs are at most 64 KiB, so that would be a
# header-trusting allocation). Prints the executions per target and exits 1 when
# any target found something; the failing inputs are kept in
# $BUILD_DIR/fuzz-findings/<target>/ (reproduce: $BUILD_DIR/tests/fuzz_<target> FILE).
# The corpus grown by earlier runs is kept in $BUILD_DIR/fuzz-corpus/.
#
#   FUZZ_TARGETS  targets to run (default "ply pcd obj xyz off stl")
#   JOBS          build parallelism (default 2)
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-60}
BUILD_DIR=${BUILD_DIR:-build-fuzz}
JOBS=${JOBS:-2}
read -r -a targets <<< "${FUZZ_TARGETS:-ply pcd obj xyz off stl}"

launcher=()
if command -v ccache >/dev/null 2>&1 && [ "${BESPOKE_CCACHE:-1}" = 1 ]; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
mkdir -p "$BUILD_DIR"
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++ \
  -DCMAKE_BUILD_TYPE=RelWithDebInfo -DBESPOKE_FUZZ=ON -DBESPOKE_SANITIZE=ON \
  -DBESPOKE_BUILD_TESTS=OFF -DBESPOKE_BUILD_BENCHMARKS=OFF "${launcher[@]}" \
  > "$BUILD_DIR/configure.log" 2>&1 || { cat "$BUILD_DIR/configure.log"; exit 2; }
build_targets=(make_fuzz_seeds)
for t in "${targets[@]}"; do build_targets+=("fuzz_$t"); done
cmake --build "$BUILD_DIR" -j "$JOBS" --target "${build_targets[@]}"

seeds="$BUILD_DIR/fuzz-seeds"
rm -rf "$seeds"
"$BUILD_DIR/tests/make_fuzz_seeds" "$seeds"

export ASAN_OPTIONS=${ASAN_OPTIONS:-detect_leaks=1:allocator_may_return_null=0}
export UBSAN_OPTIONS=${UBSAN_OPTIONS:-print_stacktrace=1:halt_on_error=1}
status=0
printf '%-8s %12s %10s  %s\n' target executions corpus result
for t in "${targets[@]}"; do
  corpus="$BUILD_DIR/fuzz-corpus/$t"
  findings="$BUILD_DIR/fuzz-findings/$t"
  log="$BUILD_DIR/fuzz-$t.log"
  mkdir -p "$corpus" "$findings"
  rc=0
  "$BUILD_DIR/tests/fuzz_$t" "$corpus" "$seeds/$t" -max_total_time="$seconds" \
    -max_len=65536 -malloc_limit_mb=512 -rss_limit_mb=2048 -timeout=10 \
    -artifact_prefix="$findings/" -print_final_stats=1 > "$log" 2>&1 || rc=$?
  execs=$(awk '/stat::number_of_executed_units/ {print $2}' "$log" | tail -n 1)
  files=$(find "$corpus" -type f | wc -l)
  if [ "$rc" -eq 0 ]; then
    result=ok
  else
    result="FINDING (exit $rc; log $log; inputs in $findings)"
    status=1
  fi
  printf '%-8s %12s %10s  %s\n' "$t" "${execs:-?}" "$files" "$result"
  if [ "$rc" -ne 0 ]; then grep -E 'ERROR|SUMMARY|==[0-9]+==|runtime error|terminate' "$log" | head -20; fi
done
exit $status
