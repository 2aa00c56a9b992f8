#!/usr/bin/env bash
# Configures and builds Bespoke.
#   BUILD_DIR (default build)  BUILD_TYPE (default Release)
#   BESPOKE_SANITIZE=ON        address + undefined behaviour sanitizers
#   BESPOKE_UNITY=OFF          one source a compile (default ON: each library's
#                              sources compiled in batches of 8; plain cmake
#                              defaults to OFF, for quick rebuilds while editing)
#   JOBS (default: number of cores)
#   TARGETS (default: everything), e.g. TARGETS=bespoke builds only the CLI
# Extra arguments are passed to cmake's configure step.
set -euo pipefail
cd "$(dirname "$0")/.."
BUILD_DIR=${BUILD_DIR:-build}
BUILD_TYPE=${BUILD_TYPE:-Release}
JOBS=${JOBS:-$(nproc)}
launcher=()
if command -v ccache >/dev/null 2>&1 && [ "${BESPOKE_CCACHE:-1}" = 1 ]; then
  launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
fi
cmake -S . -B "$BUILD_DIR" -G Ninja -DCMAKE_BUILD_TYPE="$BUILD_TYPE" \
  -DBESPOKE_SANITIZE="${BESPOKE_SANITIZE:-OFF}" -DBESPOKE_UNITY_BUILD="${BESPOKE_UNITY:-ON}" \
  "${launcher[@]}" "$@"
targets=()
for t in ${TARGETS:-}; do targets+=(--target "$t"); done
cmake --build "$BUILD_DIR" -j "$JOBS" "${targets[@]}"
