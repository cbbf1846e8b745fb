// Mesh files through the importer (shapes::read_mesh_hull and read_mesh_triangles), one target
// per format: ROCKFALL_FUZZ_MESH_EXTENSION is the file extension (".obj", ".ply", ...) the
// bytes are written under, which picks assimp's reader.

#include "fuzz_support.hpp"

#include "shapes/mesh_io.hpp"

#include <filesystem>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    const std::filesystem::path file = fuzz::write_scratch(
        std::string("mesh") + ROCKFALL_FUZZ_MESH_EXTENSION, fuzz::text_of(data, size));
    fuzz::expect_clear_refusal([&] {
        const shapes::TriangleMesh mesh = shapes::read_mesh_triangles(file);
        fuzz::require(mesh.vertices.size() <= shapes::max_mesh_vertices,
                      "a mesh over the vertex limit was read");
        for (const auto& triangle : mesh.triangles)
            for (const int index : triangle)
                fuzz::require(index >= 0 && static_cast<std::size_t>(index) < mesh.vertices.size(),
                              "a triangle names a vertex the mesh does not have");
    });
    fuzz::expect_clear_refusal([&] {
        const shapes::ConvexPolyhedron hull = shapes::read_mesh_hull(file);
        fuzz::require(hull.vertices.size() <= shapes::max_hull_vertices,
                      "a hull over the vertex limit was built");
    });
    return 0;
}
