#!/usr/bin/env bash
# Regenerates the sample terrain mesh with `rockfall terrain` (our own code): the seed slope's
# reference profile (../seed_slope.toml) triangulated every 0.25 m on the surface, 0.5 m past the
# crown, the end and both sides, with a smooth random relief of 3 cm rms (wavelengths 1 to 8 m,
# seed 7) standing in for a survey. The mesh is in the slope frame (m): x downslope from the
# crown, y across, z up.
# Usage: samples/terrain/generate.sh [path/to/rockfall]   (default: build/app/rockfall)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rockfall=${1:-$here/../../build/app/rockfall}
"$rockfall" terrain "$here/../seed_slope.toml" --spacing 0.25 --margin 0.5 --roughness 0.03 \
    --wavelength 1 --seed 7 --obj "$here/survey.obj" >/dev/null
