#!/usr/bin/env bash
# README command 2: installs what is needed, builds, and runs the whole test
# suite with ctest, then a short bounded fuzzing run of the scan readers
# (scripts/fuzz.sh: libFuzzer + ASan/UBSan, every reader). Tests that need
# ../shared skip (with a message) where it is absent. Exit status: ctest's,
# or 1 when fuzzing found something.
#   CTEST_ARGS     extra ctest arguments, e.g. "-L shared" or "-E slow"
#   FUZZ_SECONDS   seconds per fuzz target (default 10; 0 = no fuzzing)
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
status=0
# shellcheck disable=SC2086
(cd "$BUILD_DIR" && ctest --output-on-failure -j "$(nproc)" ${CTEST_ARGS:-}) || status=$?
fuzz_seconds=${FUZZ_SECONDS:-10}
if [ "$fuzz_seconds" -gt 0 ]; then
  echo "== fuzzing the scan readers, ${fuzz_seconds} s per format (scripts/fuzz.sh)"
  BUILD_DIR=${FUZZ_BUILD_DIR:-build-fuzz} scripts/fuzz.sh "$fuzz_seconds" || {
    echo "fuzzing found a problem (see above)"
    [ "$status" -ne 0 ] || status=1
  }
fi
exit "$status"
