#!/usr/bin/env bash
# sweep_resume.sh ROCKFALL SCENARIO WORKDIR [SWEEP OPTIONS...]: a sweep crashed in the middle
# of a batch and then resumed must store exactly what an uninterrupted sweep stores, whatever
# the thread counts of the two.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work"
"$rockfall" sweep "$scenario" --db "$work/whole.db" --threads 2 --quiet "$@" >/dev/null

set +e
"$rockfall" sweep "$scenario" --db "$work/crashed.db" --threads 1 --quiet --crash-after 10 "$@" \
    >/dev/null 2>&1
code=$?
set -e
[ "$code" -eq 3 ] || { echo "the crash run should exit 3, got $code"; exit 1; }
stored=$(sqlite3 "$work/crashed.db" "SELECT count(*) FROM samples")
echo "after the crash: $stored samples stored"
[ "$stored" -ge 10 ] && [ "$stored" -lt 20 ] || { echo "expected 10 to 19 samples stored before the crash"; exit 1; }
# The half-written transaction must not be visible.
[ "$(sqlite3 "$work/crashed.db" "SELECT count(*) FROM zones WHERE name = 'half-written'")" = 0 ]

"$rockfall" sweep "$scenario" --db "$work/crashed.db" --threads 2 --quiet --resume "$@" >/dev/null

for table in samples rocks outcomes stations wall_impacts; do
    a=$(sqlite3 "$work/whole.db" "SELECT * FROM $table ORDER BY 1, 2, 3")
    b=$(sqlite3 "$work/crashed.db" "SELECT * FROM $table ORDER BY 1, 2, 3")
    [ "$a" = "$b" ] || { echo "table $table differs after the resume"; exit 1; }
    echo "$table: $(wc -l <<<"$a") rows, identical"
done
[ "$(sqlite3 "$work/crashed.db" "SELECT status FROM run")" = complete ]
echo "resumed sweep equals the uninterrupted one"
