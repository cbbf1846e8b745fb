#!/usr/bin/env bash
# simulate_figures.sh ROCKFALL QUICK_SCENARIO SINGLE_ROCK_SCENARIO WORKDIR: rockfall simulate
# --figures DIR writes the figures a run has data for, and only those, and lists them.
# - The quick scenario ([wall_cells], two named rocks, wall hits): the four figures, each an SVG
#   document, listed in the summary; the marked rocks' table and JSON section with the camera
#   interval given.
# - A single unnamed rock without [wall_cells] that hits the wall: wall_force.svg alone.
# - DIR is created with its parents; no part file is left behind.
set -euo pipefail
rockfall=$1 quick=$2 single=$3 work=$4
rm -rf "$work" && mkdir -p "$work"

out=$("$rockfall" simulate "$quick" --figures "$work/quick/figures")
for f in pressure_peak pressure_at_peak wall_force marked_speeds; do
    svg="$work/quick/figures/$f.svg"
    [ -s "$svg" ] || { echo "$f.svg was not written"; echo "$out"; exit 1; }
    head -n 1 "$svg" | grep -q '^<svg xmlns="http://www.w3.org/2000/svg"' &&
        [ "$(tail -n 1 "$svg")" = "</svg>" ] || { echo "$f.svg is not an SVG document"; exit 1; }
    grep -q "^  $f.svg: " <<<"$out" || { echo "the summary does not list $f.svg"; echo "$out"; exit 1; }
done
grep -q "^4 figures written to $work/quick/figures:" <<<"$out" ||
    { echo "no count of the figures written"; echo "$out"; exit 1; }
grep -q '>peak sampled pressure (kPa)</text>' "$work/quick/figures/pressure_peak.svg" ||
    { echo "pressure_peak.svg has no colour bar label in kPa"; exit 1; }
grep -q '>red (camera, every 0.04 s)</text>' "$work/quick/figures/marked_speeds.svg" ||
    { echo "marked_speeds.svg has no camera series for rock red"; exit 1; }
grep -Eq '^marked rocks \(' <<<"$out" && grep -Eq '^ +1  red ' <<<"$out" ||
    { echo "the summary has no marked rocks' table"; echo "$out"; exit 1; }
echo "the quick scenario wrote and listed the four figures and the marked rocks' table"

json=$("$rockfall" simulate "$quick" --json --camera-interval 0.02 --figures "$work/quick/json")
grep -q '"camera_interval_s": 0.02' <<<"$json" && grep -q '"speed_at_distance"' <<<"$json" &&
    grep -q '"figures_written"' <<<"$json" ||
    { echo "--json lacks marked_rocks with the camera interval or the figures written"; exit 1; }
[ -s "$work/quick/json/marked_speeds.svg" ] || { echo "--json --figures wrote no figures"; exit 1; }
echo "--json has the marked rocks at the given camera interval and lists the figures"

out=$("$rockfall" simulate "$single" --figures "$work/single")
[ "$(ls "$work/single")" = "wall_force.svg" ] ||
    { echo "a single rock without cells or name wrote: $(ls "$work/single")"; exit 1; }
grep -q "^1 figure written to $work/single:" <<<"$out" || { echo "$out"; exit 1; }
echo "a single unnamed rock without [wall_cells] wrote wall_force.svg alone"

leftover=$(find "$work" -name '*.part*')
[ -z "$leftover" ] || { echo "part files left behind: $leftover"; exit 1; }
echo "no part file left behind"
