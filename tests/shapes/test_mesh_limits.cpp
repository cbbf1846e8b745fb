// Mesh files refused before the expensive work: PLY headers that break the format's rules (one
// without `end_header` hung assimp), and meshes or hulls beyond the documented size limits.

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::shapes::GeometryError;
using rockfall::shapes::max_hull_vertices;
using rockfall::shapes::max_mesh_vertices;
using rockfall::shapes::read_mesh_hull;
using rockfall::shapes::read_mesh_triangles;

// A file in the temporary directory, removed on destruction.
class TemporaryMesh {
  public:
    TemporaryMesh(const std::string& name, const std::string& bytes)
        : path_(fs::temp_directory_path() /
                ("rockfall_test_mesh_limits_" + std::to_string(getpid()) + "_" + name)) {
        std::ofstream(path_, std::ios::binary) << bytes;
    }
    TemporaryMesh(const TemporaryMesh&) = delete;
    TemporaryMesh& operator=(const TemporaryMesh&) = delete;
    ~TemporaryMesh() { fs::remove(path_); }
    const fs::path& path() const { return path_; }

  private:
    fs::path path_;
};

std::string error_of(const fs::path& file) {
    try {
        read_mesh_hull(file);
    } catch (const GeometryError& error) {
        return error.what();
    }
    FAIL("no GeometryError for " << file);
    return "";
}

const std::string cube_vertices =
    "0 0 0\n0 0 0.2\n0 0.2 0\n0 0.2 0.2\n0.2 0 0\n0.2 0 0.2\n0.2 0.2 0\n0.2 0.2 0.2\n";

std::string ply_header(const std::string& body) { return "ply\nformat ascii 1.0\n" + body; }

// `count` points on a sphere of radius 0.2 m (a Fibonacci lattice: every one on the hull).
std::string sphere_obj(std::size_t count) {
    std::string text;
    const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
    for (std::size_t i = 0; i < count; ++i) {
        const double z = 1.0 - 2.0 * (static_cast<double>(i) + 0.5) / static_cast<double>(count);
        const double r = std::sqrt(1.0 - z * z);
        const double t = golden * static_cast<double>(i);
        text += "v " + std::to_string(0.2 * r * std::cos(t)) + " " +
                std::to_string(0.2 * r * std::sin(t)) + " " + std::to_string(0.2 * z) + "\n";
    }
    return text;
}

}  // namespace

TEST_CASE("a good PLY header passes, ASCII and binary", "[shapes][mesh]") {
    const TemporaryMesh ascii("ascii.ply",
                              ply_header("comment a cube\nobj_info scanner 1\nelement vertex 8\n"
                                         "property float x\nproperty float y\nproperty float z\n"
                                         "end_header\n") +
                                  cube_vertices);
    CHECK(read_mesh_hull(ascii.path()).vertices.size() == 8);
    std::string binary =
        "ply\r\nformat binary_little_endian 1.0\r\nelement vertex 8\r\nproperty float x\r\n"
        "property float y\r\nproperty float z\r\nend_header\n";
    for (int corner = 0; corner < 8; ++corner) {
        for (const int bit : {4, 2, 1}) {
            const float value = (corner & bit) != 0 ? 0.2F : 0.0F;
            binary.append(reinterpret_cast<const char*>(&value), sizeof value);
        }
    }
    const TemporaryMesh little("binary.ply", binary);
    CHECK(read_mesh_hull(little.path()).vertices.size() == 8);
}

TEST_CASE("a PLY header that breaks the format's rules is refused at once", "[shapes][mesh]") {
    const std::string vertex =
        "element vertex 8\nproperty float x\nproperty float y\n"
        "property float z\n";
    const std::pair<std::string, std::string> cases[] = {
        // The file that hung: the header never ends, and assimp read on forever.
        {ply_header(vertex) + cube_vertices,
         "line 7 (\"0 0 0\"): not a header line (comment, obj_info, element, property or "
         "end_header); is the `end_header` line missing?"},
        {ply_header(vertex),
         "the header has no `end_header` line (the file ends at line 6 without one)"},
        {"ply\n", "the header ends after `ply`, without a `format` line"},
        {"PLY\nformat ascii 1.0\n", "a PLY file starts with the line `ply`, this one with \"PLY\""},
        {"ply\nformat ascii 2.0\nend_header\n",
         "line 2 is \"format ascii 2.0\", not `format ascii"},
        {ply_header("element vertex eight\nend_header\n"),
         "line 3 (\"element vertex eight\"): an element line is `element NAME COUNT`"},
        {ply_header("element vertex -8\nend_header\n"),
         "line 3 (\"element vertex -8\"): an element line is `element NAME COUNT`, COUNT >= 0"},
        {ply_header("property float x\nelement vertex 8\nend_header\n"),
         "line 3 (\"property float x\"): a property before any element"},
        {ply_header("element vertex 8\nproperty real x\nend_header\n"),
         "line 4 (\"property real x\"): a property line is `property TYPE NAME`"},
        {ply_header("element vertex 8\nproperty list uchar x\nend_header\n"),
         "line 4 (\"property list uchar x\"): a property line is `property TYPE NAME` or "
         "`property list COUNT_TYPE TYPE NAME`"},
        {ply_header(vertex + "vertices follow\nend_header\n"),
         "line 7 (\"vertices follow\"): not a header line"},
        // Counts the file cannot hold are refused before assimp allocates for them.
        {ply_header(vertex +
                    "element face 1000000000000\nproperty list uchar int i\nend_header\n") +
             cube_vertices,
         "the header announces 1000000000000 face entries of at least 2 bytes each, but only " +
             std::to_string(cube_vertices.size()) + " bytes follow it (the file is truncated)"},
        {"ply\nformat binary_little_endian 1.0\n" + vertex + "end_header\n" + std::string(95, '\0'),
         "the header announces 8 vertex entries of at least 12 bytes each, but only 95 bytes"},
        {ply_header("element vertex 1000000\nproperty float x\nproperty float y\nproperty float z\n"
                    "end_header\n"),
         "the header announces 1000000 vertices, more than the 200000 a mesh file may have "
         "(max_mesh_vertices)"},
    };
    int number = 0;
    for (const auto& [text, problem] : cases) {
        const TemporaryMesh file("bad_" + std::to_string(++number) + ".ply", text);
        INFO(text);
        const std::string message = error_of(file.path());
        CHECK_THAT(message, Contains("mesh file '" + file.path().string() +
                                     "': cannot be read as .ply: " + problem));
    }
    // A header of text lines must end within 1 MiB: a long binary blob without `end_header`.
    const TemporaryMesh blob("blob.ply", ply_header(std::string(std::size_t{3} << 20, 'x')));
    CHECK_THAT(error_of(blob.path()), Contains("no `end_header` line in its first 1 MiB"));
}

TEST_CASE("a mesh file beyond max_mesh_vertices is refused before the hull", "[shapes][mesh]") {
    const TemporaryMesh many("many.obj", sphere_obj(max_mesh_vertices + 1));
    const auto start = std::chrono::steady_clock::now();
    const std::string message = error_of(many.path());
    INFO("refused after "
         << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
         << " s");
    CHECK_THAT(message, Contains("has 200001 vertices, more than the 200000 a mesh file may have "
                                 "(max_mesh_vertices)"));
    CHECK_THROWS_WITH(read_mesh_triangles(many.path()), Contains("(max_mesh_vertices)"));
    // A binary STL says its size in its header: 70000 triangles, 210000 vertices.
    std::string stl(80, ' ');
    const std::uint32_t triangles = 70000;
    stl.append(reinterpret_cast<const char*>(&triangles), sizeof triangles);
    stl.append(std::size_t{50} * triangles, '\0');
    const TemporaryMesh big("big.stl", stl);
    CHECK_THAT(error_of(big.path()),
               Contains("a binary STL of 70000 triangles has 210000 vertices, more than the "
                        "200000 a mesh file may have"));
}

TEST_CASE("a rock hull beyond max_hull_vertices is refused", "[shapes][mesh]") {
    const TemporaryMesh fine("fine.obj", sphere_obj(max_hull_vertices));
    CHECK(read_mesh_hull(fine.path()).vertices.size() == max_hull_vertices);
    const TemporaryMesh round("round.obj", sphere_obj(max_hull_vertices + 1));
    CHECK_THAT(error_of(round.path()),
               Contains("its convex hull has 2001 vertices, more than the 2000 a rock may have "
                        "(max_hull_vertices"));
}

// Found by the fuzz targets (docs/fuzzing.md): counts and lengths in a file that assimp sizes
// its arrays by before reading what they count, and a broken glTF that assimp handed to
// another format's importer, which crashed.
TEST_CASE("counts and lengths a mesh file cannot hold are refused before assimp reads it",
          "[shapes][mesh]") {
    const std::string vertex =
        "element vertex 8\nproperty float x\nproperty float y\nproperty float z\n";
    const std::string faces =
        "element face 2\nproperty list uchar int vertex_indices\nend_header\n";
    // A PLY list count beyond its type or the values on its line (a count of 10^12 made assimp
    // take 22 GB), an entry short of values, and a list whose count type is not an integer.
    const std::pair<std::string, std::string> plies[] = {
        {ply_header(vertex + faces) + cube_vertices + "3 0 1 2\n999999999999 0 1 2\n",
         "face entry 1 has a list count that is not a whole number in [0, 255]"},
        {ply_header(vertex + faces) + cube_vertices + "3 0 1 2\n200 0 1 2\n",
         "line 19 (face entry 1): a list of 200 values, but the line holds only 3 more"},
        {ply_header(vertex + faces) + cube_vertices + "3 0 1 2\n-3 0 1 2\n",
         "face entry 1 has a list count that is not a whole number in [0, 255]"},
        {ply_header(vertex + faces) + "0 0 0\n0 0\n" + cube_vertices.substr(12) + "3 0 1 2\n",
         "line 11 (vertex entry 1): fewer values than the element's 3 properties"},
        {ply_header(vertex + "element face 1\nproperty list float int vertex_indices\n"
                             "end_header\n") +
             cube_vertices + "3 0 1 2\n",
         "a list's count type must be an integer type"},
    };
    int number = 0;
    for (const auto& [text, problem] : plies) {
        const TemporaryMesh file("list_" + std::to_string(++number) + ".ply", text);
        INFO(text);
        CHECK_THAT(error_of(file.path()), Contains(problem));
    }
    // A count too large for 64 bits was read as 0 by the header check (found by fuzz_mesh_ply:
    // assimp then read for ever).
    const TemporaryMesh huge("huge_count.ply",
                             ply_header("element vertex 65555555555555555555555555\nproperty "
                                        "float x\nend_header\n0\n"));
    CHECK_THAT(error_of(huge.path()), Contains("an element line is `element NAME COUNT`"));
    const TemporaryMesh nul(
        "nul.ply", ply_header(vertex + faces) + cube_vertices + "3 0 1 2\n3 1" + '\0' + "1 0 1\n");
    CHECK_THAT(error_of(nul.path()), Contains("the ASCII data hold a NUL byte"));
    // The same good file passes the walk.
    const TemporaryMesh good("lists.ply",
                             ply_header(vertex + faces) + cube_vertices + "3 0 1 2\n4 4 5 6 7\n");
    CHECK(read_mesh_hull(good.path()).vertices.size() == 8);

    // OFF counts, read by assimp as wrapping 32-bit numbers (129000000004 faces took 2.3 GB).
    const TemporaryMesh off("counts.off", "OFF\n8 129000000004 0\n" + cube_vertices + "3 0 1 2\n");
    CHECK_THAT(error_of(off.path()),
               Contains("cannot be read as .off: the header announces 8 vertices and "
                        "129000000004 faces, one line each, but only 9 lines follow it"));
    // Face lines assimp's two passes read differently (a crash): every face is 1 to 9 corners
    // naming vertices that exist, every vertex three numbers; no NUL byte.
    const std::pair<std::string, std::string> offs[] = {
        {"OFF\n8 1 0\n" + cube_vertices + "10 0 1 2 3 4 5 6 7 0 1\n",
         "line 11 (\"10 0 1 2 3 4 5 6 7 0 1\"): a face line is n (1 to 9) and n vertex indices "
         "in [0, 8)"},
        {"OFF\n8 1 0\n" + cube_vertices + "3 0 1 8\n", "line 11 (\"3 0 1 8\"): a face line"},
        {"OFF\n8 1 0\n" + cube_vertices + "3 0 1\n", "line 11 (\"3 0 1\"): a face line"},
        {"OFF\n8 1 0\n0 0\n" + cube_vertices.substr(6) + "3 0 1 2\n",
         "line 3 (\"0 0\"): a vertex line starts with three numbers"},
        {std::string("OFF\n8 1 0\n") + '\0' + cube_vertices + "3 0 1 2\n", "it holds a NUL byte"},
        {"8 1 0\n" + cube_vertices + "3 0 1 2\n", "it starts with its keyword"},
    };
    for (const auto& [text, problem] : offs) {
        const TemporaryMesh file("face_" + std::to_string(++number) + ".off", text);
        INFO(text);
        CHECK_THAT(error_of(file.path()), Contains("cannot be read as .off: " + problem));
    }
    const TemporaryMesh good_off(
        "good.off", "OFF\n# a cube\n8 2 0\n\n" + cube_vertices + "3 0 1 2 255 0 0\n4 4 5 7 6\n");
    CHECK(read_mesh_hull(good_off.path()).vertices.size() == 8);
    const TemporaryMesh off_many("many.off", "OFF\n200001 1 0\n" + cube_vertices);
    CHECK_THAT(error_of(off_many.path()), Contains("announces 200001 vertices, more than the"));

    // A GLB chunk longer than the file (a 3.9 GB JSON chunk in 848 bytes).
    std::string glb = "glTF";
    const auto word = [&glb](std::uint32_t value) {
        for (int i = 0; i < 4; ++i) glb += static_cast<char>((value >> (8 * i)) & 0xFFU);
    };
    const std::string json = R"({"asset": {"version": "2.0"}})";
    word(2);
    word(static_cast<std::uint32_t>(12 + 8 + json.size()));
    word(0xEA00028CU);
    glb += "JSON" + json;
    const TemporaryMesh chunk("chunk.glb", glb);
    CHECK_THAT(error_of(chunk.path()),
               Contains("cannot be read as .glb: chunk 1 announces 3925869196 bytes, but only 29 "
                        "follow it"));

    // Text that is no glTF: assimp's glTF readers both decline it, and it went to OpenGEX.
    const TemporaryMesh gltf("opengex.gltf", "esset: {!.0vertexarray (attrib\x85\x90\x9c\xff");
    CHECK_THAT(error_of(gltf.path()),
               Contains("cannot be read as .gltf: none of assimp's .gltf readers recognises its "
                        "contents"));
}
