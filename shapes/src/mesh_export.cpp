#include "shapes/mesh_io.hpp"

#include <Eigen/Geometry>

#include <charconv>
#include <ostream>

namespace rockfall::shapes {
namespace {

// Shortest decimal that reads back to the same double.
std::string number(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

std::string triple(const Vec3& v) {
    return number(v.x()) + " " + number(v.y()) + " " + number(v.z());
}

// The comment's lines as OBJ comment lines.
void write_comment(std::ostream& out, std::string_view comment) {
    std::string_view rest = comment;
    while (!rest.empty()) {
        const std::size_t end = rest.find('\n');
        out << "# " << rest.substr(0, end) << '\n';
        rest = end == std::string_view::npos ? std::string_view() : rest.substr(end + 1);
    }
}

void write_faces(std::ostream& out, const std::vector<Vec3>& vertices,
                 const std::vector<std::array<int, 3>>& triangles) {
    for (const Vec3& v : vertices) out << "v " << triple(v) << '\n';
    // OBJ indices count from 1.
    for (const auto& [a, b, c] : triangles) {
        out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
    }
}

}  // namespace

void write_obj(std::ostream& out, const ConvexPolyhedron& hull, std::string_view comment) {
    write_comment(out, comment);
    write_faces(out, hull.vertices, hull.triangles);
}

void write_obj(std::ostream& out, const TriangleMesh& mesh, std::string_view comment) {
    write_comment(out, comment);
    write_faces(out, mesh.vertices, mesh.triangles);
}

void write_stl(std::ostream& out, const ConvexPolyhedron& hull, std::string_view name) {
    std::string solid(name);
    for (char& c : solid) {
        if (c == '\n' || c == '\r') c = ' ';
    }
    out << "solid " << solid << '\n';
    for (const auto& triangle : hull.triangles) {
        const Vec3& a = hull.vertices[static_cast<std::size_t>(triangle[0])];
        const Vec3& b = hull.vertices[static_cast<std::size_t>(triangle[1])];
        const Vec3& c = hull.vertices[static_cast<std::size_t>(triangle[2])];
        out << "  facet normal " << triple((b - a).cross(c - a).normalized()) << '\n'
            << "    outer loop\n"
            << "      vertex " << triple(a) << '\n'
            << "      vertex " << triple(b) << '\n'
            << "      vertex " << triple(c) << '\n'
            << "    endloop\n"
            << "  endfacet\n";
    }
    out << "endsolid " << solid << '\n';
}

}  // namespace rockfall::shapes
