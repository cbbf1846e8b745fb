#!/usr/bin/env bash
# sweep_resume_stored.sh ROCKFALL SCENARIO WORKDIR [SWEEP OPTIONS...]: a sweep started with
# OPTIONS (not the defaults) continues with the options left out, taking them from its database:
# - crashed once, it is resumed with the SCENARIO and a --seed equal to the stored one (the
#   other options not given), and crashes again;
# - then `rockfall sweep --db FILE --resume` alone, run from another directory, completes it;
# every table then holds what an uninterrupted sweep's holds, and the run record the same run.
# A complete run resumed again is left byte for byte; an option given that differs from the
# stored one is refused, naming the option and both values.
set -euo pipefail
rockfall=$1 scenario=$2 work=$3
shift 3
rm -rf "$work" && mkdir -p "$work"
db=$work/part.db
fail() { echo "$*"; exit 1; }
"$rockfall" sweep "$scenario" --db "$work/whole.db" --threads 2 --quiet "$@" >/dev/null

# crash LOW HIGH SWEEP-ARGS...: the sweep must crash (exit 3) with LOW to HIGH samples stored.
crash() {
    local low=$1 high=$2 code stored
    shift 2
    set +e
    "$rockfall" sweep "$@" >/dev/null 2>&1
    code=$?
    set -e
    [ "$code" -eq 3 ] || fail "the crash run should exit 3, got $code: $*"
    stored=$(sqlite3 "$db" "SELECT count(*) FROM samples")
    [ "$stored" -ge "$low" ] && [ "$stored" -le "$high" ] ||
        fail "expected $low to $high samples stored after the crash, got $stored"
    echo "crashed with $stored samples stored"
}
crash 10 19 "$scenario" --db "$db" --threads 1 --quiet --crash-after 10 "$@"
seed=$(sqlite3 "$db" "SELECT seed FROM run")
crash 20 29 "$scenario" --db "$db" --seed "$seed" --resume --threads 1 --quiet --crash-after 20
(cd / && "$rockfall" sweep --db "$db" --resume --quiet >/dev/null)

for table in samples rocks outcomes stations wall_impacts trajectories; do
    a=$(sqlite3 "$work/whole.db" "SELECT * FROM $table ORDER BY 1, 2, 3")
    b=$(sqlite3 "$db" "SELECT * FROM $table ORDER BY 1, 2, 3")
    [ "$a" = "$b" ] || fail "table $table differs after the resume"
    echo "$table: $(sqlite3 "$db" "SELECT count(*) FROM $table") rows, identical"
done
[ "$(sqlite3 "$work/whole.db" "SELECT * FROM zones ORDER BY 1")" = \
    "$(sqlite3 "$db" "SELECT * FROM zones ORDER BY 1")" ] || fail "table zones differs"
# The run as recorded; the thread count is the first command's, not part of the run.
run="SELECT scenario_text, scenario_hash, seed, method, samples_planned, stop_rule,
            json_remove(settings_json, '$.threads'), status FROM run"
[ "$(sqlite3 "$work/whole.db" "$run")" = "$(sqlite3 "$db" "$run")" ] || fail "the run records differ"
[ "$(sqlite3 "$db" "SELECT status FROM run")" = complete ] || fail "the run is not complete"
echo "resumed with the options left out, the sweep equals the uninterrupted one"

before=$(sha256sum <"$db")
out=$("$rockfall" sweep --db "$db" --resume --quiet 2>&1)
grep -q "part.db: the run is complete already ([0-9]* samples stored); nothing to run" <<<"$out" ||
    fail "a complete run should say so: $out"
[ "$(sha256sum <"$db")" = "$before" ] || fail "resuming a complete run changed the file"
echo "a complete run resumed again says so and keeps every byte"

# refused OPTION VALUE MESSAGE: --resume with the option given otherwise is refused (exit 2).
refused() {
    local out code
    set +e
    out=$("$rockfall" sweep --db "$db" --resume --quiet "$1" "$2" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || fail "$1 $2: expected exit 2, got $code: $out"
    grep -qF -- "part.db: cannot resume: the database's $3" <<<"$out" || fail "$1 $2: $out"
    echo "refused: $out"
}
refused --seed $((seed + 1)) "seed is $seed but this command gives $((seed + 1))"
planned=$(sqlite3 "$db" "SELECT samples_planned FROM run")
refused --samples $((planned + 1)) "sample count is $planned but this command gives $((planned + 1))"
case $(sqlite3 "$db" "SELECT method FROM run") in
monte_carlo) refused --method lhs "method is monte_carlo but this command gives latin_hypercube" ;;
*) refused --method mc "method is latin_hypercube but this command gives monte_carlo" ;;
esac
interval=$(sqlite3 "$db" "SELECT json_extract(settings_json, '$.trajectory_interval_s') FROM run")
refused --trajectories 0.5 "--trajectories is $interval but this command gives 0.5"
until=$(sqlite3 "$db" "SELECT json_extract(settings_json, '$.until') FROM run")
if [ -n "$until" ]; then
    width=$(sqlite3 "$db" "SELECT json_extract(settings_json, '$.half_width') FROM run")
    refused --half-width 0.3 "--half-width is $width but this command gives 0.3"
    refused --until exceed:99 "--until is \"$until\" but this command gives \"exceed:99\""
else
    refused --until wall "--until is (none) but this command gives \"wall\""
fi
[ "$(sha256sum <"$db")" = "$before" ] || fail "a refused --resume changed the file"
echo "options given otherwise are refused and change nothing"
