#!/usr/bin/env bash
# validate_seed001.sh ROCKFALL NUMERICAL PHYSICAL SPEEDS: `rockfall validate` over one cluster
# seed (all 30 runs of seed 001's reproduction, about 5 minutes on 2 cores). Checks that every
# table is there, that every numerical cell got a value, that the counts of cells within their
# targets are at least NUMERICAL, PHYSICAL and SPEEDS (the counts docs/validation.md reports for
# seed 1, so that a change that loses agreement fails here), and that the trends are printed
# with the paper's own verdicts (all hold for Table 2).
set -euo pipefail
rockfall=$1 numerical=$2 physical=$3 speeds=$4

out=$("$rockfall" validate --seeds 1 --threads 0 --quiet)
echo "$out"
for table in "Table 2, numerical rows" "Table 2, physical rows" "speeds at 1.4 m of travel"; do
    grep -q "$table" <<<"$out" || { echo "no table: $table"; exit 1; }
done
[ "$(grep -c '^  peak force, \(tetrahedron\|cube\|octahedron\|sphere\), ' <<<"$out")" -eq 24 ] ||
    { echo "expected 24 numerical cells"; exit 1; }
if grep -E '^  peak force, (tetrahedron|cube|octahedron|sphere), .*no value' <<<"$out"; then
    echo "a numerical cell has no value"; exit 1
fi
counts=$(grep -Eo '^  [0-9]+ of 24 within' <<<"$out" | awk '{print $1}' | tr '\n' ' ')
read -r got_numerical got_physical got_speeds <<<"$counts"
[ "$got_numerical" -ge "$numerical" ] || { echo "numerical cells within 25 %: $got_numerical < $numerical"; exit 1; }
[ "$got_physical" -ge "$physical" ] || { echo "physical cells within 25 %: $got_physical < $physical"; exit 1; }
[ "$got_speeds" -ge "$speeds" ] || { echo "speeds within 20 %: $got_speeds < $speeds"; exit 1; }
[ "$(grep -c '(Table 2: holds)' <<<"$out")" -eq 20 ] || { echo "expected 20 trends, all holding in Table 2"; exit 1; }
echo "validate_seed001: $got_numerical, $got_physical and $got_speeds of 24 within target"
