#!/usr/bin/env bash
# rockfall.1 against the program's --help: a section for every command and subcommand that
# --help lists, holding every option that command's --help lists; the global options; roff that
# groff reads without a warning (when groff is installed).
# Usage: man_page.sh ROCKFALL MAN_PAGE
set -euo pipefail
rockfall=$1 page=$2
fail() {
    echo "man_page.sh: $*" >&2
    exit 1
}
[ -s "$page" ] || fail "$page is missing or empty"
if command -v groff >/dev/null; then
    warnings=$(groff -man -ww -z "$page" 2>&1)
    [ -z "$warnings" ] || fail "groff warns on $page: $warnings"
fi
# The page's text with roff's escapes undone: \- is -, \& and font changes are nothing.
text=$(sed -e 's/\\-/-/g' -e 's/\\&//g' -e 's/\\f[BIR]//g' "$page")

# The long options a --help text lists, and the subcommands under its "Subcommands:" heading.
options_of() { grep -oE '^ +(-[A-Za-z0-9], ?)?--[A-Za-z0-9][A-Za-z0-9-]*' | grep -oE -- '--[A-Za-z0-9-]+'; }
subcommands_of() { awk '/^Subcommands:/ { on = 1; next } on && /^$/ { exit } on { print $1 }'; }
# The lines of the page from the heading `.SS "rockfall PATH"` (or .SH NAME) to the next one.
section() { awk -v heading="$1" '$0 == heading { on = 1; next } on && /^\.S[HS]/ { exit } on'; }

commands=0
# check PATH WORDS...: the command named PATH, called as `rockfall WORDS... --help`.
check() {
    local path=$1 help body option sub before
    shift
    local call=("$@")
    help=$("$rockfall" "${call[@]}" --help) || fail "rockfall ${call[*]} --help failed"
    if [ -z "$path" ]; then
        body=$(section ".SH OPTIONS" <<<"$text")
    else
        body=$(section ".SS \"rockfall $path\"" <<<"$text")
        [ -n "$body" ] || fail "no section for 'rockfall $path' in $page"
        commands=$((commands + 1))
    fi
    for option in $(options_of <<<"$help"); do
        grep -qF -- "$option" <<<"$body" ||
            fail "'rockfall $path' lists $option in --help, the man page does not"
    done
    # A positional that the usage line puts before SUBCOMMAND takes a placeholder.
    read -ra before <<<"$(grep -m1 '^Usage:' <<<"$help" | sed -n 's/.*\[OPTIONS\]\(.*\) SUBCOMMAND.*/\1/p')"
    for sub in $(subcommands_of <<<"$help"); do
        check "${path:+$path }$sub" "${call[@]}" "${before[@]/*/x}" "$sub"
    done
}
check ""
[ "$commands" -ge 10 ] || fail "only $commands commands found in rockfall --help"
echo "man_page.sh: $commands commands and their options in $(basename "$page")"
