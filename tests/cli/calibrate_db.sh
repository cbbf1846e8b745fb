#!/usr/bin/env bash
# calibrate_db.sh ROCKFALL WORKDIR HEAP_OPTIONS...: `rockfall calibrate drop|heap --db` as a
# user runs it. The database holds what --json printed (the identified restitution to the last
# digit), reads with sqlite3 and `rockfall query DB summary`, is never replaced, and is refused
# by the rock-sweep queries with a message naming what it holds.
set -euo pipefail
rockfall=$1 work=$2
shift 2
rm -rf "$work" && mkdir -p "$work"
fail() { echo "$@"; exit 1; }

json=$("$rockfall" calibrate drop --kind sphere --count 3 --target-cor 0.3 --json \
    --db "$work/drop.db")
printed=$(grep -Eo '"surface_restitution": [0-9.e-]+' <<<"$json" | tail -1 | cut -d' ' -f2)
stored=$(sqlite3 "$work/drop.db" "SELECT printf('%.17g', value) FROM calibration_identified")
awk -v a="$printed" -v b="$stored" 'BEGIN { exit !(a - b < 1e-12 && b - a < 1e-12) }' ||
    fail "stored restitution $stored is not the printed $printed"
[ "$(sqlite3 "$work/drop.db" "SELECT count(*) FROM drop_tests")" = 3 ] || fail "not 3 drops"
[ "$(sqlite3 "$work/drop.db" "SELECT kind || ' ' || method || ' ' || status FROM run")" = \
    "drop_test drop_test complete" ] || fail "run row is not a complete drop test"
points=$(sqlite3 "$work/drop.db" "SELECT count(*) FROM calibration_curve WHERE refinement = 0")
[ "$points" = 11 ] || fail "expected the 11 points of the default curve, got $points"
sqlite3 "$work/drop.db" "SELECT json_extract(settings_json, '\$.\"target-cor\"') FROM run" |
    grep -qx "0.3" || fail "settings_json does not hold --target-cor 0.3"

summary=$("$rockfall" query "$work/drop.db" summary)
grep -q "drop test" <<<"$summary" || fail "summary does not say drop test: $summary"
grep -q "sphere" <<<"$summary" || fail "summary has no sphere row: $summary"
"$rockfall" query "$work/drop.db" summary --json | grep -q '"kind": "drop_test"' ||
    fail "JSON summary has no kind"

before=$(sha256sum <"$work/drop.db")
if err=$("$rockfall" calibrate drop --kind sphere --count 1 --quiet --db "$work/drop.db" 2>&1); then
    fail "an existing database was accepted"
else
    code=$?
fi
[ "$code" = 2 ] || fail "exit $code for an existing database, not 2"
grep -q "drop.db" <<<"$err" || fail "the error does not name the file: $err"
[ "$(sha256sum <"$work/drop.db")" = "$before" ] || fail "the existing database was changed"

if err=$("$rockfall" query "$work/drop.db" percentiles --of reach 2>&1); then
    fail "a sweep query read a drop test"
fi
grep -q "holds a drop test" <<<"$err" || fail "the sweep query's error does not say so: $err"

"$rockfall" calibrate heap --kind sphere "$@" --db "$work/heap.db" >/dev/null
[ "$(sqlite3 "$work/heap.db" "SELECT count(*) FROM heap_tests")" = 1 ] || fail "not 1 heap"
[ "$(sqlite3 "$work/heap.db" "SELECT count(*) FROM heap_planes")" = 8 ] || fail "not 8 planes"
"$rockfall" query "$work/heap.db" summary --csv | grep -q "^shape,label" ||
    fail "no CSV summary of the heap test"
echo "calibrate --db: stored as printed, read back, never replaced, refused by sweep queries"
