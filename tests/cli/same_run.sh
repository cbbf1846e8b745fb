# Sourced by the CLI test scripts. same_run A B: fails (exit 1) unless every table a sweep
# writes and the run record (all but the thread count and times) are equal in the results
# databases A and B, row by row.
same_run() {
    local table a b
    for table in samples rocks outcomes stations wall_impacts trajectories zones; do
        a=$(sqlite3 "$1" "SELECT * FROM $table ORDER BY 1, 2")
        b=$(sqlite3 "$2" "SELECT * FROM $table ORDER BY 1, 2")
        [ "$a" = "$b" ] || { echo "FAIL: table $table differs between $1 and $2"; exit 1; }
        [ -n "$a" ] || [ "$table" = wall_impacts ] || [ "$table" = trajectories ] ||
            { echo "FAIL: table $table is empty in $1"; exit 1; }
    done
    local run="SELECT tool_version, build, scenario_name, scenario_text, scenario_hash, seed,
                      method, samples_planned, stop_rule, json_remove(settings_json, '$.threads'),
                      status FROM run"
    [ "$(sqlite3 "$1" "$run")" = "$(sqlite3 "$2" "$run")" ] ||
        { echo "FAIL: the run records of $1 and $2 differ"; exit 1; }
}
