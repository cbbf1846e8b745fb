#!/usr/bin/env bash
# Makes the Debian packages with CPack from the build and checks their names, contents and
# dependencies (dpkg-shlibdeps must have found the program's shared libraries). Exits 77 (skipped)
# without dpkg-deb and dpkg-shlibdeps (package dpkg-dev).
# Usage: debian_package.sh BUILD_DIR WORK_DIR VERSION
set -euo pipefail
build=$1 work=$2 version=$3
fail() {
    echo "debian_package.sh: $*" >&2
    exit 1
}
for tool in cpack dpkg-deb dpkg-shlibdeps; do
    command -v "$tool" >/dev/null || {
        echo "debian_package.sh: $tool not found (Debian: apt install dpkg-dev); skipped"
        exit 77
    }
done

rm -rf "$work"
mkdir -p "$work"
cpack --config "$build/CPackConfig.cmake" -B "$work" >"$work/cpack.log" 2>&1 || {
    cat "$work/cpack.log" >&2
    fail "cpack failed"
}
arch=$(dpkg --print-architecture)
program=$work/rockfall_${version}_${arch}.deb
dev=$work/rockfall-dev_${version}_${arch}.deb
[ -f "$program" ] || fail "no $(basename "$program"); made: $(cd "$work" && echo ./*.deb)"
[ -f "$dev" ] || fail "no $(basename "$dev"); made: $(cd "$work" && echo ./*.deb)"

contents=$(dpkg-deb -c "$program")
for file in ./usr/bin/rockfall ./usr/share/man/man1/rockfall.1 \
    ./usr/share/bash-completion/completions/rockfall ./usr/share/rockfall/samples/seed_slope.toml; do
    grep -qF " $file" <<<"$contents" || fail "$(basename "$program") lacks $file"
done
dev_contents=$(dpkg-deb -c "$dev")
for file in /include/shapes/rocks.hpp /librockfall_engine.a /rockfallConfig.cmake \
    /rockfallConfigVersion.cmake /rockfallTargets.cmake /RockfallBullet.cmake; do
    grep -qF "$file" <<<"$dev_contents" || fail "$(basename "$dev") lacks */${file#/}"
done

# The program's runtime libraries, found by dpkg-shlibdeps from what the binary links.
depends=$(dpkg-deb -f "$program" Depends)
echo "Depends: $depends"
for package in libc6 libstdc++6 libbullet libassimp libqhull libsqlite3 libtomlplusplus; do
    grep -q "$package" <<<"$depends" || fail "Depends of $(basename "$program") lacks $package"
done
grep -qF "rockfall (= $version)" <<<"$(dpkg-deb -f "$dev" Depends)" ||
    fail "$(basename "$dev") does not depend on rockfall (= $version)"
echo "debian_package.sh: $(basename "$program") and $(basename "$dev") checked"
rm -rf "$work/_CPack_Packages"
