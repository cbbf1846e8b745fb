#!/usr/bin/env bash
# sweep_files.sh ROCKFALL SCENARIO WORKDIR: what a sweep does to the files it is given.
# - A refused --resume (another seed) leaves every byte of the database, and of its -wal and
#   -journal, as it was: for a finished file and for one left in WAL mode by a crash.
# - A sweep killed before its database appeared leaves a hidden part file; --resume then says
#   so, and the next run without --resume removes it.
# - A sample count beyond the limit is refused before anything is written.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
rm -rf "$work" && mkdir -p "$work"

# Bytes of the file and its -wal and -journal, absent ones marked, as one comparable listing.
bytes() {
    for f in "$1" "$1-wal" "$1-journal"; do
        if [ -e "$f" ]; then echo "$f $(sha256sum <"$f")"; else echo "$f absent"; fi
    done
}
refused_resume_changes_nothing() {
    local db=$1 before after out code
    before=$(bytes "$db")
    set +e
    out=$("$rockfall" sweep "$scenario" --db "$db" --seed 8 --resume --quiet 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || { echo "expected exit 2 for another seed, got $code: $out"; exit 1; }
    grep -q "cannot resume: the database's seed is 7 but this command gives 8" <<<"$out"
    after=$(bytes "$db")
    [ "$before" = "$after" ] || { echo "the refused file changed:"; echo "$before"; echo "$after"; exit 1; }
    echo "refused --resume left $(basename "$db") byte for byte unchanged:"
    echo "$after"
}

"$rockfall" sweep "$scenario" --db "$work/done.db" --quiet >/dev/null
refused_resume_changes_nothing "$work/done.db"

set +e
"$rockfall" sweep "$scenario" --db "$work/crashed.db" --threads 1 --quiet --crash-after 10 \
    >/dev/null 2>&1
set -e
[ -s "$work/crashed.db-wal" ] || { echo "the crash should leave samples in the -wal"; exit 1; }
refused_resume_changes_nothing "$work/crashed.db"

# The part file a sweep killed early leaves (same name pattern, no process holding it).
part="$work/.early.db.00c0ffee00c0ffee.part"
: >"$part"
: >"$part-journal"
set +e
out=$("$rockfall" sweep "$scenario" --db "$work/early.db" --resume --quiet 2>&1)
code=$?
set -e
echo "$out"
[ "$code" -eq 2 ] && grep -q "was stopped before it stored anything" <<<"$out" &&
    grep -q ".early.db.00c0ffee00c0ffee.part" <<<"$out" ||
    { echo "--resume should explain the stale part file (exit 2), got $code"; exit 1; }
[ -e "$part" ] || { echo "a refused --resume removed the part file"; exit 1; }
"$rockfall" sweep "$scenario" --db "$work/early.db" --quiet >/dev/null
[ ! -e "$part" ] && [ ! -e "$part-journal" ] || { echo "the stale part file was not removed"; exit 1; }
echo "the next run removed the stale part file and its journal"

set +e
out=$("$rockfall" sweep "$scenario" --db "$work/huge.db" --samples 1099511627776 --quiet 2>&1)
code=$?
set -e
echo "$out"
[ "$code" -eq 2 ] && grep -q -- "--samples: 1099511627776 is out of range: a sample count must be a whole number in \[1, 100000000\]" <<<"$out" ||
    { echo "expected a refusal with the range, got $code"; exit 1; }
[ -z "$(ls -A "$work" | grep huge || true)" ] || { echo "a refused sweep left files"; ls -A "$work"; exit 1; }
echo "too many samples: refused, nothing written"
