#include "scenario/shape_source.hpp"

#include "shapes/generators.hpp"
#include "shapes/mass_properties.hpp"
#include "shapes/measures.hpp"
#include "shapes/mesh_io.hpp"
#include "shapes/platonic.hpp"

#include <filesystem>
#include <map>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace rockfall::scenario {
namespace {

namespace fs = std::filesystem;

// Size of a shape that has none of its own when neither --size nor --long-axis is given, m.
constexpr double kDefaultSize = 0.2;
constexpr std::uint64_t kDefaultSeed = 1;

using ShapeKind = std::variant<shapes::RockKind, shapes::PlatonicKind>;

const std::map<std::string, ShapeKind>& shape_kinds() {
    static const std::map<std::string, ShapeKind> kinds = {
        {"sphere", shapes::RockKind::sphere},
        {"massive", shapes::RockKind::massive},
        {"planar", shapes::RockKind::planar},
        {"tetrahedron", shapes::PlatonicKind::tetrahedron},
        {"cube", shapes::PlatonicKind::cube},
        {"octahedron", shapes::PlatonicKind::octahedron},
        {"dodecahedron", shapes::PlatonicKind::dodecahedron},
        {"icosahedron", shapes::PlatonicKind::icosahedron}};
    return kinds;
}

void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument(message);
}

std::string number(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

void check_args(const ShapeRequest& a) {
    const int sources =
        int(a.file.has_value()) + int(a.kind.has_value()) + int(a.generate.has_value());
    require(sources == 1, "give exactly one of FILE, --kind or --generate");
    const bool catalogue = a.file && is_catalogue(*a.file);
    require(!a.entry || catalogue, "--entry applies only to a catalogue (a folder or .toml file)");
    require(!a.scale || (a.file && !catalogue), "--scale applies only to a mesh FILE");
    require(!(a.size && a.long_axis), "give --size or --long-axis, not both");
    if (a.size) {
        require(
            *a.size >= shapes::min_nominal_size && *a.size <= shapes::max_nominal_size,
            "--size = " + number(*a.size) + " m: the volume-equivalent diameter must be within [" +
                number(shapes::min_nominal_size) + ", " + number(shapes::max_nominal_size) + "] m");
    }
    if (a.long_axis) {
        require(std::isfinite(*a.long_axis) && *a.long_axis > 0.0,
                "--long-axis = " + number(*a.long_axis) + " m: must be finite and > 0");
    }
    if (a.scale) {
        require(std::isfinite(*a.scale) && *a.scale > 0.0,
                "--scale = " + number(*a.scale) + ": must be finite and > 0");
    }
    const std::string generator = a.generate.value_or("");
    require(a.ratios.empty() || generator == "ellipsoid",
            "--ratios applies only to --generate ellipsoid");
    require(!a.sphericity || generator == "sphericity",
            "--sphericity applies only to --generate sphericity");
    require(generator != "sphericity" || a.sphericity.has_value(),
            "--generate sphericity needs --sphericity S (the target Wadell sphericity)");
    require(!(a.seed || a.points || a.roughness) || !generator.empty(),
            "--seed, --points and --roughness apply only to --generate");
}

shapes::MeshScaling scaling_of(const ShapeRequest& a, bool has_own_size) {
    shapes::MeshScaling scaling;
    scaling.scale = a.scale.value_or(1.0);
    scaling.size = a.size.value_or(0.0);
    scaling.long_axis = a.long_axis.value_or(0.0);
    if (!has_own_size && !a.size && !a.long_axis) scaling.size = kDefaultSize;
    return scaling;
}

ShapeResult custom_rock(std::string label, std::string source, shapes::ConvexPolyhedron hull) {
    shapes::CustomShape shape{label, std::move(hull)};
    const double size = shapes::equivalent_diameter(shapes::mass_properties(shape.hull).volume);
    return {std::move(label), std::move(source), shapes::make_rock(shape, size), std::nullopt};
}

ShapeResult entry_rock(const shapes::CatalogueEntry& catalogue_entry, const ShapeRequest& a,
                       const std::string& catalogue) {
    shapes::CatalogueEntry entry = catalogue_entry;
    if (a.size || a.long_axis) {
        entry.scaling.size = a.size.value_or(0.0);
        entry.scaling.long_axis = a.long_axis.value_or(0.0);
    }
    shapes::CustomShape shape = shapes::load_entry(entry);
    return custom_rock(
        entry.name,
        "catalogue " + catalogue + ", entry '" + entry.name + "' (" + entry.file.string() + ")",
        std::move(shape.hull));
}

shapes::RandomRockOptions random_options(const ShapeRequest& a) {
    shapes::RandomRockOptions options;
    options.points = a.points.value_or(options.points);
    options.roughness = a.roughness.value_or(options.roughness);
    return options;
}

ShapeResult generated_rock(const ShapeRequest& a) {
    const shapes::RandomRockOptions options = random_options(a);
    const std::uint64_t seed = a.seed.value_or(kDefaultSeed);
    const std::string cloud = "seed " + std::to_string(seed) + ", " +
                              std::to_string(options.points) + " points, roughness " +
                              number(options.roughness);
    if (*a.generate == "ellipsoid") {
        require(a.ratios.empty() || a.ratios.size() == 3, "--ratios needs three numbers a b c");
        const shapes::Vec3 ratios = a.ratios.empty()
                                        ? shapes::Vec3(1.0, 0.7, 0.5)
                                        : shapes::Vec3(a.ratios[0], a.ratios[1], a.ratios[2]);
        const shapes::ConvexPolyhedron hull = shapes::ellipsoid_rock(ratios, seed, options);
        return custom_rock("ellipsoid rock",
                           "ellipsoid generator, axes " + number(ratios[0]) + " : " +
                               number(ratios[1]) + " : " + number(ratios[2]) + ", " + cloud,
                           shapes::scaled_hull(hull, scaling_of(a, false), "generated rock"));
    }
    const shapes::SphericityRock rock = shapes::rock_with_sphericity(*a.sphericity, seed, options);
    ShapeResult result = custom_rock(
        "sphericity rock", "sphericity generator, target " + number(*a.sphericity) + ", " + cloud,
        shapes::scaled_hull(rock.hull, scaling_of(a, false), "generated rock"));
    result.stretch = rock.stretch;
    return result;
}

ShapeResult kind_rock(const ShapeRequest& a) {
    const auto found = shape_kinds().find(*a.kind);
    require(found != shape_kinds().end(), "--kind " + *a.kind + ": unknown kind");
    if (const auto* platonic = std::get_if<shapes::PlatonicKind>(&found->second)) {
        const shapes::ConvexPolyhedron hull = shapes::platonic_solid(*platonic, 1.0);
        return custom_rock(*a.kind, "Platonic solid",
                           shapes::scaled_hull(hull, scaling_of(a, false), *a.kind));
    }
    const shapes::RockKind kind = std::get<shapes::RockKind>(found->second);
    double size = a.size.value_or(kDefaultSize);
    if (a.long_axis) {
        // Every family scales uniformly: the long axis is proportional to the size.
        const shapes::RockGeometry unit = shapes::make_rock(kind, 1.0);
        size = *a.long_axis / shapes::shape_measures(unit).axis_lengths[0];
    }
    return {*a.kind, "rock family", shapes::make_rock(kind, size), std::nullopt};
}

}  // namespace

std::vector<std::string> shape_kind_names() {
    std::vector<std::string> names;
    for (const auto& [name, kind] : shape_kinds()) names.push_back(name);
    return names;
}

std::vector<std::string> generator_names() { return {"ellipsoid", "sphericity"}; }

bool is_catalogue(const std::string& file) {
    std::error_code error;
    return fs::is_directory(file, error) || fs::path(file).extension() == ".toml";
}

ShapeResult make_shape(const ShapeRequest& a) {
    check_args(a);
    if (a.kind) return kind_rock(a);
    if (a.generate) return generated_rock(a);
    if (is_catalogue(*a.file)) {
        require(a.entry.has_value(), "a catalogue needs --entry NAME to describe one rock");
        const shapes::ShapeCatalogue catalogue = shapes::read_catalogue(*a.file);
        return entry_rock(shapes::find_entry(catalogue, *a.entry), a, *a.file);
    }
    return custom_rock(fs::path(*a.file).stem().string(), "mesh " + *a.file,
                       shapes::read_mesh_hull(*a.file, scaling_of(a, true)));
}

std::vector<ShapeResult> catalogue_shapes(const ShapeRequest& a) {
    check_args(a);
    const shapes::ShapeCatalogue catalogue = shapes::read_catalogue(*a.file);
    std::vector<ShapeResult> results;
    for (const shapes::CatalogueEntry& entry : catalogue.entries) {
        results.push_back(entry_rock(entry, a, *a.file));
    }
    return results;
}

}  // namespace rockfall::scenario
