#pragma once
// Custom rock shapes in scenario files: the keys `mesh`, `mesh_scale`, `catalogue`, `entry`,
// `vertices`, `shape_name` and `long_axis` of a [[rocks]] table (docs/scenarios.md, "Rocks from
// meshes, catalogues and generators").

#include "scenario_reader.hpp"

#include "engine/scenario.hpp"
#include "shapes/catalogue.hpp"
#include "shapes/rocks.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::scenario::detail {

// Shapes and catalogues loaded while reading one scenario, so that rocks naming the same mesh
// at the same scaling share one hull and each file is read once.
class RockShapeCache {
  public:
    // The shape stored under `key`, or null.
    std::shared_ptr<const shapes::CustomShape> find(const std::string& key) const;
    // Stores and returns `shape` under `key`.
    std::shared_ptr<const shapes::CustomShape> add(const std::string& key,
                                                   shapes::CustomShape shape);
    // The catalogue read from `source` (read on first use; throws shapes::GeometryError).
    const shapes::ShapeCatalogue& catalogue(const std::filesystem::path& source);

  private:
    std::map<std::string, std::shared_ptr<const shapes::CustomShape>> shapes_;
    std::map<std::string, shapes::ShapeCatalogue> catalogues_;
};

// A path written at `node`, resolved against the folder of the file that wrote it (a base
// file's own folder for keys that came through extends).
std::filesystem::path resolve_path(const toml::node& node, const std::string& path,
                                   Context& context);

// The points of the `vertices` key of r's table, `node` ([[x, y, z], ...], m); reports a
// malformed value at that key and returns nothing.
std::optional<std::vector<shapes::Vec3>> read_vertices(TableReader& r, const toml::node& node);

// Reads the custom-shape keys of one [[rocks]] table, after its kind and size. With a shape
// source (exactly one of mesh, catalogue + entry, vertices) the rock becomes kind custom with
// that hull, and its size, when not written, becomes the shape's own volume-equivalent
// diameter (or follows from long_axis). Problems are reported at their keys.
void read_rock_shape(TableReader& r, engine::RockSpec& rock, RockShapeCache& cache);

// Reads a rock's own keys from r's table (a [[rocks]] entry or a marked cluster rock): `kind`,
// `size`, `density`, the custom-shape keys and [material].
void read_rock_spec(TableReader& r, engine::RockSpec& rock, RockShapeCache& cache);

// Checks a rock's own fields read by read_rock_spec, at `path` (e.g. "rocks[0]"): size,
// density, material, a custom kind exactly with a shape, and a mean restitution with the wall
// above 0. Returns whether its geometry can be built.
bool check_rock_spec(Checker& c, const engine::Scenario& scenario, const engine::RockSpec& rock,
                     const std::string& path);

}  // namespace rockfall::scenario::detail
