#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, one per file reader) with clang into build-fuzz/ and runs
# each for a fixed number of runs from seed corpora made of samples/ (docs/fuzzing.md).
# Usage: scripts/fuzz.sh [TARGET...]   (default: every target; names as in fuzz/CMakeLists.txt)
# Environment: RUNS (runs per target, default 2000, from random seed FUZZ_SEED, default 1),
# SECONDS_EACH (instead of RUNS: run each target this many seconds), JOBS (build parallelism,
# default nproc), FUZZ_SANITIZE (e.g. address,undefined: a sanitized fuzz build of its own in
# build-fuzz-san/). Exits non-zero when a target finds an input that crashes, hangs (10 s) or
# aborts; the input is kept in build-fuzz/findings/ and its path printed.
set -euo pipefail
cd "$(dirname "$0")/.."
jobs=${JOBS:-$(nproc)}
build=build-fuzz${FUZZ_SANITIZE:+-san}
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
    -DROCKFALL_FUZZ=ON -DROCKFALL_FUZZ_SANITIZE="${FUZZ_SANITIZE:-}" \
    -DROCKFALL_BUILD_TESTS=OFF -DROCKFALL_BUILD_BENCH=OFF >/dev/null
cmake --build "$build" -j "$jobs" --target fuzz_all

# Seed corpora: what the readers are given in samples/ (meshes in formats samples/ lacks come
# from tests/data/meshes/); a [sweep] target's seed is a sample's [sweep] table without its
# header line, as the target adds it.
seeds=$build/seeds
rm -rf "$seeds"
seed() {  # seed TARGET FILE...: copies the files that exist into the target's seed folder
    local target=$1
    shift
    mkdir -p "$seeds/$target"
    for f in "$@"; do [ -f "$f" ] && cp "$f" "$seeds/$target/"; done
    return 0
}
seed fuzz_scenario samples/*.toml samples/seed_slope/*.toml samples/terrain/*.toml
seed fuzz_soil samples/soil/*.toml
mkdir -p "$seeds/fuzz_sweep"
for f in samples/seed_sweep*.toml; do
    awk '/^\[sweep/ {on = 1} on && !/^\[sweep\]$/' "$f" >"$seeds/fuzz_sweep/$(basename "$f")"
done
seed fuzz_catalogue samples/rocks/catalogue.toml
seed fuzz_impact_csv samples/impacts/*.csv
seed fuzz_load_record samples/soil/*.csv
for format in obj stl ply off gltf glb; do
    seed "fuzz_mesh_$format" samples/rocks/*/*."$format" samples/terrain/*."$format" \
        tests/data/meshes/*."$format"
done

targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=($(ls "$seeds"))
# A fixed number of runs from a fixed random seed repeats the same inputs on every machine;
# with SECONDS_EACH the seed is libFuzzer's own (from the clock), for longer runs.
limit=(-runs="${RUNS:-2000}" -seed="${FUZZ_SEED:-1}")
[ -z "${SECONDS_EACH:-}" ] || limit=(-max_total_time="$SECONDS_EACH")
mkdir -p "$build/corpus" "$build/findings" "$build/logs"
failed=()
for target in "${targets[@]}"; do
    corpus=$build/corpus/$target
    mkdir -p "$corpus"
    log=$build/logs/$target.log
    # The first folder collects the inputs that reach new code; the seeds are only read.
    if "$build/fuzz/$target" "${limit[@]}" -timeout=10 -rss_limit_mb=2048 \
        -artifact_prefix="$build/findings/$target-" -print_final_stats=1 \
        "$corpus" "$seeds/$target" >"$log" 2>&1; then
        runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$')
        echo "fuzz.sh: $target: ${runs:-?} runs, no finding (corpus $(ls "$corpus" | wc -l) inputs)"
    else
        echo "fuzz.sh: $target: FINDING, see $log:"
        grep -E "^==|ERROR|fuzz: |Test unit written" "$log" | head -5
        failed+=("$target")
    fi
done
[ ${#failed[@]} -eq 0 ] || { echo "fuzz.sh: findings in ${failed[*]}"; exit 1; }
