#!/usr/bin/env bash
# sweep_shards.sh ROCKFALL SCENARIO WORKDIR [SWEEP OPTIONS...]: a sweep run as three shards
# (`--shard K/3`, one of them crashed and continued with `--resume` alone) and merged equals
# the one-process sweep with the same options table by table, row by row; the run record too.
# Merging refuses a gap (unless --allow-gaps: the merged run then completes with --resume and
# equals the one-process sweep), an overlap, a shard of another run, a foreign and a corrupt
# file, and an existing OUT, each with exit 2 and leaving no OUT and no temporary file.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# shellcheck source=same_run.sh
source "$(dirname "$0")/same_run.sh"
"$rockfall" sweep "$scenario" --db "$work/whole.db" --threads 2 --quiet "$@" >/dev/null

"$rockfall" sweep "$scenario" --db "$work/s0.db" --shard 0/3 --threads 2 --quiet "$@" >/dev/null
set +e
"$rockfall" sweep "$scenario" --db "$work/s1.db" --shard 1/3 --threads 1 --quiet --crash-after 2 \
    "$@" >/dev/null 2>&1
code=$?
set -e
[ "$code" -eq 3 ] || fail "the crashed shard should exit 3, got $code"
(cd / && "$rockfall" sweep --db "$work/s1.db" --resume --quiet >/dev/null)
"$rockfall" sweep "$scenario" --db "$work/s2.db" --shard 2/3 --threads 1 --quiet "$@" >/dev/null
for k in 0 1 2; do
    bad=$(sqlite3 "$work/s$k.db" "SELECT count(*) FROM samples WHERE sample % 3 != $k")
    [ "$bad" -eq 0 ] || fail "shard $k/3 holds $bad samples of other shards"
    [ "$(sqlite3 "$work/s$k.db" "SELECT json_extract(settings_json, '$.shard') FROM run")" = "$k/3" ] ||
        fail "shard $k/3 does not record its shard"
done

out=$("$rockfall" merge "$work/merged.db" "$work/s2.db" "$work/s0.db" "$work/s1.db" 2>&1)
grep -q "merged 3 files ([0-9]* of [0-9]* samples) into .*merged.db: complete" <<<"$out" ||
    fail "merge: $out"
same_run "$work/whole.db" "$work/merged.db"
echo "3 shards merged equal the one-process sweep: $(sqlite3 "$work/merged.db" \
    "SELECT count(*) FROM samples") samples, $(sqlite3 "$work/merged.db" "SELECT count(*) FROM outcomes") rocks"

# refused MESSAGE FILES...: merging FILES into refused.db exits 2 saying MESSAGE, leaving nothing.
refused() {
    local message=$1 out code
    shift
    set +e
    out=$("$rockfall" merge "$work/refused.db" "$@" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || fail "merge $*: expected exit 2, got $code: $out"
    grep -qE -- "$message" <<<"$out" || fail "merge $*: expected /$message/, got: $out"
    [ ! -e "$work/refused.db" ] || fail "a refused merge left refused.db"
    [ -z "$(find "$work" -name '*.part*')" ] || fail "a refused merge left a temporary file"
    echo "refused: $out"
}
refused "[0-9]+ of the run's [0-9]+ planned samples are in none of the files \\(samples 1, 4, .*no file given is shard 1/3.*--allow-gaps" \
    "$work/s0.db" "$work/s2.db"
cp "$work/s0.db" "$work/copy0.db"
refused "s0.db \\(shard 0/3\\) and .*copy0.db \\(shard 0/3\\) both hold sample 0" \
    "$work/s0.db" "$work/s1.db" "$work/s2.db" "$work/copy0.db"
refused "given twice" "$work/s0.db" "$work/s1.db" "$work/s0.db"
# A shard of another run (here: another seed, the check before the scenario hash's).
cp "$work/s1.db" "$work/other.db"
sqlite3 "$work/other.db" "UPDATE run SET seed = 99"
refused "other.db is not a shard of the run in .*s0.db: its seed is 99, not" \
    "$work/s0.db" "$work/other.db" "$work/s2.db"
sqlite3 "$work/foreign.db" "CREATE TABLE t (x); INSERT INTO t VALUES (1)"
refused "foreign.db is an SQLite database but not a rockfall results database" \
    "$work/s0.db" "$work/foreign.db"
refused "not an SQLite database" "$work/s0.db" "$scenario"
# A shard whose pages past the first are overwritten: quick_check (or SQLite itself) says so.
cp "$work/s2.db" "$work/corrupt.db"
size=$(stat -c %s "$work/corrupt.db")
head -c $((size - 4096)) /dev/urandom | dd of="$work/corrupt.db" bs=4096 seek=1 conv=notrunc status=none
refused "corrupt.db.*(corrupt|malformed|damaged|not a database)" "$work/s0.db" "$work/s1.db" "$work/corrupt.db"
set +e
out=$("$rockfall" merge "$work/merged.db" "$work/s0.db" "$work/s1.db" "$work/s2.db" 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "merged.db exists already" <<<"$out" || fail "merge over a file: $code $out"
same_run "$work/whole.db" "$work/merged.db"

# With --allow-gaps the merged run is interrupted; --resume alone runs the missing samples.
out=$("$rockfall" merge "$work/gaps.db" "$work/s0.db" "$work/s2.db" --allow-gaps 2>&1)
grep -q "samples missing; run them with .rockfall sweep --db .*gaps.db --resume" <<<"$out" ||
    fail "merge --allow-gaps: $out"
[ "$(sqlite3 "$work/gaps.db" "SELECT status FROM run")" = interrupted ] ||
    fail "a merged run with gaps should be interrupted"
"$rockfall" sweep --db "$work/gaps.db" --resume --quiet >/dev/null
same_run "$work/whole.db" "$work/gaps.db"
echo "merged with gaps, then resumed: equal to the one-process sweep"
