#!/usr/bin/env bash
# sweep_interrupt.sh ROCKFALL SCENARIO WORKDIR: Ctrl-C (SIGINT) during a sweep stores the
# finished samples, marks the run interrupted and exits 130; --resume then completes it. 600
# samples take about 10 s on one thread, so the interrupt comes long before the end even on a
# loaded machine (the first batch is stored after 1 s).
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
db="$work/interrupted.db"
"$rockfall" sweep "$scenario" --db "$db" --threads 1 --samples 600 >"$work/out.txt" 2>&1 &
pid=$!
# Wait until some samples are stored, then interrupt.
for _ in $(seq 100); do
    sleep 0.1
    n=$(sqlite3 "$db" "SELECT count(*) FROM samples" 2>/dev/null || echo 0)
    [ "${n:-0}" -gt 0 ] && break
done
kill -INT "$pid"
set +e
wait "$pid"
code=$?
set -e
cat "$work/out.txt"
[ "$code" -eq 130 ] || { echo "expected exit 130 after SIGINT, got $code"; exit 1; }
grep -q "continue with the same command and --resume" "$work/out.txt"
[ "$(sqlite3 "$db" "SELECT status FROM run")" = interrupted ]
stored=$(sqlite3 "$db" "SELECT count(*) FROM samples")
[ "$stored" -gt 0 ] && [ "$stored" -lt 600 ] || { echo "expected a partial run, got $stored"; exit 1; }
echo "interrupted with $stored of 600 samples stored"
"$rockfall" sweep "$scenario" --db "$db" --threads 2 --samples 600 --resume --quiet >/dev/null
[ "$(sqlite3 "$db" "SELECT count(*) FROM samples")" = 600 ]
[ "$(sqlite3 "$db" "SELECT status FROM run")" = complete ]
echo "resumed to 600 samples, complete"
