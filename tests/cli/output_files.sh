#!/usr/bin/env bash
# output_files.sh ROCKFALL SCENARIO SWEEP_SCENARIO WORKDIR: the one rule for output paths.
# - A character device (a copy of /dev/null made with mknod) and a FIFO are written directly
#   and stay what they are; /dev/stdout reaches standard output.
# - A directory is refused (exit 2, message naming it) and left as it was, by every command.
# - A regular file behind a symbolic link is replaced whole: the link and the file's mode stay.
# - A results database is never a device or FIFO.
# - No part file is left behind.
set -euo pipefail
rockfall=$1 scenario=$2 sweep=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cd "$work"

if mknod null c 1 3 2>/dev/null; then
    "$rockfall" simulate "$scenario" --trajectory null >/dev/null
    [ -c null ] || { echo "--trajectory replaced the character device"; ls -l null; exit 1; }
    "$rockfall" shape --kind cube --obj null --stl null >/dev/null
    [ -c null ] || { echo "--obj/--stl replaced the character device"; ls -l null; exit 1; }
    echo "a character device (mknod c 1 3) was written to and is still a character device"
else
    echo "mknod is not permitted here: the character-device case did not run (the FIFO case did)"
fi

mkfifo pipe
wc -l <pipe >pipe_lines &
reader=$!
"$rockfall" simulate "$scenario" --trajectory pipe >/dev/null
wait "$reader"
[ -p pipe ] || { echo "--trajectory replaced the FIFO"; ls -l pipe; exit 1; }
"$rockfall" simulate "$scenario" --trajectory direct.csv >/dev/null
[ "$(cat pipe_lines)" -eq "$(wc -l <direct.csv)" ] && [ "$(cat pipe_lines)" -gt 100 ] ||
    { echo "the FIFO's reader got $(cat pipe_lines) lines, the file $(wc -l <direct.csv)"; exit 1; }
echo "a FIFO got the whole trajectory ($(cat pipe_lines) lines) and is still a FIFO"

rows=$("$rockfall" simulate "$scenario" --trajectory /dev/stdout | grep -c '^1,')
[ "$rows" -eq $(($(wc -l <direct.csv) - 1)) ] ||
    { echo "--trajectory /dev/stdout printed $rows rows"; exit 1; }
echo "--trajectory /dev/stdout printed every row"

mkdir folder
refused() {  # refused COMMAND...: exit 2 naming the directory, which stays empty
    local out code
    set +e
    out=$("$@" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] && grep -q "cannot write the output file 'folder': it is a directory" <<<"$out" ||
        { echo "'$*': expected exit 2 refusing the directory, got $code: $out"; exit 1; }
    [ -d folder ] && [ -z "$(ls -A folder)" ] || { echo "'$*' changed the directory"; exit 1; }
}
refused "$rockfall" simulate "$scenario" --trajectory folder
refused "$rockfall" shape --kind cube --obj folder
refused "$rockfall" shape --kind cube --stl folder
refused "$rockfall" terrain "$scenario" --obj folder
echo "a directory was refused by --trajectory, --obj and --stl and left as it was"

echo "old" >target.csv
chmod 640 target.csv
ln -s target.csv link.csv
"$rockfall" simulate "$scenario" --trajectory link.csv >/dev/null
[ -L link.csv ] && [ "$(stat -c %a target.csv)" = 640 ] && cmp -s target.csv direct.csv ||
    { echo "through a symbolic link: the link, the mode or the contents are wrong"; ls -l; exit 1; }
echo "a file behind a symbolic link was replaced whole; the link and its mode 640 stayed"

set +e
out=$("$rockfall" sweep "$sweep" --db pipe --quiet 2>&1)
code=$?
set -e
[ "$code" -eq 2 ] && grep -q "pipe is not a regular file" <<<"$out" && [ -p pipe ] ||
    { echo "sweep --db on a FIFO: expected exit 2, got $code: $out"; exit 1; }
echo "sweep --db refused the FIFO: $out"

leftover=$(find . -name '*.part*')
[ -z "$leftover" ] || { echo "part files left behind: $leftover"; exit 1; }
echo "no part file left behind"
