#!/usr/bin/env bash
# Command 1 of the README: installs the Debian packages, builds rockfall and runs its main job:
# a Monte Carlo sweep of 2000 random rocks on the shipped seed slope into an SQLite results
# database (results/seed_sweep.db, replaced on every run), then prints its summary.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/install-deps.sh
bash scripts/build.sh
mkdir -p results
rm -f results/seed_sweep.db results/seed_sweep.db-wal results/seed_sweep.db-shm
echo
echo "== rockfall sweep samples/seed_sweep.toml --db results/seed_sweep.db"
build/app/rockfall sweep samples/seed_sweep.toml --db results/seed_sweep.db
echo
echo "Query it further: build/app/rockfall query results/seed_sweep.db --help"
