#include "mesh_header.hpp"

#include "shapes/mass_properties.hpp"
#include "shapes/measures.hpp"
#include "shapes/mesh_io.hpp"
#include "shapes/rocks.hpp"

#include <Eigen/Geometry>
#include <assimp/BaseImporter.h>
#include <assimp/Importer.hpp>
#include <assimp/importerdesc.h>
#include <assimp/postprocess.h>
#include <assimp/scene.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

namespace rockfall::shapes {
namespace {

namespace fs = std::filesystem;

// Single-precision coordinates (assimp's ai_real) resolve 6e-8 of their magnitude; a mesh
// further from the origin than this many times its extent loses more than 1e-4 of its shape.
constexpr double kMaxOffsetOverExtent = 1000.0;

std::string quoted(const fs::path& file) { return "'" + file.string() + "'"; }

[[noreturn]] void fail(const fs::path& file, const std::string& problem) {
    throw GeometryError("mesh file " + quoted(file) + ": " + problem);
}

std::string lower_extension(const fs::path& file) {
    std::string extension = file.extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return extension;
}

std::string describe(const Vec3& p) {
    std::ostringstream out;
    out << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
    return out.str();
}

void check_readable(const fs::path& file) {
    std::error_code error;
    const fs::file_status status = fs::status(file, error);
    if (!fs::exists(status)) fail(file, "no such file");
    if (fs::is_directory(status)) fail(file, "is a directory, not a mesh file");
    std::ifstream in(file, std::ios::binary);
    if (!in) fail(file, std::string("cannot be opened: ") + std::strerror(errno));
}

Eigen::Matrix4d to_eigen(const aiMatrix4x4& m) {
    Eigen::Matrix4d out;
    out << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2, m.d3,
        m.d4;
    return out;
}

// Vertices (and, when `triangles` is given, the triangles) of the meshes a node and its
// children place, through the product of the node transforms from the root (assimp stores each
// mesh in its node's local frame).
void collect(const aiScene& scene, const aiNode& node, const Eigen::Matrix4d& parent,
             std::vector<Vec3>& points, std::vector<std::array<int, 3>>* triangles) {
    const Eigen::Matrix4d transform = parent * to_eigen(node.mTransformation);
    const Eigen::Affine3d affine(transform);
    for (unsigned i = 0; i < node.mNumMeshes; ++i) {
        const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
        const auto first = static_cast<int>(points.size());
        for (unsigned k = 0; k < mesh.mNumVertices; ++k) {
            const aiVector3D& v = mesh.mVertices[k];
            points.push_back(affine * Vec3(v.x, v.y, v.z));
        }
        for (unsigned f = 0; triangles != nullptr && f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            // Points and lines have fewer indices; polygons were triangulated on import.
            if (face.mNumIndices != 3) continue;
            triangles->push_back({first + static_cast<int>(face.mIndices[0]),
                                  first + static_cast<int>(face.mIndices[1]),
                                  first + static_cast<int>(face.mIndices[2])});
        }
    }
    for (unsigned i = 0; i < node.mNumChildren; ++i) {
        collect(scene, *node.mChildren[i], transform, points, triangles);
    }
}

// assimp's readers can leave a scene its own post-processing asserts on (Debian builds assimp
// with assertions, which abort): an OFF file that declares more faces than it holds gets faces
// without corners, and a face or node may name an index past the end. Its validation step
// would also refuse point clouds (meshes without faces), so the structure is checked here.
void check_structure(const fs::path& file, const aiScene& scene) {
    for (unsigned m = 0; m < scene.mNumMeshes; ++m) {
        const aiMesh& mesh = *scene.mMeshes[m];
        for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
            const aiFace& face = mesh.mFaces[f];
            const std::string which = "face " + std::to_string(f + 1) + " of mesh " +
                                      std::to_string(m + 1) + " (counting from 1)";
            if (face.mNumIndices == 0) {
                fail(file, which +
                               " has no corners: the file lists fewer faces than it declares, "
                               "or a face line is broken");
            }
            for (unsigned k = 0; k < face.mNumIndices; ++k) {
                if (face.mIndices[k] >= mesh.mNumVertices) {
                    fail(file, which + " names vertex " + std::to_string(face.mIndices[k]) +
                                   " of a mesh with " + std::to_string(mesh.mNumVertices) +
                                   " vertices (numbered from 0)");
                }
            }
        }
    }
    std::vector<const aiNode*> nodes;
    if (scene.mRootNode != nullptr) nodes.push_back(scene.mRootNode);
    while (!nodes.empty()) {
        const aiNode& node = *nodes.back();
        nodes.pop_back();
        for (unsigned i = 0; i < node.mNumMeshes; ++i) {
            if (node.mMeshes[i] >= scene.mNumMeshes) {
                fail(file, "a node names mesh " + std::to_string(node.mMeshes[i]) + " of " +
                               std::to_string(scene.mNumMeshes));
            }
        }
        for (unsigned i = 0; i < node.mNumChildren; ++i) nodes.push_back(node.mChildren[i]);
    }
}

// assimp picks its importer by the extension; when several claim it (.gltf and .glb: glTF 1
// and glTF 2) it asks each whether the contents are theirs, and when none does it tries every
// importer it has on the contents: a broken .gltf then went to the OpenGEX importer, which
// crashed on it (found by fuzz_mesh_gltf). A file no importer of its extension recognises is
// refused here instead; with one importer assimp uses it without asking, and never falls back.
void check_importer(const fs::path& file, const Assimp::Importer& importer) {
    const std::string extension = lower_extension(file).substr(1);
    std::vector<Assimp::BaseImporter*> claims;
    for (std::size_t i = 0; i < importer.GetImporterCount(); ++i) {
        std::istringstream extensions(importer.GetImporterInfo(i)->mFileExtensions);
        for (std::string claimed; extensions >> claimed;) {
            if (claimed == extension) claims.push_back(importer.GetImporter(i));
        }
    }
    if (claims.size() <= 1) return;
    for (Assimp::BaseImporter* candidate : claims) {
        if (candidate->CanRead(file.string(), importer.GetIOHandler(), true)) return;
    }
    fail(file, "cannot be read as ." + extension + ": none of assimp's ." + extension +
                   " readers recognises its contents");
}

bool has_polygons(const aiScene& scene) {
    for (unsigned i = 0; i < scene.mNumMeshes; ++i) {
        if ((scene.mMeshes[i]->mPrimitiveTypes & aiPrimitiveType_POLYGON) != 0) return true;
    }
    return false;
}

// Every vertex of a mesh file and, when `triangles` is given, its triangles; the checks of
// read_mesh_vertices.
std::vector<Vec3> import_mesh(const fs::path& file, std::vector<std::array<int, 3>>* triangles) {
    check_readable(file);
    if (!is_mesh_file(file)) {
        const std::string extension = file.extension().string();
        fail(file, "unknown mesh format" +
                       (extension.empty() ? std::string(" (no file extension)")
                                          : " '" + extension + "'") +
                       ": use .obj, .stl, .ply, .off, .gltf or .glb (or another format assimp "
                       "reads)");
    }
    check_mesh_header(file, lower_extension(file));
    // No post-processing on reading: a hull needs only the vertices, and assimp's steps reject
    // point clouds (meshes without faces). assimp logs nothing unless a logger is created.
    Assimp::Importer importer;
    check_importer(file, importer);
    const aiScene* scene = importer.ReadFile(file.string(), 0);
    if (scene == nullptr) {
        fail(file, "cannot be read as " + lower_extension(file) + ": " + importer.GetErrorString());
    }
    check_structure(file, *scene);
    // Faces of more than three corners (quads of a survey grid) become triangles; only files
    // that have such faces go through the step, so point clouds still reach our own checks.
    if (triangles != nullptr && has_polygons(*scene)) {
        scene = importer.ApplyPostProcessing(aiProcess_Triangulate);
        if (scene == nullptr) {
            fail(file, "cannot be triangulated: " + std::string(importer.GetErrorString()));
        }
    }
    std::vector<Vec3> points;
    if (scene->mRootNode != nullptr) {
        collect(*scene, *scene->mRootNode, Eigen::Matrix4d::Identity(), points, triangles);
    }
    if (points.empty()) fail(file, "contains no vertices (empty mesh)");
    if (points.size() > max_mesh_vertices) {
        fail(file, "has " + std::to_string(points.size()) + " vertices, more than the " +
                       std::to_string(max_mesh_vertices) +
                       " a mesh file may have (max_mesh_vertices): simplify it first, e.g. by "
                       "quadric decimation in MeshLab or Blender");
    }
    const auto bad =
        std::find_if(points.begin(), points.end(), [](const Vec3& p) { return !p.allFinite(); });
    if (bad != points.end()) {
        const auto count = std::count_if(points.begin(), points.end(),
                                         [](const Vec3& p) { return !p.allFinite(); });
        fail(file, std::to_string(count) + " of " + std::to_string(points.size()) +
                       " vertices have non-finite coordinates, e.g. " + describe(*bad));
    }
    return points;
}

// Single-precision coordinates far from the origin blur the shape (kMaxOffsetOverExtent).
void check_precision(const fs::path& file, const std::vector<Vec3>& points) {
    Eigen::AlignedBox3d box;
    double offset = 0.0;
    for (const Vec3& p : points) {
        box.extend(p);
        offset = std::max(offset, p.cwiseAbs().maxCoeff());
    }
    const double extent = box.diagonal().norm();
    if (extent > 0.0 && offset > kMaxOffsetOverExtent * extent) {
        std::ostringstream problem;
        problem << "the mesh lies " << offset << " from the origin but is only " << extent
                << " across: single-precision coordinates would blur its shape; move it "
                   "near the origin";
        fail(file, problem.str());
    }
}

double factor_to_size(const ConvexPolyhedron& hull, const MeshScaling& scaling) {
    const MassProperties properties = mass_properties(hull);
    if (scaling.size > 0.0) return scaling.size / equivalent_diameter(properties.volume);
    if (scaling.long_axis > 0.0) return scaling.long_axis / axis_lengths(hull, properties)[0];
    return 1.0;
}

void check_scaling(const MeshScaling& scaling, std::string_view what) {
    std::ostringstream problem;
    if (!(std::isfinite(scaling.scale) && scaling.scale > 0.0)) {
        problem << "scale = " << scaling.scale << ": must be finite and > 0";
    } else if (!(std::isfinite(scaling.size) && scaling.size >= 0.0)) {
        problem << "size = " << scaling.size << " m: must be finite and >= 0";
    } else if (!(std::isfinite(scaling.long_axis) && scaling.long_axis >= 0.0)) {
        problem << "long_axis = " << scaling.long_axis << " m: must be finite and >= 0";
    } else if (scaling.size > 0.0 && scaling.long_axis > 0.0) {
        problem << "size = " << scaling.size << " m and long_axis = " << scaling.long_axis
                << " m: give at most one of them";
    }
    if (!problem.str().empty()) throw GeometryError(std::string(what) + ": " + problem.str());
}

}  // namespace

std::vector<std::string> mesh_extensions() {
    Assimp::Importer importer;
    std::string list;
    importer.GetExtensionList(list);
    std::vector<std::string> extensions;
    std::istringstream in(list);
    for (std::string item; std::getline(in, item, ';');) {
        // assimp lists "*.obj"; keep ".obj".
        if (item.size() > 1 && item[0] == '*') extensions.push_back(item.substr(1));
    }
    return extensions;
}

bool is_mesh_file(const fs::path& file) {
    const std::string extension = lower_extension(file);
    if (extension.size() < 2) return false;
    return Assimp::Importer().IsExtensionSupported(extension);
}

std::vector<Vec3> read_mesh_vertices(const fs::path& file) { return import_mesh(file, nullptr); }

TriangleMesh read_mesh_triangles(const fs::path& file) {
    TriangleMesh mesh;
    mesh.vertices = import_mesh(file, &mesh.triangles);
    check_precision(file, mesh.vertices);
    return mesh;
}

ConvexPolyhedron read_mesh_hull(const fs::path& file, const MeshScaling& scaling) {
    const std::vector<Vec3> points = read_mesh_vertices(file);
    check_precision(file, points);
    ConvexPolyhedron hull;
    try {
        hull = convex_hull(points);
    } catch (const GeometryError& error) {
        fail(file, error.what());
    }
    if (hull.vertices.size() > max_hull_vertices) {
        fail(file, "its convex hull has " + std::to_string(hull.vertices.size()) +
                       " vertices, more than the " + std::to_string(max_hull_vertices) +
                       " a rock may have (max_hull_vertices; each costs collision time): "
                       "simplify the mesh first, e.g. by quadric decimation in MeshLab or Blender");
    }
    return scaled_hull(hull, scaling, "mesh file " + quoted(file));
}

ConvexPolyhedron scaled_hull(const ConvexPolyhedron& hull, const MeshScaling& scaling,
                             std::string_view what) {
    check_scaling(scaling, what);
    ConvexPolyhedron out = hull;
    for (Vec3& v : out.vertices) v *= scaling.scale;
    const double factor = factor_to_size(out, scaling);
    for (Vec3& v : out.vertices) v *= factor;
    const double size = equivalent_diameter(mass_properties(out).volume);
    if (!(size >= min_nominal_size && size <= max_nominal_size)) {
        std::ostringstream problem;
        problem << what << ": the rock's volume-equivalent diameter is " << size
                << " m, outside the accepted [" << min_nominal_size << ", " << max_nominal_size
                << "] m";
        if (scaling.size == 0.0 && scaling.long_axis == 0.0) {
            problem << " (coordinates are read as metres times scale = " << scaling.scale
                    << "; give a scale such as 0.001 for millimetres, or a size)";
        }
        throw GeometryError(problem.str());
    }
    return out;
}

}  // namespace rockfall::shapes
