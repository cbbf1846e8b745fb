#!/usr/bin/env bash
# bad_numbers.sh ROCKFALL SCENARIO SWEEP_SCENARIO WORKDIR: whole-number options take one rule.
# - Every command with --seed refuses a negative, an overflowing, a hex and a blank-padded seed
#   with exit 2 and a message naming --seed and the range [0, 2^64 - 1]; a sweep writes nothing.
# - A seed with leading zeros is read in decimal (010 is 10, not octal 8); 2^64 - 1 is accepted.
set -euo pipefail
rockfall=$1 scenario=$2 sweep=$3 work=$4
rm -rf "$work" && mkdir -p "$work"

range='a seed must be a whole number in \[0, 18446744073709551615\], written in decimal'
refused() {  # refused VALUE COMMAND...: exit 2, --seed and the range named
    local value=$1 out code
    shift
    set +e
    out=$("$@" --seed "$value" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || { echo "--seed '$value' on '$*': expected exit 2, got $code: $out"; exit 1; }
    grep -Eq -- "--seed: $value( is out of range)?: $range" <<<"$out" ||
        { echo "--seed '$value' on '$*': unexpected message: $out"; exit 1; }
}
for value in -1 -0 18446744073709551616 99999999999999999999999 0x10 " 5" 1e3 ""; do
    refused "$value" "$rockfall" simulate "$scenario"
    refused "$value" "$rockfall" shape --generate sphericity --sphericity 0.8
    refused "$value" "$rockfall" terrain "$scenario"
    refused "$value" "$rockfall" sweep "$sweep" --db "$work/never.db" --quiet
    [ ! -e "$work/never.db" ] || { echo "a refused seed left $work/never.db"; exit 1; }
done
echo "every --seed refused the bad values with the range"

"$rockfall" simulate "$scenario" --seed 010 | grep -q ", seed 10, " ||
    { echo "--seed 010 should be read as decimal 10"; exit 1; }
"$rockfall" simulate "$scenario" --seed 18446744073709551615 | grep -q ", seed 18446744073709551615, " ||
    { echo "--seed 2^64 - 1 should be accepted"; exit 1; }
echo "--seed 010 is 10 and 2^64 - 1 is accepted"
