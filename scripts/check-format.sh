#!/usr/bin/env bash
# Fails when a C++ source differs from .clang-format (CI checks formatting, never rewrites it).
set -euo pipefail
cd "$(dirname "$0")/.."
if ! command -v clang-format >/dev/null; then
    echo "check-format.sh: clang-format not installed; skipping the format check"
    exit 0
fi
files=$(git ls-files '*.cpp' '*.hpp')
[ -z "$files" ] && exit 0
# shellcheck disable=SC2086
if ! clang-format --dry-run --Werror $files; then
    echo "check-format.sh: run clang-format -i on the files above" >&2
    exit 1
fi
echo "check-format.sh: $(echo "$files" | wc -w) files formatted"
