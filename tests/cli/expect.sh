#!/usr/bin/env bash
# expect.sh CODE REGEX CMD...: runs CMD, passes when it exits with CODE ("nonzero" for any
# non-zero code) and its combined output matches the extended REGEX.
set -u
want=$1 regex=$2
shift 2
out=$("$@" 2>&1)
code=$?
if [ "$want" = nonzero ]; then
    [ "$code" -ne 0 ] || { echo "expected a non-zero exit, got 0"; echo "$out"; exit 1; }
elif [ "$code" -ne "$want" ]; then
    echo "expected exit $want, got $code"; echo "$out"; exit 1
fi
if ! grep -Eq -- "$regex" <<<"$out"; then
    echo "output does not match /$regex/:"; echo "$out"; exit 1
fi
echo "ok: exit $code, output matches /$regex/"
