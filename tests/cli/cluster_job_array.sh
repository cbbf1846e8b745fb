#!/usr/bin/env bash
# cluster_job_array.sh ROCKFALL DOC SCENARIO WORKDIR [SWEEP OPTIONS...]: the Slurm job-array
# and merge scripts of docs/cluster.md, extracted from the page as they stand, run as Slurm
# would run them: each array task with SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT and its own
# node-local SLURM_TMPDIR; one task stopped by SIGTERM to the script (as --signal=B:TERM does
# before the time limit), which copies its shard back interrupted, then requeued on the same
# node; one task requeued on another node after it had finished (it continues from the copy);
# then the merge. The merged database equals a one-process sweep.
set -euo pipefail
rockfall=$1 doc=$2 scenario=$3 work=$4
shift 4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# shellcheck source=same_run.sh
source "$(dirname "$0")/same_run.sh"
# shellcheck source=paused.sh
source "$(dirname "$0")/paused.sh"

# extract MARKER FILE: the first ```sh block after the line "<!-- cluster.md: MARKER -->".
extract() {
    awk -v marker="<!-- cluster.md: $1 -->" '
        $0 == marker { found = 1; next }
        found == 1 && /^```sh$/ { found = 2; next }
        found == 2 && /^```$/ { exit }
        found == 2 { print }' "$doc" >"$2"
    [ -s "$2" ] || fail "no script after '<!-- cluster.md: $1 -->' in $doc"
}
extract "job-array script" "$work/sweep_array.sh"
extract "merge script" "$work/merge.sh"

samples=240 seed=11 tasks=3
"$rockfall" sweep "$scenario" --db "$work/one.db" --samples $samples --seed $seed --quiet >/dev/null
export SCENARIO=$scenario SAMPLES=$samples SEED=$seed ROCKFALL=$rockfall
export SHARDS_DIR=$work/shared/shards SLURM_ARRAY_TASK_COUNT=$tasks SLURM_CPUS_PER_TASK=1
task() {
    mkdir -p "$work/node$1"
    (cd "$work" && SLURM_ARRAY_TASK_ID=$1 SLURM_TMPDIR=$work/node$1 bash "$work/sweep_array.sh")
}
task 0
task 1
# Task 2 stopped by SIGTERM to its script mid-run. Its sweep runs through a wrapper that adds
# the hidden --pause-after 5: it stops itself (SIGSTOP) once its node-local shard holds 5
# samples. SIGTERM then goes to the script, whose trap passes it on to the stopped sweep (the
# signal waits, pending); SIGCONT lets the sweep take it. However fast the machine, the signal
# lands mid-run.
printf '#!/bin/sh\nexec "%s" "$@" --pause-after 5\n' "$rockfall" >"$work/pausing_rockfall"
chmod +x "$work/pausing_rockfall"
mkdir -p "$work/node2"
(cd "$work" && exec env SLURM_ARRAY_TASK_ID=2 SLURM_TMPDIR=$work/node2 \
    ROCKFALL="$work/pausing_rockfall" bash "$work/sweep_array.sh") &
pid=$!
# pending_term PID: whether SIGTERM (15) waits, undelivered, for the process (1 << 14 in ShdPnd).
pending_term() {
    local mask
    mask=$(awk '/^ShdPnd:/ {print $2}' "/proc/$1/status" 2>/dev/null || echo 0)
    (((0x$mask >> 14) & 1))
}
sweep=
for _ in $(seq 1200); do
    sweep=$(pgrep -P "$pid" || true)
    [ -n "$sweep" ] && stopped "$sweep" && break
    sleep 0.05
done
[ -n "$sweep" ] && stopped "$sweep" || fail "task 2's sweep did not pause after 5 samples"
kill -TERM "$pid"
for _ in $(seq 1200); do
    pending_term "$sweep" && break
    sleep 0.05
done
pending_term "$sweep" || fail "the job-array script did not pass SIGTERM on to its sweep"
kill -CONT "$sweep"
set +e
wait "$pid"
code=$?
set -e
[ "$code" -eq 130 ] || fail "task 2 stopped by SIGTERM: expected exit 130, got $code"
[ "$(sqlite3 "$SHARDS_DIR/shard_2.db" "SELECT status FROM run")" = interrupted ] ||
    fail "task 2 stopped by SIGTERM did not copy its interrupted shard back"
echo "task 2 stopped by SIGTERM: exit 130, $(sqlite3 "$SHARDS_DIR/shard_2.db" "SELECT count(*) FROM samples") samples copied back"
task 2
for k in $(seq 0 $((tasks - 1))); do
    [ -f "$SHARDS_DIR/shard_$k.db" ] || fail "task $k did not copy its shard back"
    [ "$(sqlite3 "$SHARDS_DIR/shard_$k.db" "SELECT json_extract(settings_json, '$.shard'), status FROM run")" = "$k/$tasks|complete" ] ||
        fail "task $k: its shard is not shard $k/$tasks, complete"
done
# A requeued task on another node (empty node-local disk) continues from the copy.
rm -rf "$work/node1"
before=$(sqlite3 "$SHARDS_DIR/shard_1.db" "SELECT * FROM outcomes ORDER BY 1, 2")
task 1
[ "$before" = "$(sqlite3 "$SHARDS_DIR/shard_1.db" "SELECT * FROM outcomes ORDER BY 1, 2")" ] ||
    fail "the requeued task changed its shard"
[ -z "$(find "$SHARDS_DIR" -name '.*')" ] || fail "a temporary copy was left in $SHARDS_DIR"
mkdir -p "$work/results"
(cd "$work" && SLURM_TMPDIR=$work/node0 bash "$work/merge.sh")
same_run "$work/one.db" "$work/results/sweep.db"
echo "the job-array and merge scripts of $(basename "$doc"), run as $tasks tasks and merged, equal one process"
