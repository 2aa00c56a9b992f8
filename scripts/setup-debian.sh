#!/usr/bin/env bash
# Installs exactly the Debian 12 packages Bespoke needs to build, test and run.
# Idempotent: does nothing when every package is already installed.
# Runs apt-get as root, or through sudo when not root.
set -euo pipefail

PACKAGES=(
  # toolchain
  build-essential cmake ninja-build pkg-config git
  # the design's six libraries
  libpcl-dev libflann-dev libopen3d-dev libcgal-dev libeigen3-dev libopencv-dev
  # helpers
  libcli11-dev nlohmann-json3-dev libspdlog-dev libfmt-dev libtbb-dev libpagmo-dev
  libcairo2-dev fonts-dejavu-core libboost-dev
  # PCD binary_compressed (LZF) in scanners/io
  liblzf-dev
  # tests, benchmarks, fuzzing (libFuzzer ships with clang's runtime)
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev clang-format
  # batch: SHA-256 of outputs (done.json); the Slurm job-array test (scripts/slurm)
  libssl-dev slurm-wlm munge
)

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} Debian packages already installed"
  exit 0
fi

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
echo "setup: installing ${#missing[@]} Debian packages: ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -q
$SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
