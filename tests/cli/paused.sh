# Sourced by the CLI test scripts whose sweeps stop themselves with the hidden --pause-after.
# stopped PID: whether the process is stopped (state T in /proc/PID/stat).
stopped() {
    [ "$(awk '{print $3}' "/proc/$1/stat" 2>/dev/null)" = T ]
}
# wait_stopped PID: waits up to 60 s for the process to stop; fails (status 1) if it does not.
wait_stopped() {
    for _ in $(seq 1200); do
        stopped "$1" && return 0
        sleep 0.05
    done
    stopped "$1"
}
