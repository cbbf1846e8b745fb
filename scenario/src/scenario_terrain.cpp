#include "scenario_terrain.hpp"

#include "scenario_rock_shape.hpp"

#include "shapes/terrain.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::scenario::detail {
namespace {

// The corners [i, j, k] of one triangle: vertex indices counted from 0.
std::optional<std::array<int, 3>> corners(const toml::node& item) {
    const auto* array = item.as_array();
    if (array == nullptr || array->size() != 3) return std::nullopt;
    std::array<int, 3> out{};
    for (std::size_t k = 0; k < 3; ++k) {
        const auto* index = array->get(k)->as_integer();
        if (index == nullptr || index->get() < 0 ||
            index->get() > std::numeric_limits<int>::max()) {
            return std::nullopt;
        }
        out[k] = static_cast<int>(index->get());
    }
    return out;
}

std::optional<shapes::TriangleMesh> inline_mesh(TableReader& r, const toml::node& vertices) {
    std::optional<std::vector<shapes::Vec3>> points = read_vertices(r, vertices);
    std::vector<std::array<int, 3>> triangles;
    bool ok = points.has_value();
    read_list(r, "triangles", triangles, "triangles [i, j, k] (vertex indices from 0)",
              [&](const toml::node& item, const std::string& path) {
                  std::optional<std::array<int, 3>> triangle = corners(item);
                  if (!triangle) {
                      r.context().report(item, path,
                                         describe(item) +
                                             ": must be a triangle [i, j, k] of 3 vertex indices "
                                             "(integers >= 0, counted from 0)");
                      ok = false;
                  }
                  return triangle;
              });
    if (!ok) return std::nullopt;
    return shapes::TriangleMesh{std::move(*points), std::move(triangles)};
}

}  // namespace

void read_terrain(TableReader& slope_reader, shapes::SlopeSpec& slope) {
    with_table(slope_reader, "terrain", [&](TableReader& r) {
        Context& context = r.context();
        const toml::node* mesh = r.get("mesh");
        const toml::node* vertices = r.get("vertices");
        const toml::node* triangles = r.get("triangles");
        shapes::TerrainPlacement placement;
        read(r, "scale", placement.scale, "", positive());
        read(r, "offset", placement.offset, "m", any_finite());
        std::string name;
        read(r, "name", name);
        // At the key's line, or the table's when the key is absent.
        const auto report = [&](std::string_view key, const std::string& message) {
            Location where = context.sources.find(r.path(key));
            context.problems.push_back({where.file, where.line, r.path(key), message});
        };

        bool ok = true;
        if (r.contains("scale") && !positive().contains(placement.scale)) {
            report("scale", format_number(placement.scale) + ": must be " + positive().describe());
            ok = false;
        }
        if (r.contains("offset") && !placement.offset.allFinite()) {
            report("offset",
                   format_vector(placement.offset) + " m: every component must be finite");
            ok = false;
        }
        if (r.contains("name") && name.empty()) {
            report("name", "\"\": must not be empty");
            ok = false;
        }
        if (mesh != nullptr && (vertices != nullptr || triangles != nullptr)) {
            report(vertices != nullptr ? "vertices" : "triangles",
                   "give either mesh or vertices with triangles, not both");
            return;
        }
        if (mesh == nullptr && (vertices == nullptr || triangles == nullptr)) {
            if (vertices == nullptr && triangles == nullptr) {
                report("mesh",
                       "missing: a terrain needs mesh = \"file\" (or vertices with "
                       "triangles)");
            } else {
                report(vertices == nullptr ? "vertices" : "triangles",
                       "missing: vertices and triangles go together");
            }
            return;
        }

        try {
            if (mesh != nullptr) {
                const auto* file = mesh->as_string();
                if (file == nullptr || file->get().empty()) {
                    context.report(*mesh, r.path("mesh"),
                                   describe(*mesh) +
                                       ": must be the path of a mesh file (a "
                                       "non-empty string)");
                    return;
                }
                if (!ok) return;
                slope.terrain = std::make_shared<const shapes::Terrain>(shapes::read_terrain(
                    resolve_path(*mesh, file->get(), context), placement, name));
                return;
            }
            std::optional<shapes::TriangleMesh> triangle_mesh = inline_mesh(r, *vertices);
            if (!triangle_mesh || !ok) return;
            slope.terrain = std::make_shared<const shapes::Terrain>(
                name.empty() ? std::string("terrain") : name, std::move(*triangle_mesh), placement,
                "terrain");
        } catch (const shapes::GeometryError& error) {
            const toml::node* at = mesh != nullptr ? mesh : vertices;
            context.report(*at, r.path(mesh != nullptr ? "mesh" : "vertices"),
                           describe(*at) + ": " + error.what());
        }
    });
}

void check_terrain(Checker& c, const engine::Scenario& s, bool profile_ok) {
    if (!s.slope.terrain || !profile_ok) return;
    const shapes::Terrain& terrain = *s.slope.terrain;
    const shapes::Slope slope(profile_only(s.slope));

    // Coordinates read in single precision may miss a boundary by their round-off.
    const double half = 0.5 * s.slope.width;
    const double slack = 1e-6 * std::max({1.0, slope.end_x(), s.slope.width});
    const shapes::Vec3& lo = terrain.lower();
    const shapes::Vec3& hi = terrain.upper();
    if (lo.x() > slack || hi.x() < slope.end_x() - slack || lo.y() > -half + slack ||
        hi.y() < half - slack) {
        c.fail("slope.terrain",
               "'" + terrain.name() + "' spans x in [" + format_number(lo.x()) + ", " +
                   format_number(hi.x()) + "] m, y in [" + format_number(lo.y()) + ", " +
                   format_number(hi.y()) + "] m",
               "must cover the slope's footprint, x in [0, " + format_number(slope.end_x()) +
                   "] m (crown to the end of the profile) and y in [" + format_number(-half) +
                   ", " + format_number(half) +
                   "] m (the width); place it in the slope frame with offset and scale");
        return;
    }
    for (std::size_t i = 0; i < s.rocks.size(); ++i) {
        const engine::Release& release = s.rocks[i].release;
        const shapes::Vec3 point =
            slope.point_at_distance(release.distance) + release.lateral * shapes::Vec3::UnitY();
        if (!terrain.ground(point.x(), point.y())) {
            c.fail("rocks[" + std::to_string(i) + "].release.distance",
                   format_number(release.distance) + " m",
                   "the terrain '" + terrain.name() +
                       "' has no surface under the release point (x = " + format_number(point.x()) +
                       " m, y = " + format_number(point.y()) + " m): a hole in the mesh");
        }
    }
}

}  // namespace rockfall::scenario::detail
