#pragma once
/// The five Platonic solids as convex hulls.

#include "shapes/polyhedron.hpp"

#include <string_view>

namespace rockfall::shapes {

/// One of the five regular convex polyhedra.
enum class PlatonicKind {
    tetrahedron,   ///< 4 triangular faces
    cube,          ///< 6 square faces
    octahedron,    ///< 8 triangular faces
    dodecahedron,  ///< 12 pentagonal faces
    icosahedron,   ///< 20 triangular faces
};

/// Lower-case name of a kind ("tetrahedron", "cube", ...).
std::string_view to_string(PlatonicKind kind);

/// The Platonic solid with the given edge length, m (finite, > 0), centred on the origin, as
/// the Qhull hull of its vertices (faces triangulated). Throws GeometryError for a bad edge.
ConvexPolyhedron platonic_solid(PlatonicKind kind, double edge_length);

}  // namespace rockfall::shapes
