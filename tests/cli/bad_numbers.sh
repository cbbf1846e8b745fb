#!/usr/bin/env bash
# bad_numbers.sh ROCKFALL SCENARIO SWEEP_SCENARIO WORKDIR: whole-number options take one rule.
# - Every command with --seed refuses a negative, an overflowing, a hex and a blank-padded seed
#   with exit 2 and a message naming --seed and the range [0, 2^64 - 1]; a sweep writes nothing.
# - A seed with leading zeros is read in decimal (010 is 10, not octal 8); 2^64 - 1 is accepted.
# - --samples out of [1, 10^8] is refused naming --samples; the file's sweep.samples, naming the
#   key with its file and line.
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

for value in 0 100000001 1099511627776 -1 99999999999999999999; do
    set +e
    out=$("$rockfall" sweep "$sweep" --db "$work/never.db" --quiet --samples "$value" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] &&
        grep -Eq -- "^--samples: $value( is out of range)?: a sample count must be a whole number in \[1, 100000000\]" <<<"$out" &&
        ! grep -q "sweep.samples" <<<"$out" ||
        { echo "--samples $value: expected exit 2 naming --samples, got $code: $out"; exit 1; }
    [ ! -e "$work/never.db" ] || { echo "a refused --samples left $work/never.db"; exit 1; }
done
printf 'extends = "%s"\n[sweep]\nsamples = 100000001\n' "$(realpath "$sweep")" >"$work/huge.toml"
set +e
out=$("$rockfall" sweep "$work/huge.toml" --db "$work/never.db" --quiet 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "sweep.samples = 100000001: must be in \[1, 100000000\], the most one sweep plans (.*huge.toml:3)" <<<"$out" ||
    { echo "sweep.samples = 100000001: expected exit 2 naming the key, got $code: $out"; exit 1; }
echo "--samples out of range names --samples, the file's key names sweep.samples"
