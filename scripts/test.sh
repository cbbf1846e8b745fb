#!/usr/bin/env bash
# Command 2 of the README: installs the Debian packages if missing, builds rockfall and runs
# the whole test suite (unit and verification tests; benchmarks are not tests).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
cd build
ctest --output-on-failure -j "$(nproc)" "$@"
