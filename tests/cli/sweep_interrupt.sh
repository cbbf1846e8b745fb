#!/usr/bin/env bash
# sweep_interrupt.sh ROCKFALL SCENARIO WORKDIR: Ctrl-C (SIGINT) during a sweep stores the
# finished samples, marks the run interrupted and exits 130; --resume then completes it.
# A SIGINT while the database is being created (sent by the sweep to itself just before, with
# the hidden --interrupt-at-create) ends the run the same way: a whole file marked interrupted,
# no hidden part file left, exit 130, and --resume completes it.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
rm -rf "$work" && mkdir -p "$work"
# shellcheck source=paused.sh
source "$(dirname "$0")/paused.sh"
db="$work/interrupted.db"
# The sweep stops itself (SIGSTOP, the hidden --pause-after) once 5 samples are stored; the
# SIGINT sent while it is stopped is taken on SIGCONT, mid-run however fast the machine is.
"$rockfall" sweep "$scenario" --db "$db" --threads 1 --samples 600 --pause-after 5 \
    >"$work/out.txt" 2>&1 &
pid=$!
if ! wait_stopped "$pid"; then
    cat "$work/out.txt"
    echo "the sweep did not pause after 5 samples"; exit 1
fi
kill -INT "$pid"
kill -CONT "$pid"
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

early="$work/early.db"
set +e
"$rockfall" sweep "$scenario" --db "$early" --threads 1 --samples 100 --quiet --interrupt-at-create \
    >"$work/early.txt" 2>&1
code=$?
set -e
cat "$work/early.txt"
[ "$code" -eq 130 ] || { echo "SIGINT at creation: expected exit 130, got $code"; exit 1; }
[ "$(sqlite3 "file:$early?mode=ro" "SELECT status FROM run")" = interrupted ]
parts=$(find "$work" -name '.early.db.*')
[ -z "$parts" ] || { echo "SIGINT at creation left part files: $parts"; exit 1; }
echo "SIGINT at creation: a whole database marked interrupted, no part file"
"$rockfall" sweep "$scenario" --db "$early" --threads 2 --samples 100 --resume --quiet >/dev/null
[ "$(sqlite3 "$early" "SELECT count(*) FROM samples")" = 100 ]
echo "resumed to 100 samples, complete"
