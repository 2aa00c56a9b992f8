#!/usr/bin/env bash
# README command 2: installs what is needed, builds, and runs the whole test
# suite with ctest. Tests that need ../shared skip (with a message) where it
# is absent. Exit status is ctest's.
#   CTEST_ARGS   extra ctest arguments, e.g. "-L shared" or "-E slow"
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/setup-debian.sh
scripts/build.sh
BUILD_DIR=${BUILD_DIR:-build}
cd "$BUILD_DIR"
# shellcheck disable=SC2086
ctest --output-on-failure -j "$(nproc)" ${CTEST_ARGS:-}
