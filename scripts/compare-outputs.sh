#!/usr/bin/env bash
# Runs every command of the README and docs/ with two rockfall binaries and diffs what they
# print (stdout, stderr, exit code) and the files they write. Used to check that a change which
# must not change behaviour (a refactoring) gives byte-for-byte the same outputs.
# Usage: scripts/compare-outputs.sh OLD_BINARY NEW_BINARY [WORK_DIR]
# Times, dates, runtimes, progress lines and paths of the scratch folders are masked before
# the diff; a database is compared through `sqlite3 .dump` with its clock columns (run start and
# end, soil run runtime) blanked. Exit 0 when nothing differs, 1 otherwise.
set -euo pipefail
old=$(realpath "$1")
new=$(realpath "$2")
top=$(cd "$(dirname "$0")/.." && pwd)
work=${3:-$(mktemp -d /tmp/rockfall-compare.XXXX)}
mkdir -p "$work"

# The commands, in document order, each once; the setup sweep first (README command 1).
commands="$work/commands.txt"
{
    echo "build/app/rockfall sweep samples/seed_sweep.toml --db results/seed_sweep.db"
    grep -hE '^\s*(build/app/rockfall|sqlite3) ' "$top/README.md" "$top"/docs/*.md |
        sed -E 's/^\s+//; s/\s+#.*$//'
} | awk '!seen[$0]++' >"$commands"

mask() {
    sed -E -e '/samples\/s/d' -e 's/[0-9]{4}-[0-9]{2}-[0-9]{2}T[0-9]{2}:[0-9]{2}:[0-9]{2}Z/<time>/g' \
        -e 's/(runtime|wall-clock|took|elapsed)([^0-9]*)[0-9.eE+-]+/\1\2<t>/g' \
        -e 's/"runtime_s": [0-9.eE+-]+/"runtime_s": <t>/g' \
        -e "s#$work/[a-z]+#<dir>#g"
}

# A database's content without the columns that hold wall-clock times.
dump_db() {
    local copy
    copy=$(mktemp "$work/dump.XXXX")
    cp "$1" "$copy"
    sqlite3 "$copy" "UPDATE run SET started_at = NULL, finished_at = NULL;" 2>/dev/null || true
    sqlite3 "$copy" "UPDATE soil_run SET runtime_s = NULL;" 2>/dev/null || true
    sqlite3 "$copy" .dump | mask
    rm -f "$copy"
}

run_all() {
    local name=$1 binary=$2 dir="$work/$1"
    rm -rf "$dir"
    mkdir -p "$dir/build/app" "$dir/results" "$dir/out"
    ln -s "$binary" "$dir/build/app/rockfall"
    for d in samples docs tests; do ln -s "$top/$d" "$dir/$d"; done
    local i=0
    while IFS= read -r cmd; do
        i=$((i + 1))
        (cd "$dir" && timeout 600 bash -c "$cmd" >"out/$i.stdout" 2>"out/$i.stderr"; echo $? >"out/$i.rc") || true
        mask <"$dir/out/$i.stdout" >"$dir/out/$i.stdout.masked"
        mask <"$dir/out/$i.stderr" >"$dir/out/$i.stderr.masked"
    done <"$commands"
    echo "compare-outputs.sh: ran $i commands with $name ($binary)" >&2
}

run_all old "$old"
run_all new "$new"

status=0
i=0
while IFS= read -r cmd; do
    i=$((i + 1))
    for part in stdout.masked stderr.masked rc; do
        if ! cmp -s "$work/old/out/$i.$part" "$work/new/out/$i.$part"; then
            echo "DIFFERS ($part): $cmd"
            diff "$work/old/out/$i.$part" "$work/new/out/$i.$part" | head -20 || true
            status=1
        fi
    done
done <"$commands"

# Files the commands wrote (everything but the links and our own captures).
while IFS= read -r file; do
    rel=${file#"$work/old/"}
    other="$work/new/$rel"
    if [ ! -e "$other" ]; then
        echo "MISSING in new: $rel"; status=1; continue
    fi
    case "$rel" in
        *.db)
            a=$(dump_db "$file")
            b=$(dump_db "$other")
            [ "$a" = "$b" ] || { echo "DIFFERS (database content): $rel"; status=1; } ;;
        *)
            cmp -s <(mask <"$file") <(mask <"$other") || { echo "DIFFERS (file): $rel"; status=1; } ;;
    esac
done < <(find "$work/old" -type f ! -path "$work/old/out/*")

if [ $status -eq 0 ]; then
    echo "compare-outputs.sh: $i commands, same outputs and files (work dir $work)"
else
    echo "compare-outputs.sh: outputs differ (work dir $work)"
fi
exit $status
