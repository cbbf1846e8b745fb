#!/usr/bin/env bash
# validate_seed001.sh ROCKFALL: `rockfall validate` as CI can afford it: the physical rows over
# one cluster seed (6 runs, about 2 minutes on 2 cores; the whole reproduction is 90 runs,
# docs/validation.md). Checks that the six case files load and run, that the tables are there
# with every cell (numerical cells without runs say "no value"), that at least 20 of the 24
# painted rocks travelled 1.4 m and got a camera speed, and that the 20 trends are printed
# with the paper's own verdicts (all hold for Table 2).
set -euo pipefail
rockfall=$1

out=$("$rockfall" validate --quick --rows physical --seeds 1 --threads 0 --quiet)
echo "$out"
for table in "Table 2, numerical rows" "Table 2, physical rows" "speeds at 1.4 m of travel"; do
    grep -q "$table" <<<"$out" || { echo "no table: $table"; exit 1; }
done
[ "$(grep -Ec '^  peak force, (tetrahedron|cube|octahedron|sphere), .*no value' <<<"$out")" -eq 24 ] ||
    { echo "expected 24 numerical cells without runs"; exit 1; }
[ "$(grep -Ec '^  peak force, (yellow|green|blue|red), ' <<<"$out")" -eq 24 ] ||
    { echo "expected 24 physical cells"; exit 1; }
# A painted rock may stay short of 1.4 m in the 2.5 s run (one of 24 for seed 1).
[ "$(grep -Ec '^  speed at 1\.4 m, (yellow|green|blue|red), .* 1/1 ' <<<"$out")" -ge 20 ] ||
    { echo "expected a camera speed at 1.4 m for at least 20 of the 24 painted rocks"; exit 1; }
[ "$(grep -c '(Table 2: holds)' <<<"$out")" -eq 20 ] || { echo "expected 20 trends, all holding in Table 2"; exit 1; }
grep -q "^6 runs, " <<<"$out" || { echo "expected 6 runs"; exit 1; }
