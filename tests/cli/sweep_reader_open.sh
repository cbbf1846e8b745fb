#!/usr/bin/env bash
# sweep_reader_open.sh ROCKFALL SCENARIO WORKDIR: an sqlite3 shell that opened the database
# during the sweep and is still open when the sweep ends does not keep the samples out of the
# file: the .db alone, copied without its -wal, holds every sample and the status complete.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
rm -rf "$work" && mkdir -p "$work/alone"
# shellcheck source=paused.sh
source "$(dirname "$0")/paused.sh"
db="$work/read.db"
# The sweep stops itself (SIGSTOP, the hidden --pause-after) once one sample is stored, so
# that the reader reads mid-run however fast the machine is; SIGCONT once it has read.
"$rockfall" sweep "$scenario" --db "$db" --threads 1 --samples 120 --quiet --pause-after 1 \
    >"$work/out.txt" 2>&1 &
pid=$!
wait_stopped "$pid" ||
    { cat "$work/out.txt"; echo "the sweep did not pause after one sample"; exit 1; }
# The reader: an sqlite3 shell reading commands from a FIFO held open, so that it stays
# connected (idle, as a shell or a pandas connection left open) until the FIFO closes.
mkfifo "$work/commands"
sqlite3 "$db" <"$work/commands" >"$work/reader.txt" 2>&1 &
reader=$!
exec 3>"$work/commands"
echo "SELECT status FROM run;" >&3
for _ in $(seq 1200); do
    [ -s "$work/reader.txt" ] && break
    sleep 0.05
done
kill -CONT "$pid"
set +e
wait "$pid"
code=$?
set -e
cat "$work/out.txt"
[ "$code" -eq 0 ] || { echo "the sweep exited $code"; exit 1; }
first=$(head -n 1 "$work/reader.txt")
[ "$first" = running ] || { echo "the reader did not read during the sweep (it saw '$first')"; exit 1; }
kill -0 "$reader" || { echo "the reader is not open at the end of the sweep"; exit 1; }
cp "$db" "$work/alone/read.db"
exec 3>&-
wait "$reader"
alone="file:$work/alone/read.db?mode=ro"
n=$(sqlite3 "$alone" "SELECT count(*) FROM samples")
status=$(sqlite3 "$alone" "SELECT status FROM run")
echo "the .db alone: $n samples, status $status"
[ "$n" = 120 ] && [ "$status" = complete ]
