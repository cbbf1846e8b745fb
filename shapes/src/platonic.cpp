#include "shapes/platonic.hpp"

#include <cassert>
#include <cmath>
#include <numbers>
#include <sstream>
#include <vector>

namespace rockfall::shapes {
namespace {

// Every sign combination of (x, y, z), skipping duplicates where a coordinate is zero.
void add_signed(std::vector<Vec3>& points, double x, double y, double z) {
    for (const double sx : {-1.0, 1.0}) {
        for (const double sy : {-1.0, 1.0}) {
            for (const double sz : {-1.0, 1.0}) {
                if ((x == 0.0 && sx > 0.0) || (y == 0.0 && sy > 0.0) || (z == 0.0 && sz > 0.0)) {
                    continue;
                }
                points.emplace_back(sx * x, sy * y, sz * z);
            }
        }
    }
}

// The three cyclic permutations of (x, y, z) with every sign combination.
void add_cyclic(std::vector<Vec3>& points, double x, double y, double z) {
    add_signed(points, x, y, z);
    add_signed(points, y, z, x);
    add_signed(points, z, x, y);
}

// Textbook vertex coordinates (Coxeter, "Regular Polytopes", 1973, table I) and the edge
// length they give, so that the caller only rescales.
struct Canonical {
    std::vector<Vec3> vertices;
    double edge = 0.0;
};

Canonical canonical(PlatonicKind kind) {
    const double phi = std::numbers::phi;
    Canonical c;
    switch (kind) {
        case PlatonicKind::tetrahedron:
            c.vertices = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
            c.edge = 2.0 * std::numbers::sqrt2;
            break;
        case PlatonicKind::cube:
            add_signed(c.vertices, 1.0, 1.0, 1.0);
            c.edge = 2.0;
            break;
        case PlatonicKind::octahedron:
            add_cyclic(c.vertices, 1.0, 0.0, 0.0);
            c.edge = std::numbers::sqrt2;
            break;
        case PlatonicKind::dodecahedron:
            add_signed(c.vertices, 1.0, 1.0, 1.0);
            add_cyclic(c.vertices, 0.0, 1.0 / phi, phi);
            c.edge = 2.0 / phi;
            break;
        case PlatonicKind::icosahedron:
            add_cyclic(c.vertices, 0.0, 1.0, phi);
            c.edge = 2.0;
            break;
    }
    return c;
}

}  // namespace

std::string_view to_string(PlatonicKind kind) {
    switch (kind) {
        case PlatonicKind::tetrahedron:
            return "tetrahedron";
        case PlatonicKind::cube:
            return "cube";
        case PlatonicKind::octahedron:
            return "octahedron";
        case PlatonicKind::dodecahedron:
            return "dodecahedron";
        case PlatonicKind::icosahedron:
            return "icosahedron";
    }
    assert(false && "unknown PlatonicKind");
    return "unknown";
}

ConvexPolyhedron platonic_solid(PlatonicKind kind, double edge_length) {
    if (!(std::isfinite(edge_length) && edge_length > 0.0)) {
        std::ostringstream message;
        message << "platonic " << to_string(kind) << " edge_length = " << edge_length
                << " m: must be finite and > 0";
        throw GeometryError(message.str());
    }
    Canonical c = canonical(kind);
    const double scale = edge_length / c.edge;
    for (Vec3& v : c.vertices) {
        v *= scale;
    }
    return convex_hull(c.vertices);
}

}  // namespace rockfall::shapes
