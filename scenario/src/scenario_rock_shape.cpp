#include "scenario_rock_shape.hpp"

#include "shapes/mass_properties.hpp"
#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace rockfall::scenario::detail {
namespace {

namespace fs = std::filesystem;

// The nodes of the shape keys of one rock table.
struct ShapeKeys {
    const toml::node* mesh = nullptr;
    const toml::node* mesh_scale = nullptr;
    const toml::node* catalogue = nullptr;
    const toml::node* entry = nullptr;
    const toml::node* vertices = nullptr;
    const toml::node* shape_name = nullptr;
    const toml::node* long_axis = nullptr;
};

const Range& size_range() {
    const auto found = std::find_if(rock_fields.begin(), rock_fields.end(),
                                    [](const auto& field) { return field.key == "size"; });
    return found->range;
}

std::optional<std::string> text(TableReader& r, const toml::node* node, std::string_view key) {
    if (const auto* value = node->as_string(); value != nullptr && !value->get().empty()) {
        return value->get();
    }
    r.context().report(*node, r.path(key), describe(*node) + ": must be a non-empty string");
    return std::nullopt;
}

std::optional<double> positive_number(TableReader& r, const toml::node* node, std::string_view key,
                                      std::string_view unit) {
    const std::optional<double> value = number_of(*node);
    if (value && std::isfinite(*value) && *value > 0.0) return value;
    r.context().report(*node, r.path(key),
                       describe(*node) + ": " + expectation("a number", unit, positive()));
    return std::nullopt;
}

std::string scaling_key(const shapes::MeshScaling& s) {
    return "|" + format_number(s.scale) + "|" + format_number(s.size) + "|" +
           format_number(s.long_axis);
}

// Loads the shape of the one source given; reports its problems and returns null on failure.
std::shared_ptr<const shapes::CustomShape> load(TableReader& r, const ShapeKeys& keys,
                                                shapes::MeshScaling scaling,
                                                const std::optional<std::string>& name,
                                                RockShapeCache& cache) {
    Context& context = r.context();
    const auto report = [&](const toml::node* node, std::string_view key, const auto& error) {
        context.report(*node, r.path(key), describe(*node) + ": " + error.what());
        return nullptr;
    };
    const std::string name_key = "|" + name.value_or("");
    if (keys.mesh != nullptr) {
        const std::optional<std::string> file = text(r, keys.mesh, "mesh");
        if (!file) return nullptr;
        const fs::path path = resolve_path(*keys.mesh, *file, context);
        const std::string key = "mesh|" + path.string() + scaling_key(scaling) + name_key;
        if (auto shape = cache.find(key)) return shape;
        try {
            return cache.add(
                key, {name.value_or(path.stem().string()), shapes::read_mesh_hull(path, scaling)});
        } catch (const shapes::GeometryError& error) {
            return report(keys.mesh, "mesh", error);
        }
    }
    if (keys.catalogue != nullptr) {
        const std::optional<std::string> file = text(r, keys.catalogue, "catalogue");
        if (keys.entry == nullptr) {
            context.report(
                *keys.catalogue, r.path("catalogue"),
                describe(*keys.catalogue) + ": needs entry = \"name\", the catalogue entry to use");
            return nullptr;
        }
        const std::optional<std::string> entry_name = text(r, keys.entry, "entry");
        if (!file || !entry_name) return nullptr;
        const fs::path path = resolve_path(*keys.catalogue, *file, context);
        shapes::CatalogueEntry entry;
        try {
            entry = shapes::find_entry(cache.catalogue(path), *entry_name);
        } catch (const shapes::GeometryError& error) {
            return report(keys.entry, "entry", error);
        }
        // The rock's own size or long axis replaces the entry's; the entry's scale stays.
        if (scaling.size > 0.0 || scaling.long_axis > 0.0) {
            entry.scaling.size = scaling.size;
            entry.scaling.long_axis = scaling.long_axis;
        }
        const std::string key = "catalogue|" + path.string() + "|" + *entry_name +
                                scaling_key(entry.scaling) + name_key;
        if (auto shape = cache.find(key)) return shape;
        try {
            shapes::CustomShape shape = shapes::load_entry(entry);
            if (name) shape.name = *name;
            return cache.add(key, std::move(shape));
        } catch (const shapes::GeometryError& error) {
            return report(keys.entry, "entry", error);
        }
    }
    const std::optional<std::vector<shapes::Vec3>> cloud = read_vertices(r, *keys.vertices);
    if (!cloud) return nullptr;
    try {
        const shapes::ConvexPolyhedron hull =
            shapes::scaled_hull(shapes::convex_hull(*cloud), scaling, "vertices");
        return std::make_shared<const shapes::CustomShape>(
            shapes::CustomShape{name.value_or("vertices"), hull});
    } catch (const shapes::GeometryError& error) {
        return report(keys.vertices, "vertices", error);
    }
}

}  // namespace

fs::path resolve_path(const toml::node& node, const std::string& path, Context& context) {
    const fs::path folder = fs::path(node_location(node, context.file).file).parent_path();
    return (folder / path).lexically_normal();
}

std::optional<std::vector<shapes::Vec3>> read_vertices(TableReader& r, const toml::node& node) {
    const auto* array = node.as_array();
    std::vector<shapes::Vec3> out;
    for (std::size_t i = 0; array != nullptr && i < array->size(); ++i) {
        const auto* point = array->get(i)->as_array();
        shapes::Vec3 p;
        for (std::size_t k = 0; point != nullptr && point->size() == 3 && k < 3; ++k) {
            const std::optional<double> value = number_of(*point->get(k));
            p[static_cast<Eigen::Index>(k)] = value.value_or(std::nan(""));
        }
        if (point == nullptr || point->size() != 3 || !p.allFinite()) {
            r.context().report(
                *array->get(i), r.path("vertices") + "[" + std::to_string(i) + "]",
                describe(*array->get(i)) + ": must be a point [x, y, z] of 3 finite numbers (m)");
            return std::nullopt;
        }
        out.push_back(p);
    }
    if (array == nullptr) {
        r.context().report(node, r.path("vertices"),
                           describe(node) + ": must be an array of points [x, y, z] (m)");
        return std::nullopt;
    }
    return out;
}

std::shared_ptr<const shapes::CustomShape> RockShapeCache::find(const std::string& key) const {
    const auto found = shapes_.find(key);
    return found == shapes_.end() ? nullptr : found->second;
}

std::shared_ptr<const shapes::CustomShape> RockShapeCache::add(const std::string& key,
                                                               shapes::CustomShape shape) {
    auto stored = std::make_shared<const shapes::CustomShape>(std::move(shape));
    shapes_.insert_or_assign(key, stored);
    return stored;
}

const shapes::ShapeCatalogue& RockShapeCache::catalogue(const fs::path& source) {
    const auto found = catalogues_.find(source.string());
    if (found != catalogues_.end()) return found->second;
    return catalogues_.emplace(source.string(), shapes::read_catalogue(source)).first->second;
}

void read_rock_shape(TableReader& r, engine::RockSpec& rock, RockShapeCache& cache) {
    ShapeKeys keys;
    keys.mesh = r.get("mesh");
    keys.mesh_scale = r.get("mesh_scale");
    keys.catalogue = r.get("catalogue");
    keys.entry = r.get("entry");
    keys.vertices = r.get("vertices");
    keys.shape_name = r.get("shape_name");
    keys.long_axis = r.get("long_axis");
    Context& context = r.context();

    const std::vector<std::pair<std::string_view, const toml::node*>> sources = {
        {"mesh", keys.mesh}, {"catalogue", keys.catalogue}, {"vertices", keys.vertices}};
    std::vector<std::string_view> given;
    for (const auto& [key, node] : sources) {
        if (node != nullptr) given.push_back(key);
    }
    if (given.empty()) {
        const std::pair<std::string_view, const toml::node*> options[] = {
            {"mesh_scale", keys.mesh_scale},
            {"entry", keys.entry},
            {"shape_name", keys.shape_name},
            {"long_axis", keys.long_axis}};
        for (const auto& [key, node] : options) {
            if (node != nullptr) {
                context.report(
                    *node, r.path(key),
                    describe(*node) + ": applies only to a rock with mesh, catalogue or vertices");
            }
        }
        return;
    }
    const toml::node* first = keys.mesh        ? keys.mesh
                              : keys.catalogue ? keys.catalogue
                                               : keys.vertices;
    if (given.size() > 1) {
        context.report(*first, r.path(given.front()),
                       describe(*first) +
                           ": give one shape source (mesh, catalogue with entry, "
                           "or vertices), not both " +
                           std::string(given[0]) + " and " + std::string(given[1]));
        return;
    }
    bool ok = true;
    if (r.contains("kind")) {
        const Location where = context.sources.find(r.path("kind"));
        context.problems.push_back(
            {where.file, where.line, r.path("kind"),
             "a rock with " + std::string(given.front()) +
                 " is of kind custom; leave kind out (it applies to the sphere, massive and "
                 "planar families)"});
        ok = false;
    }
    if (keys.mesh_scale != nullptr && keys.mesh == nullptr) {
        context.report(*keys.mesh_scale, r.path("mesh_scale"),
                       describe(*keys.mesh_scale) +
                           ": applies only to mesh (a catalogue entry has its own scale)");
        ok = false;
    }
    if (keys.entry != nullptr && keys.catalogue == nullptr) {
        context.report(*keys.entry, r.path("entry"),
                       describe(*keys.entry) + ": applies only together with catalogue");
        ok = false;
    }
    shapes::MeshScaling scaling;
    if (keys.mesh_scale != nullptr) {
        const std::optional<double> scale = positive_number(r, keys.mesh_scale, "mesh_scale", "");
        ok &= scale.has_value();
        scaling.scale = scale.value_or(1.0);
    }
    const bool size_given = r.contains("size");
    if (size_given) {
        // An invalid size is reported by the range checks; the shape waits for a valid one.
        ok &= size_range().contains(rock.size);
        scaling.size = rock.size;
    }
    if (keys.long_axis != nullptr) {
        const std::optional<double> axis = positive_number(r, keys.long_axis, "long_axis", "m");
        ok &= axis.has_value();
        if (axis && size_given) {
            context.report(*keys.long_axis, r.path("long_axis"),
                           describe(*keys.long_axis) + " m: give size or long_axis, not both");
            ok = false;
        }
        scaling.long_axis = axis.value_or(0.0);
    }
    std::optional<std::string> name;
    if (keys.shape_name != nullptr) {
        name = text(r, keys.shape_name, "shape_name");
        ok &= name.has_value();
    }
    if (!ok) return;

    const std::shared_ptr<const shapes::CustomShape> shape = load(r, keys, scaling, name, cache);
    if (!shape) return;
    rock.kind = shapes::RockKind::custom;
    rock.shape = shape;
    if (size_given) return;
    const double size = shapes::equivalent_diameter(shapes::mass_properties(shape->hull).volume);
    if (!size_range().contains(size)) {
        context.report(*first, r.path(given.front()),
                       describe(*first) + ": gives a rock of volume-equivalent diameter " +
                           format_number(size) + " m, outside the scenario's " +
                           size_range().describe() + " m; give size or long_axis" +
                           (keys.mesh != nullptr ? " (or mesh_scale)" : ""));
        return;
    }
    rock.size = size;
}

}  // namespace rockfall::scenario::detail
