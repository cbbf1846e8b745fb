#!/usr/bin/env bash
# Installs every Debian 12 package rockfall needs to build, test and run.
# Idempotent; run as root. Uses apt only; nothing else is downloaded.
set -euo pipefail

packages=(
    # toolchain
    build-essential cmake ninja-build pkg-config git ccache
    # physics, geometry, maths
    libbullet-dev libeigen3-dev libqhull-dev libassimp-dev
    # assimp's CMake targets (assimpTargets.cmake) link /usr/lib/x86_64-linux-gnu/libz.so, but
    # libassimp-dev does not depend on zlib1g-dev: without it the link step has no rule for it
    zlib1g-dev
    # storage and command line
    libsqlite3-dev sqlite3 libcli11-dev libtomlplusplus-dev nlohmann-json3-dev
    # sweeps over MPI ranks (optional at build time; docs/cluster.md)
    libopenmpi-dev openmpi-bin
    # tests and format check
    catch2 clang-format
    # the HTML report test parses the report as XML (tests/cli/report_html.sh)
    libxml2-utils
    # fuzz targets (scripts/fuzz.sh, run by CI): clang and its libFuzzer runtime
    clang libclang-rt-14-dev
    # the Debian package (CPack's DEB generator runs `file` to find the binaries it hands to
    # dpkg-shlibdeps; a bare Debian 12 with --no-install-recommends has no `file`)
    file dpkg-dev
)

missing=()
for p in "${packages[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
    echo "install-deps.sh: all ${#packages[@]} packages already installed"
    exit 0
fi

if [ "$(id -u)" -ne 0 ]; then
    echo "install-deps.sh: must run as root to install: ${missing[*]}" >&2
    exit 1
fi

export DEBIAN_FRONTEND=noninteractive
apt-get update -qq
apt-get install -y -qq --no-install-recommends "${missing[@]}"
echo "install-deps.sh: installed ${missing[*]}"
