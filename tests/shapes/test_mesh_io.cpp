// Mesh import (assimp) and export: every tested format, node transforms, scaling, the round
// trip through OBJ and STL, and one clear error per kind of bad mesh.

#include "shapes/generators.hpp"
#include "shapes/mass_properties.hpp"
#include "shapes/measures.hpp"
#include "shapes/mesh_io.hpp"
#include "shapes/rocks.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::ConvexPolyhedron;
using rockfall::shapes::GeometryError;
using rockfall::shapes::MeshScaling;
using rockfall::shapes::read_mesh_hull;
using rockfall::shapes::Vec3;

const fs::path meshes = ROCKFALL_MESH_DATA_DIR;

// The test cube of tests/data/meshes: edge 0.2 m, centred at (0.1, 0.2, 0.3).
constexpr double kEdge = 0.2;
// assimp reads coordinates in single precision.
constexpr double kFloat = 1e-6;

// The error message read_mesh_hull gives for a file.
std::string error_of(const fs::path& file, const MeshScaling& scaling = {}) {
    try {
        read_mesh_hull(file, scaling);
    } catch (const GeometryError& error) {
        return error.what();
    }
    FAIL("no GeometryError for " << file);
    return "";
}

fs::path temporary(const std::string& name) {
    return fs::temp_directory_path() /
           ("rockfall_test_mesh_io_" + std::to_string(getpid()) + "_" + name);
}

}  // namespace

TEST_CASE("the cube reads the same from OBJ, STL, PLY, OFF, glTF and GLB", "[shapes][mesh]") {
    for (const char* name : {"cube.obj", "cube.stl", "cube_binary.stl", "cube.ply", "cube.off",
                             "cube.gltf", "cube.glb", "cube_points.obj"}) {
        INFO(name);
        const ConvexPolyhedron hull = read_mesh_hull(meshes / name);
        CHECK(hull.vertices.size() == 8);
        CHECK(hull.triangles.size() == 12);
        const auto p = rockfall::shapes::mass_properties(hull);
        CHECK_THAT(p.volume, WithinRel(kEdge * kEdge * kEdge, 3 * kFloat));
        CHECK_THAT(p.surface_area, WithinRel(6 * kEdge * kEdge, 3 * kFloat));
        CHECK_THAT(p.centroid.x(), WithinAbs(0.1, kFloat));
        CHECK_THAT(p.centroid.y(), WithinAbs(0.2, kFloat));
        CHECK_THAT(p.centroid.z(), WithinAbs(0.3, kFloat));
    }
}

TEST_CASE("node transforms of a glTF scene are applied", "[shapes][mesh]") {
    // The node scales the cube by 2 and moves it by 1 m along x.
    const auto p =
        rockfall::shapes::mass_properties(read_mesh_hull(meshes / "cube_scaled_node.gltf"));
    CHECK_THAT(p.volume, WithinRel(8 * kEdge * kEdge * kEdge, 3 * kFloat));
    CHECK_THAT(p.centroid.x(), WithinAbs(1.2, 2 * kFloat));
    CHECK_THAT(p.centroid.y(), WithinAbs(0.4, 2 * kFloat));
    CHECK_THAT(p.centroid.z(), WithinAbs(0.6, 2 * kFloat));
}

TEST_CASE("mesh scaling: factor, volume-equivalent size, long axis", "[shapes][mesh]") {
    const fs::path cube = meshes / "cube.obj";
    MeshScaling scaling;
    scaling.scale = 10.0;
    CHECK_THAT(rockfall::shapes::mass_properties(read_mesh_hull(cube, scaling)).volume,
               WithinRel(8.0, 3 * kFloat));

    scaling = {};
    scaling.size = 0.5;
    const auto sized = rockfall::shapes::shape_measures(read_mesh_hull(cube, scaling));
    CHECK_THAT(sized.equivalent_diameter, WithinRel(0.5, 1e-12));

    scaling = {};
    scaling.long_axis = 0.3;
    const auto long_axis = rockfall::shapes::shape_measures(read_mesh_hull(cube, scaling));
    CHECK_THAT(long_axis.axis_lengths[0], WithinRel(0.3, 1e-12));

    // A target size lifts the natural-size limit: a 1 km mesh may be scaled to 0.2 m.
    scaling = {};
    scaling.size = 0.2;
    CHECK_THAT(rockfall::shapes::shape_measures(read_mesh_hull(meshes / "km_rock.obj", scaling))
                   .equivalent_diameter,
               WithinRel(0.2, 1e-12));
}

TEST_CASE("bad scalings are GeometryErrors naming the key", "[shapes][mesh]") {
    const fs::path cube = meshes / "cube.obj";
    MeshScaling scaling;
    scaling.scale = -1.0;
    CHECK_THAT(error_of(cube, scaling), Contains("scale = -1: must be finite and > 0"));
    scaling = {};
    scaling.size = 0.2;
    scaling.long_axis = 0.3;
    CHECK_THAT(error_of(cube, scaling), Contains("give at most one of them"));
    scaling = {};
    scaling.size = 500.0;
    CHECK_THAT(error_of(cube, scaling), Contains("diameter is 500 m, outside the accepted"));
}

TEST_CASE("OBJ and STL round trip: write the hull, read it back, same measures", "[shapes][mesh]") {
    const ConvexPolyhedron hull = rockfall::shapes::ellipsoid_rock(Vec3(1.0, 0.7, 0.4), 5);
    const auto rock = rockfall::shapes::make_rock({"rock", hull}, 0.3);
    const auto original = rockfall::shapes::shape_measures(rock);
    for (const char* name : {"rock.obj", "rock.stl"}) {
        INFO(name);
        const fs::path file = temporary(name);
        {
            std::ofstream out(file);
            if (fs::path(name).extension() == ".obj") {
                rockfall::shapes::write_obj(out, rock.hull, "round trip\nsecond comment line");
            } else {
                rockfall::shapes::write_stl(out, rock.hull, "round trip");
            }
        }
        const ConvexPolyhedron back = read_mesh_hull(file);
        fs::remove(file);
        CHECK(back.vertices.size() == rock.hull.vertices.size());
        CHECK(back.triangles.size() == rock.hull.triangles.size());
        const auto measures = rockfall::shapes::shape_measures(back);
        // Single-precision coordinates: relative 6e-8 each.
        CHECK_THAT(measures.properties.volume, WithinRel(original.properties.volume, 3 * kFloat));
        CHECK_THAT(measures.properties.surface_area,
                   WithinRel(original.properties.surface_area, 3 * kFloat));
        CHECK_THAT(measures.wadell_sphericity, WithinRel(original.wadell_sphericity, kFloat));
        CHECK_THAT(measures.krumbein_sphericity,
                   WithinRel(original.krumbein_sphericity, 3 * kFloat));
        for (int i = 0; i < 3; ++i) {
            CHECK_THAT(measures.axis_lengths[i], WithinRel(original.axis_lengths[i], 3 * kFloat));
            CHECK_THAT(measures.properties.principal_moments[i],
                       WithinRel(original.properties.principal_moments[i], 5 * kFloat));
            CHECK_THAT(measures.properties.centroid[i], WithinAbs(0.0, kFloat));
        }
    }
}

TEST_CASE("OBJ output: comments, shortest exact numbers, 1-based outward faces", "[shapes][mesh]") {
    ConvexPolyhedron tetra;
    tetra.vertices = {Vec3(0, 0, 0), Vec3(0.1, 0, 0), Vec3(0, 0.1, 0), Vec3(0, 0, 0.1)};
    tetra.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    std::ostringstream obj;
    rockfall::shapes::write_obj(obj, tetra, "one\ntwo");
    CHECK(obj.str() ==
          "# one\n# two\nv 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\n"
          "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
    std::ostringstream stl;
    rockfall::shapes::write_stl(stl, tetra, "tetra");
    CHECK_THAT(stl.str(), Contains("solid tetra\n  facet normal 0 0 -1\n    outer loop\n"
                                   "      vertex 0 0 0\n      vertex 0 0.1 0\n"));
    CHECK_THAT(stl.str(), Contains("endsolid tetra\n"));
}

TEST_CASE("every bad mesh is a GeometryError naming the file and the problem", "[shapes][mesh]") {
    const std::pair<const char*, const char*> cases[] = {
        {"does_not_exist.obj", "no such file"},
        {"folder.obj", "is a directory"},
        {"unknown.xyz", "unknown mesh format '.xyz'"},
        {"no_extension", "unknown mesh format (no file extension)"},
        {"garbage.stl", "cannot be read as .stl"},
        {"garbage.ply", "cannot be read as .ply"},
        {"empty.obj", "contains no vertices (empty mesh)"},
        {"empty.stl", "contains no vertices (empty mesh)"},
        {"nan.obj", "non-finite coordinates"},
        {"inf.off", "non-finite coordinates"},
        {"short_faces.off",
         "the header announces 8 vertices and 12 faces, one line each, but "
         "only 18 lines follow it"},
        {"fuzz_crash.off", "cannot be read as .off: line 5"},
        {"bad_index.ply",
         "face 12 of mesh 1 (counting from 1) names vertex 8 of a mesh with 8 "
         "vertices"},
        {"flat.obj", "collinear or coplanar"},
        {"collinear.ply", "collinear or coplanar"},
        {"km_rock.obj", "diameter is 1240.7 m, outside the accepted [0.001, 100] m"},
        {"micron_rock.stl", "diameter is 1.2407e-06 m, outside the accepted [0.001, 100] m"},
        {"far_away.obj", "single-precision coordinates would blur its shape"},
    };
    for (const auto& [name, problem] : cases) {
        INFO(name);
        const std::string message = error_of(meshes / name);
        CHECK_THAT(message, Contains("mesh file '" + (meshes / name).string() + "'"));
        CHECK_THAT(message, Contains(problem));
    }
}

TEST_CASE("an unreadable mesh file is a GeometryError", "[shapes][mesh]") {
    const fs::path file = temporary("unreadable.obj");
    fs::copy_file(meshes / "cube.obj", file, fs::copy_options::overwrite_existing);
    fs::permissions(file, fs::perms::none);
    // Root reads any file: there the permission cannot make it unreadable.
    if (geteuid() != 0) {
        CHECK_THAT(error_of(file), Contains("cannot be opened"));
    } else {
        CHECK(read_mesh_hull(file).vertices.size() == 8);
    }
    fs::remove(file);
}

TEST_CASE("mesh extensions: the tested formats are among assimp's", "[shapes][mesh]") {
    const std::vector<std::string> extensions = rockfall::shapes::mesh_extensions();
    for (const char* extension : {".obj", ".stl", ".ply", ".off", ".gltf", ".glb"}) {
        CHECK(std::find(extensions.begin(), extensions.end(), extension) != extensions.end());
    }
    CHECK(rockfall::shapes::is_mesh_file("ROCK.OBJ"));
    CHECK_FALSE(rockfall::shapes::is_mesh_file("catalogue.toml"));
    CHECK_FALSE(rockfall::shapes::is_mesh_file("obj"));
}
