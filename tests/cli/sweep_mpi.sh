#!/usr/bin/env bash
# sweep_mpi.sh ROCKFALL MPIEXEC SCENARIO WORKDIR MODE [SWEEP OPTIONS...]: `mpirun -np 3 rockfall
# sweep` (one thread per rank, on loopback) against the one-process sweep with the same options.
# MODE equal: the databases are equal table by table, row by row, and so is a sweep crashed
#   in one process and completed with --resume under mpirun.
# MODE signals: SIGTERM to rank 1 stops every rank, the database is interrupted and valid; a
#   rank killed with SIGKILL ends the job (non-zero, Open MPI names the rank); after each,
#   `rockfall sweep --db FILE --resume` completes the run equal to the one-process sweep.
# MODE refuse: a command line rank 0 refuses ends every rank with rank 0's message and code.
set -euo pipefail
rockfall=$1 mpiexec=$2 scenario=$3 work=$4 mode=$5
shift 5
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }
# shellcheck source=same_run.sh
source "$(dirname "$0")/same_run.sh"
# shellcheck source=paused.sh
source "$(dirname "$0")/paused.sh"
mpi() { "$mpiexec" --allow-run-as-root --oversubscribe -np 3 "$@"; }
"$rockfall" sweep "$scenario" --db "$work/one.db" --threads 2 --quiet "$@" >/dev/null

case $mode in
equal)
    out=$(mpi "$rockfall" sweep "$scenario" --db "$work/ranks.db" --threads 1 "$@" 2>&1)
    grep -q "1 thread on rank 0 of 3 MPI ranks" <<<"$out" || fail "no MPI banner: $out"
    same_run "$work/one.db" "$work/ranks.db"
    echo "3 ranks equal one process: $(sqlite3 "$work/ranks.db" "SELECT count(*) FROM outcomes") rocks"
    set +e
    "$rockfall" sweep "$scenario" --db "$work/resumed.db" --threads 1 --quiet --crash-after 5 \
        "$@" >/dev/null 2>&1
    code=$?
    set -e
    [ "$code" -eq 3 ] || fail "the crash run should exit 3, got $code"
    mpi "$rockfall" sweep --db "$work/resumed.db" --resume --threads 1 --quiet >/dev/null
    same_run "$work/one.db" "$work/resumed.db"
    echo "crashed in one process, resumed over 3 ranks: equal"
    ;;
signals)
    # stop_rank SIGNAL RANK NAME: starts the sweep over 3 ranks into NAME.db, whose ranks 1
    # and 2 stop themselves (SIGSTOP, the hidden --pause-after) once each has sent 3 samples;
    # then SIGNAL goes to rank RANK while it is stopped, SIGCONT to both, and `code` is set to
    # mpirun's exit code. Rank 0 cannot finish the run while the others hold unfinished
    # chunks, so the signal lands mid-run however fast the machine is.
    stop_rank() {
        local signal=$1 rank=$2 name=$3 db=$work/$3.db pid p r
        local -A by_rank=()
        shift 3
        # mpirun itself in the background (not the mpi function's subshell): its children
        # are the ranks.
        "$mpiexec" --allow-run-as-root --oversubscribe -np 3 "$rockfall" sweep "$scenario" \
            --db "$db" --threads 1 --quiet --pause-after 3 "$@" >"$work/$name.out" 2>&1 &
        pid=$!
        for _ in $(seq 1200); do
            for p in $(pgrep -P "$pid"); do
                r=$(tr '\0' '\n' <"/proc/$p/environ" 2>/dev/null | sed -n 's/^OMPI_COMM_WORLD_RANK=//p')
                [ -n "$r" ] && stopped "$p" && by_rank[$r]=$p
            done
            [ -n "${by_rank[1]:-}" ] && [ -n "${by_rank[2]:-}" ] && break
            kill -0 "$pid" 2>/dev/null || break
            sleep 0.05
        done
        [ -n "${by_rank[1]:-}" ] && [ -n "${by_rank[2]:-}" ] ||
            fail "ranks 1 and 2 did not pause after 3 samples: $(cat "$work/$name.out")"
        kill "-$signal" "${by_rank[$rank]}"
        kill -CONT "${by_rank[1]}" "${by_rank[2]}" 2>/dev/null || true
        set +e
        wait "$pid"
        code=$?
        set -e
    }
    stop_rank TERM 1 term "$@"
    [ "$code" -ne 0 ] || fail "SIGTERM to rank 1: mpirun should exit non-zero"
    grep -q "interrupted: [0-9]* samples are stored in" "$work/term.out" || fail "$(cat "$work/term.out")"
    [ "$(sqlite3 "$work/term.db" "SELECT status FROM run")" = interrupted ] ||
        fail "SIGTERM to rank 1: the run should be interrupted"
    echo "SIGTERM to rank 1: exit $code, $(sqlite3 "$work/term.db" "SELECT count(*) FROM samples") samples stored, interrupted"
    "$rockfall" sweep --db "$work/term.db" --resume --quiet >/dev/null
    same_run "$work/one.db" "$work/term.db"
    echo "resumed: equal to one process"

    stop_rank KILL 2 kill "$@"
    [ "$code" -ne 0 ] || fail "SIGKILL to rank 2: mpirun should exit non-zero"
    grep -q "rank 2 .*signal 9" "$work/kill.out" || fail "no message naming rank 2: $(cat "$work/kill.out")"
    echo "SIGKILL to rank 2: exit $code, $(sqlite3 "$work/kill.db" "SELECT count(*) FROM samples") samples stored"
    "$rockfall" sweep --db "$work/kill.db" --resume --quiet >/dev/null
    same_run "$work/one.db" "$work/kill.db"
    echo "resumed: equal to one process"
    ;;
refuse)
    set +e
    out=$(mpi "$rockfall" sweep "$scenario" --db "$work/one.db" --quiet "$@" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || fail "an existing database over ranks: expected exit 2, got $code: $out"
    grep -q "one.db exists already" <<<"$out" || fail "$out"
    [ "$(grep -c "exists already" <<<"$out")" -eq 1 ] || fail "the refusal should be said once: $out"
    echo "refused once, exit 2"
    ;;
*) fail "unknown mode $mode" ;;
esac
