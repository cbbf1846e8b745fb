#!/usr/bin/env bash
# Installs the build into an empty prefix, checks what is there, then configures, builds and runs
# the consumer project against that prefix alone (find_package(rockfall), rockfall::shapes, ...).
# Usage: install_consumer.sh CMAKE BUILD_DIR CONSUMER_SOURCE WORK_DIR SOURCE_DIR [CMAKE_ARGS...]
set -euo pipefail
cmake=$1 build=$2 consumer=$3 work=$4 source=$5
shift 5
fail() {
    echo "install_consumer.sh: $*" >&2
    exit 1
}

rm -rf "$work"
mkdir -p "$work"
prefix=$work/prefix
"$cmake" --install "$build" --prefix "$prefix" >"$work/install.log" ||
    fail "cmake --install $build failed (log: $work/install.log)"
config=$(find "$prefix" -name rockfallConfig.cmake)
[ -n "$config" ] || fail "no rockfallConfig.cmake under $prefix"
for file in bin/rockfall include/shapes/rocks.hpp include/db/results_db.hpp \
    share/man/man1/rockfall.1 share/bash-completion/completions/rockfall \
    share/rockfall/samples/seed_slope.toml; do
    [ -e "$prefix/$file" ] || fail "$prefix/$file was not installed"
done
# The installed package must not point back into the source or build tree.
if grep -rlF -e "$source/" -e "$build/" "$(dirname "$config")"; then
    fail "the CMake package above names the source or build tree"
fi
"$prefix/bin/rockfall" --version

"$cmake" -S "$consumer" -B "$work/build" -DCMAKE_PREFIX_PATH="$prefix" "$@" \
    >"$work/configure.log" 2>&1 || {
    cat "$work/configure.log" >&2
    fail "the consumer does not configure against $prefix"
}
"$cmake" --build "$work/build" >"$work/build.log" 2>&1 || {
    cat "$work/build.log" >&2
    fail "the consumer does not build against $prefix"
}
"$work/build/sphere_volume"
cd "$work"
"$work/build/simulate_scenario" "$prefix/share/rockfall/samples/seed_slope.toml"
# The prefix holds the unstripped static libraries (a few hundred MB): kept only on failure.
cd /
rm -rf "$work"
