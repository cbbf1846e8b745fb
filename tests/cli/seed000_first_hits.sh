#!/usr/bin/env bash
# seed000_first_hits.sh ROCKFALL SAMPLES WORKDIR: seed 000's shape coefficient of massive rocks
# from their arrivals at the wall (rockfall fit --first-hits), with the rounded-polyhedron wall
# law and the wall calibrated on spheres (samples/seed_sweep_calibrated_wall.toml, 600 samples,
# about 15 s on 2 cores). The paper's finding, not its numbers: blocks load the wall less than
# spheres of the same mass and speed (beta < 1) and scatter more (alpha > the spheres' 1). Over
# every hit, slow re-contacts raise beta (docs/wall_contact.md: 1.18 against 0.77 on arrivals).
set -euo pipefail
rockfall=$1 samples=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
printf 'extends = "%s"\n[wall_contact]\nhull_model = "rounded"\n' \
    "$samples/seed_sweep_calibrated_wall.toml" >"$work/rounded.toml"
"$rockfall" sweep "$work/rounded.toml" --db "$work/s.db" --samples 600 --quiet >/dev/null

# One number of a JSON document by its key (first occurrence).
value() { grep -Eo "\"$2\": [-0-9.e+]+" <<<"$1" | head -1 | awk '{print $2}'; }
first=$("$rockfall" fit "$work/s.db" --shape massive --first-hits --json)
every=$("$rockfall" fit "$work/s.db" --shape massive --json)
beta=$(value "$first" beta) alpha=$(value "$first" alpha) beta_every=$(value "$every" beta)
echo "massive, rounded law: beta $beta, alpha $alpha on first hits; beta $beta_every over every hit"
awk -v b="$beta" -v a="$alpha" -v e="$beta_every" 'BEGIN { exit !(b > 0 && b < 1 && a > 1 && e > b) }' ||
    { echo "expected 0 < beta < 1, alpha > 1 and beta over every hit above beta on first hits"; exit 1; }
echo "ok: seed 000 first hits"
