#!/usr/bin/env bash
# The completion script sourced in bash and asked as bash asks it (COMP_WORDS, COMP_CWORD):
# the commands, a command's options, a nested command's options and an option's values, each
# against what the program's --help lists.
# Usage: bash_completion.sh ROCKFALL COMPLETION_SCRIPT
set -uo pipefail
rockfall=$1 script=$2
fail() {
    echo "bash_completion.sh: $*" >&2
    exit 1
}
# shellcheck source=/dev/null
source "$script" || fail "$script does not source"
complete -p rockfall >/dev/null 2>&1 || fail "$script does not register a completion for rockfall"

# What _rockfall offers for a command line whose last word is being completed, one per line.
offers() {
    COMP_WORDS=("$@")
    COMP_CWORD=$(($# - 1))
    COMPREPLY=()
    _rockfall
    printf '%s\n' "${COMPREPLY[@]}" | sort
}
expect() {
    local want=$1 got
    shift
    got=$(offers "$@" | tr '\n' ' ')
    [ "$got" = "$want" ] || fail "'$*' completes to '$got', expected '$want'"
}

expect "sweep " rockfall sw
offers rockfall sweep --se | grep -qx -- --seed || fail "'rockfall sweep --se' does not offer --seed"
expect "--json " rockfall query results.db summary --js
expect "clopper-pearson wilson " rockfall query results.db exceed --interval ""
# Every command --help lists, and nothing else.
commands=$("$rockfall" --help | awk '/^Subcommands:/ { on = 1; next } on && /^$/ { exit } on { print $1 }' | sort | tr '\n' ' ')
[ -n "$commands" ] || fail "no commands in rockfall --help"
expect "$commands" rockfall ""
# Every long option of `rockfall sweep --help`.
for option in $("$rockfall" sweep --help | grep -oE '^ +(-[A-Za-z0-9], ?)?--[A-Za-z0-9-]+' | grep -oE -- '--[A-Za-z0-9-]+'); do
    offers rockfall sweep -- | grep -qx -- "$option" || fail "'rockfall sweep --' does not offer $option"
done
echo "bash_completion.sh: commands, options and values complete"
