#!/usr/bin/env bash
# Regenerates the sample rock meshes in obj/ and stl/ with `rockfall shape` (our own code):
# three of seed 001's four particle shapes as true solids (its fourth, the sphere, is
# kind = "sphere": an exact sphere, not a mesh) and seven seeded random rocks, all at a
# volume-equivalent diameter of 0.20 m, in the body frame (centroid at the origin, long axis x).
# Usage: samples/rocks/generate.sh [path/to/rockfall]   (default: build/app/rockfall)
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
rockfall=${1:-$here/../../build/app/rockfall}
mkdir -p "$here/obj" "$here/stl"

make() {  # make NAME ARGS...: writes obj/NAME.obj and stl/NAME.stl
    local name=$1
    shift
    "$rockfall" shape "$@" --size 0.2 --obj "$here/obj/$name.obj" --stl "$here/stl/$name.stl" \
        >/dev/null
}

# Seed 001's clump shapes (10-ball tetrahedral, 27-ball cubic, 19-ball octahedral clumps).
make tetrahedron --kind tetrahedron
make cube --kind cube
make octahedron --kind octahedron
# Irregular rocks with axis ratios of the seed 000 families and an elongated one.
make equant_rock --generate ellipsoid --ratios 1 0.9 0.8 --seed 11
make elongated_rock --generate ellipsoid --ratios 1 0.6 0.5 --seed 12
make flat_rock --generate ellipsoid --ratios 1 0.8 0.35 --seed 13
# Wadell sphericities of seed 001's four marked rocks.
make psi_072 --generate sphericity --sphericity 0.72 --seed 21
make psi_080 --generate sphericity --sphericity 0.80 --seed 22
make psi_085 --generate sphericity --sphericity 0.85 --seed 23
make psi_089 --generate sphericity --sphericity 0.89 --seed 24
