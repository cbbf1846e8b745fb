#!/usr/bin/env bash
# calibrate_drop.sh ROCKFALL CATALOGUE WORKDIR: `rockfall calibrate drop` as a user runs it.
# A sphere's COR is the contact restitution; the per-drop CSV is the same for the same seed
# on 1 and 2 threads and differs for another seed; the identified fragment is read by a
# scenario that extends it (and a broken value in it is reported at the fragment's line).
set -euo pipefail
rockfall=$1 catalogue=$2 work=$3
rm -rf "$work" && mkdir -p "$work"

out=$("$rockfall" calibrate drop --kind sphere --count 3 --restitution 0.5 --quiet)
# Contact restitution (0.3 + 0.5) / 2 = 0.4: the COR from speeds is 0.4000.
grep -Eq "kinematic COR, speeds v_out/v_in +0\.(399[5-9]|400[0-5])" <<<"$out" ||
    { echo "sphere COR from speeds is not 0.4:"; echo "$out"; exit 1; }

"$rockfall" calibrate drop "$catalogue" --entry cube --count 4 --seed 7 --threads 1 --quiet \
    --csv "$work/one.csv" >/dev/null
"$rockfall" calibrate drop "$catalogue" --entry cube --count 4 --seed 7 --threads 2 --quiet \
    --csv "$work/two.csv" >/dev/null
"$rockfall" calibrate drop "$catalogue" --entry cube --count 4 --seed 8 --threads 2 --quiet \
    --csv "$work/other.csv" >/dev/null
[ "$(wc -l <"$work/one.csv")" -eq 5 ] || { echo "expected 4 drops and a header"; exit 1; }
cmp "$work/one.csv" "$work/two.csv" || { echo "1 and 2 threads differ"; exit 1; }
if cmp -s "$work/one.csv" "$work/other.csv"; then echo "seeds 7 and 8 give the same drops"; exit 1; fi

json=$("$rockfall" calibrate drop --kind sphere --count 2 --target-cor 0.3 --json \
    --fragment "$work/fragment.toml" --svg "$work/curve.svg")
identified=$(grep -Eo '"surface_restitution": [0-9.e-]+' <<<"$json" | tail -1 | cut -d' ' -f2)
grep -q "^restitution = " "$work/fragment.toml" || { echo "no restitution in fragment"; exit 1; }
written=$(sed -n 's/^restitution = //p' "$work/fragment.toml")
awk -v a="$identified" -v b="$written" 'BEGIN { exit !(a - b < 1e-12 && b - a < 1e-12) }' ||
    { echo "fragment restitution $written is not the identified $identified"; exit 1; }
grep -q "<svg" "$work/curve.svg" || { echo "no SVG figure"; exit 1; }

printf 'extends = "fragment.toml"\n[numerics]\nmax_time = 0.05\n' >"$work/uses_fragment.toml"
"$rockfall" simulate "$work/uses_fragment.toml" >/dev/null
sed -i 's/^restitution = .*/restitution = 2/' "$work/fragment.toml"
if err=$("$rockfall" simulate "$work/uses_fragment.toml" 2>&1); then
    echo "a broken fragment was accepted"; exit 1
fi
grep -q "materials.slope.restitution = 2.*fragment.toml" <<<"$err" ||
    { echo "the error does not name the fragment:"; echo "$err"; exit 1; }
echo "calibrate drop: COR, determinism, fragment and extends all as expected"
