#!/usr/bin/env bash
# validate_html.sh ROCKFALL WORKDIR: `rockfall validate --quick --html FILE` (about 1 minute on 2
# cores, twice). Checks that the page parses as XML, has every section, a row for each of the
# analytic checks named below with its verdict, its figures and no script; that it names the
# binary's version; that the analytic sections all pass; that a second run on one thread with
# --json gives the same bytes and a JSON document with the same checks and counts; and that an
# output in a missing directory is refused at once with exit 2.
set -euo pipefail
rockfall=$1 work=$2
rm -rf "$work" && mkdir -p "$work"
cd "$work"

fail() { echo "FAIL: $*"; exit 1; }

text=$("$rockfall" validate --quick --html quick.html --quiet)
echo "$text" | grep -v '^  '
xmllint --noout quick.html || fail "quick.html is not well-formed"
for id in summary engine shapes mpm seed000 seed001 calibration; do
    grep -q "<section id=\"$id\">" quick.html || fail "no section $id"
done
for check in free_fall.drop.dt1ms slide.mu0.3.dt0.5ms roll.dt1ms bounce.sphere.0deg.e0.5.dt1ms.height \
    wall_impulse.hertz hertz.peak.e0.95 spring_dashpot.e0.5.peak mass.cube.volume \
    sphericity.tetrahedron mpm.bar.period mpm.k0.nu0.3.left mpm.collapse.a2 mpm.block.43deg \
    seed000.lambda seed000.beta.massive seed001.peak_force_red_c2_60_deg \
    seed001.speed_at_1_4_m_yellow_c1_30_deg calibration.drop.cube; do
    grep -Eq "<tr id=\"check-$check\">.*>(PASS|MISS)</td>" quick.html || fail "no row for check $check"
done
[ "$(grep -c '<figure>' quick.html)" -ge 8 ] || fail "expected at least 8 figures"
! grep -q '<script' quick.html || fail "a script in the report"
version=$("$rockfall" --version)
grep -qF "$version (" quick.html || fail "the report does not name '$version'"
! grep -q 'whole validation' quick.html || fail "a runtime in the report"
# The analytic sections pass on every build (they are the tests' checks); the seed sections
# report what they find.
for section in "Rigid-body engine" "Mass properties" "MPM soil solver"; do
    grep -Eq "^$section.*\(([0-9]+) checks: \1 PASS, 0 MISS\):" <<<"$text" ||
        fail "$section: not every check passed"
done
echo "sections, checks and figures present; analytic sections pass"

"$rockfall" validate --quick --html again.html --threads 1 --json --quiet >quick.json
cmp quick.html again.html || fail "a second run (1 thread) gives other bytes"
summary=$(grep -Eo 'Summary: [0-9]+ checks: [0-9]+ PASS, [0-9]+ MISS' quick.html | head -n 1)
python3 - "$summary" quick.json <<'EOF'
import json, re, sys
total, passed, missed = map(int, re.findall(r"\d+", sys.argv[1]))
doc = json.load(open(sys.argv[2]))
assert len(doc["checks"]) == total, (len(doc["checks"]), total)
assert doc["passed"] == passed and doc["missed"] == missed, (doc["passed"], doc["missed"])
assert doc["quick"] is True and doc["version"], doc["version"]
assert all(c["verdict"] in ("PASS", "MISS") for c in doc["checks"])
assert "physical_forces" in doc and doc["runs"] == 6, doc.get("runs")
EOF
echo "same bytes on 1 thread; JSON has the same $summary"

# Refused at once (exit 2), before the checks run: a missing directory.
start=$(date +%s)
set +e
"$rockfall" validate --quick --html missing/new.html --quiet 2>err.txt
code=$?
set -e
[ "$code" -eq 2 ] || fail "exit $code for a missing directory (expected 2)"
[ $(( $(date +%s) - start )) -lt 10 ] || fail "the missing directory was refused only after the work"
grep -q "missing/new.html" err.txt || fail "the error does not name the file: $(cat err.txt)"
echo "missing directory refused: $(cat err.txt)"
