#!/usr/bin/env bash
# soil_refine.sh ROCKFALL QUICK_2D SEED_3D WORKDIR: `rockfall soil --refine` as a user runs it.
# Each level of the study is the single run at that cell size (its peak and steady load, its
# runout), the extrapolation is Richardson's from the three levels printed, progress goes to
# standard error, and 3D studies print kN where 2D ones print kN/m.
set -euo pipefail
rockfall=$1 quick=$2 seed=$3 work=$4
rm -rf "$work" && mkdir -p "$work"

# One number of a JSON document by its key; the n-th occurrence (default 1).
value() { grep -Eo "\"$2\": [-0-9.e+]+" <<<"$1" | sed -n "${3:-1}p" | awk '{print $2}'; }
# Passes when |a - b| <= tol * |b|.
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; m = b < 0 ? -b : b; exit !(d <= t * m) }'; }

"$rockfall" soil "$quick" --refine 0.2,0.1,0.05 --json >"$work/study.json" 2>"$work/progress.txt"
study=$(cat "$work/study.json")
[ "$(grep -c '^refinement level [1-3] of 3: cell .* kN/m' "$work/progress.txt")" -eq 3 ] ||
    { echo "expected 3 progress lines on stderr:"; cat "$work/progress.txt"; exit 1; }
[ "$(grep -c '"cell_size_m"' <<<"$study")" -eq 3 ] || { echo "expected 3 levels"; exit 1; }

# The finest level against a single run at 0.05 m cells: the same scenario, the same loads.
printf 'extends = "%s"\n[numerics]\ncell_size = 0.05\n' "$quick" >"$work/fine.toml"
single=$("$rockfall" soil "$work/fine.toml" --json)
for key in peak_wall_force_N_per_m peak_wall_force_filtered_N_per_m runout_past_toe_m; do
    a=$(value "$study" "$key" 3) b=$(value "$single" "$key")
    close "$a" "$b" 1e-9 || { echo "level 3 $key = $a but the single run gives $b"; exit 1; }
done

# Richardson from the three printed steady loads (they converge monotonically; the peaks do
# not since volumetric averaging): p = ln((f1 - f2) / (f2 - f3)) / ln 2.
f1=$(value "$study" steady_wall_force_N_per_m 1) f2=$(value "$study" steady_wall_force_N_per_m 2)
f3=$(value "$study" steady_wall_force_N_per_m 3)
want=$(awk -v a="$f1" -v b="$f2" -v c="$f3" 'BEGIN { q = (a - b) / (b - c); p = log(q) / log(2); printf "%.12g %.12g", p, c + (c - b) / (2 ^ p - 1) }')
steady=$(grep -A4 '"steady_wall_force_N_per_m": {' <<<"$study")
order=$(value "$steady" observed_order) extrapolated=$(value "$steady" extrapolated)
close "$order" "${want% *}" 1e-9 || { echo "observed order $order, expected ${want% *}"; exit 1; }
close "$extrapolated" "${want#* }" 1e-9 ||
    { echo "extrapolated steady load $extrapolated, expected ${want#* }"; exit 1; }

# The text table: units on the columns and one of the two verdicts per quantity.
text=$("$rockfall" soil "$quick" --refine 0.2,0.1,0.05 2>/dev/null)
grep -Eq 'peak \(kN/m\) +t peak \(s\) +filtered \(kN/m\) +steady \(kN/m\) +runout \(m\)' <<<"$text" ||
    { echo "no 2D table header:"; echo "$text"; exit 1; }
[ "$(grep -Ec '^  (peak wall load|time of peak|filtered peak|steady wall load|runout past toe) +([0-9.]+ (kN/m|s|m), observed order|not converging monotonically)' <<<"$text")" -eq 5 ] ||
    { echo "expected 5 extrapolation lines:"; echo "$text"; exit 1; }

# 3D: a short flow at coarse cells, loads in kN.
printf 'extends = "%s"\n[output]\nduration = 0.3\n' "$seed" >"$work/short_3d.toml"
text=$("$rockfall" soil "$work/short_3d.toml" --refine 0.4,0.3,0.2 --steady-window 0.1 2>/dev/null)
grep -q '3D, 0.3 s of flow; steady load = mean over the last 0.1 s' <<<"$text" &&
    grep -Eq 'peak \(kN\) +t peak \(s\) +filtered \(kN\) +steady \(kN\) +runout \(m\)' <<<"$text" ||
    { echo "no 3D table:"; echo "$text"; exit 1; }
echo "ok: soil --refine"
