#!/usr/bin/env bash
# sweep_shapes.sh ROCKFALL SCENARIO WORKDIR: a sweep over catalogue entries and generated rocks
# of a target sphericity; every sample must replay alone from the database bit for bit
# (`simulate --from`), catalogue entries and generated rocks must both be among them, every
# sample must have a stored sphericity, and `query --by shape` must break results down by them.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
db=$work/shapes.db
"$rockfall" sweep "$scenario" --db "$db" --threads 2 --quiet >/dev/null
samples=$(sqlite3 "$db" "SELECT count(*) FROM samples")
missing=$(sqlite3 "$db" "SELECT count(*) FROM samples WHERE sphericity IS NULL")
[ "$missing" -eq 0 ] || { echo "$missing samples have no sphericity"; exit 1; }
entries=0 generated=0
for ((i = 0; i < samples; i++)); do
    out=$("$rockfall" simulate --from "$db" --sample "$i")
    if ! grep -q "replay matches the database's stored outcome" <<<"$out"; then
        echo "sample $i does not replay:"; echo "$out"; exit 1
    fi
    grep -q "custom 'generated rock of sphericity" <<<"$out" && generated=$((generated + 1))
    grep -Eq "custom '(cube|octahedron|psi_0\.72|psi_0\.85)'" <<<"$out" && entries=$((entries + 1))
done
echo "$samples samples replayed: $entries catalogue entries, $generated generated rocks"
[ "$entries" -gt 0 ] && [ "$generated" -gt 0 ] || { echo "expected both kinds of shape"; exit 1; }
by_shape=$("$rockfall" query "$db" exceed --distance 0 --by shape)
grep -q "^generated " <<<"$by_shape" || { echo "no generated group:"; echo "$by_shape"; exit 1; }
echo "replay matches the database's stored outcome for every sample"
