#!/usr/bin/env bash
# Command 1 of the README: installs the Debian packages, builds rockfall and runs its main job
# on the shipped seed slope.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
echo
echo "== rockfall simulate samples/seed_slope.toml"
build/app/rockfall simulate samples/seed_slope.toml --seed 1
