#!/usr/bin/env bash
# report_html.sh ROCKFALL MAKE_TEST_DB SOIL_DB WORKDIR: `rockfall report DB --html FILE`.
# - A synthetic sweep's report parses as XML, has its sections and figures, and prints the
#   numbers `rockfall query` prints for the same database; two runs give the same bytes.
# - One sample, no wall hit and a soil flow still give a well-formed report.
# - A missing, foreign or damaged database and an unwritable output fail with exit 2, name the
#   file and write nothing: an earlier report keeps every byte.
set -euo pipefail
rockfall=$1 make_db=$2 soil_db=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
cd "$work"

fail() { echo "FAIL: $*"; exit 1; }
well_formed() { xmllint --noout "$1" || fail "$1 is not well-formed"; }

"$make_db" sweep.db 500 >/dev/null
"$rockfall" report sweep.db --html sweep.html
well_formed sweep.html
for id in provenance convergence reach stations wall envelope worst scenario; do
    grep -q "<section id=\"$id\">" sweep.html || fail "no section $id"
done
[ "$(grep -c '<figure>' sweep.html)" -eq 4 ] || fail "expected 4 figures"
! grep -q '<script' sweep.html || fail "a script in the report"
echo "sections and figures present"

# The summary's shares, word for word.
summary=$("$rockfall" query sweep.db summary)
for line in "wall hit by: " "samples with a rock on the wall: " "past station 1 "; do
    share=$(grep "^$line" <<<"$summary" | grep -Eo '[0-9]+ of [0-9]+, [0-9.]+ % \(95 % CI [0-9.]+ to [0-9.]+ %\)')
    [ -n "$share" ] || fail "no share in the summary line '$line'"
    grep -qF "$share" sweep.html || fail "summary share '$share' not in the report"
    echo "summary '$line$share' is in the report"
done
# The 95th percentile of the peak force, to the report's 4 digits.
p95=$("$rockfall" query sweep.db percentiles --of peak_force --p 95 --csv | tail -n 1 | cut -d, -f4)
p95_text=$(printf '%.4g' "$p95")
grep -qF "<td class=\"n\">$p95_text</td>" sweep.html || fail "peak force p95 $p95_text not in the report"
echo "peak force p95 $p95_text N is in the report"
# The worst rock by reach and the command that replays it.
worst=$("$rockfall" query sweep.db worst --n 1 --csv | tail -n 1 | cut -d, -f2)
grep -qxF "rockfall simulate --from sweep.db --sample $worst" sweep.html ||
    fail "no replay command for sample $worst"
echo "worst sample $worst replays with its command"
# P(reach >= x) by zone at the convergence distance, as exceed prints it.
"$rockfall" report sweep.db --html distance.html --distance 3
exceed=$("$rockfall" query sweep.db exceed --distance 3 --by zone --csv | sed -n 2p)
zone=$(cut -d, -f1 <<<"$exceed") p=$(printf '%.4g' "$(cut -d, -f6 <<<"$exceed")")
grep -qF "<tr><td>$zone</td>" distance.html && grep -qF "<td class=\"n\">$p</td>" distance.html ||
    fail "P(reach >= 3 m) in zone $zone = $p not in the report"
echo "P(reach >= 3 m) in zone $zone: $p, as exceed prints it"

"$rockfall" report sweep.db --html again.html
cmp sweep.html again.html || fail "two runs differ"
echo "two runs give the same bytes ($(wc -c <sweep.html) bytes)"

"$make_db" one.db 1 >/dev/null
"$rockfall" report one.db --html one.html
well_formed one.html
"$rockfall" report "$soil_db" --html soil.html
well_formed soil.html
grep -q '<section id="wall-load">' soil.html || fail "no wall-load section for the soil flow"
[ "$(grep -c '<figure>' soil.html)" -eq 1 ] || fail "the soil report needs its load figure"
echo "one sample and a soil flow give well-formed reports"

# Bad input: exit 2, the file named, nothing written, an earlier report unchanged.
before=$(sha256sum <sweep.html)
expect_refused() {
    local pattern=$1 out code
    shift
    set +e
    out=$("$rockfall" report "$@" 2>&1)
    code=$?
    set -e
    [ "$code" -eq 2 ] || fail "exit $code (want 2) for: $* ($out)"
    grep -Eq -- "$pattern" <<<"$out" || fail "'$out' does not match /$pattern/"
    echo "refused (exit 2): $out"
}
expect_refused "nope\\.db: no such file" nope.db --html sweep.html
"$make_db" foreign.db 5 --application-id 7 >/dev/null
expect_refused "foreign\\.db is an SQLite database but not a rockfall results database" \
    foreign.db --html sweep.html
echo "not a database" >text.txt
expect_refused "text\\.txt is not an SQLite database" text.txt --html sweep.html
"$make_db" corrupt.db 50 --corrupt >/dev/null
expect_refused "corrupt\\.db is corrupt" corrupt.db --html sweep.html
expect_refused "--confidence = 1.5" sweep.db --html sweep.html --confidence 1.5
mkdir -p adir
expect_refused "adir" sweep.db --html adir
expect_refused "no-such-dir" sweep.db --html no-such-dir/r.html
[ "$(sha256sum <sweep.html)" = "$before" ] || fail "a refused run changed the earlier report"
[ -z "$(ls -A | grep -E '\.part$|^\.')" ] || fail "a part file was left: $(ls -A)"
[ ! -e no-such-dir ] || fail "no-such-dir was created"
echo "refused runs wrote nothing"
