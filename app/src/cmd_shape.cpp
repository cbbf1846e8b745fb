// `rockfall shape --kind K`: the shape measures of one rock, and its hull as an OBJ file.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "text_format.hpp"

#include "shapes/measures.hpp"
#include "shapes/platonic.hpp"
#include "shapes/rocks.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace rockfall::app {
namespace {

// Density for the moments in kg m2: a common granite value; per unit density is printed too.
constexpr double kReportDensity = 2600.0;

struct ShapeArgs {
    std::string kind;
    double size = 0.2;
    bool json = false;
    std::optional<std::string> obj;
};

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

// The rock as the engine would simulate it: body frame, scaled to the volume-equivalent size.
// A Platonic solid goes through rock_from_hull like any hull (family label: massive).
shapes::RockGeometry make_shape(const ShapeArgs& args) {
    if (!(args.size > 0.0)) {
        std::ostringstream message;
        message << "--size = " << args.size
                << " m: the volume-equivalent diameter must be > 0 (and within [0.001, 100] m)";
        throw std::invalid_argument(message.str());
    }
    const ShapeKind kind = shape_kinds().at(args.kind);
    if (const auto* rock = std::get_if<shapes::RockKind>(&kind)) {
        return shapes::make_rock(*rock, args.size);
    }
    return shapes::rock_from_hull(shapes::platonic_solid(std::get<shapes::PlatonicKind>(kind), 1.0),
                                  shapes::RockKind::massive, args.size);
}

std::string fmt(double value) { return app::fmt("%.6g", value); }

std::string triple(const shapes::Vec3& v) { return fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]); }

void print_text(const ShapeArgs& args, const shapes::RockGeometry& rock,
                const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    std::cout << "kind: " << args.kind << '\n'
              << "volume-equivalent diameter: " << fmt(m.equivalent_diameter) << " m\n"
              << "volume: " << fmt(p.volume) << " m3\n"
              << "surface area: " << fmt(p.surface_area) << " m2\n"
              << "centre of mass (body frame): " << triple(p.centroid) << " m\n"
              << "principal moments per unit density: " << triple(p.principal_moments) << " m5\n"
              << "principal moments at density " << fmt(kReportDensity)
              << " kg/m3: " << triple(kReportDensity * p.principal_moments) << " kg m2\n"
              << "mass at density " << fmt(kReportDensity)
              << " kg/m3: " << fmt(kReportDensity * p.volume) << " kg\n"
              << "axis lengths a b c: " << triple(m.axis_lengths) << " m\n"
              << "elongation b/a: " << fmt(m.elongation) << '\n'
              << "flatness c/b: " << fmt(m.flatness) << '\n'
              << "Wadell sphericity: " << fmt(m.wadell_sphericity) << '\n'
              << "Krumbein sphericity: " << fmt(m.krumbein_sphericity) << '\n'
              << "hull: " << rock.hull.vertices.size() << " vertices, "
              << rock.hull.triangles.size() << " triangles"
              << (rock.radius > 0.0 ? " (display only: simulated as an exact sphere)" : "") << '\n';
}

nlohmann::json to_json(const ShapeArgs& args, const shapes::RockGeometry& rock,
                       const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    const auto array = [](const shapes::Vec3& v) { return nlohmann::json{v[0], v[1], v[2]}; };
    return {{"kind", args.kind},
            {"equivalent_diameter_m", m.equivalent_diameter},
            {"volume_m3", p.volume},
            {"surface_area_m2", p.surface_area},
            {"centroid_m", array(p.centroid)},
            {"principal_moments_per_density_m5", array(p.principal_moments)},
            {"density_kg_m3", kReportDensity},
            {"principal_moments_kg_m2", array(kReportDensity * p.principal_moments)},
            {"mass_kg", kReportDensity * p.volume},
            {"axis_lengths_m", array(m.axis_lengths)},
            {"elongation", m.elongation},
            {"flatness", m.flatness},
            {"wadell_sphericity", m.wadell_sphericity},
            {"krumbein_sphericity", m.krumbein_sphericity},
            {"hull_vertices", rock.hull.vertices.size()},
            {"hull_triangles", rock.hull.triangles.size()},
            {"exact_sphere", rock.radius > 0.0}};
}

// The simulated hull as OBJ (committed only when complete).
void write_obj(const std::string& path, const ShapeArgs& args, const shapes::RockGeometry& rock) {
    AtomicFile file(path);
    std::ofstream& out = file.stream();
    out << "# rockfall shape --kind " << args.kind << " --size " << args.size
        << ": the simulated hull in the body frame (m; centroid at the origin, principal "
           "axes along x, y, z)\n";
    if (rock.radius > 0.0) {
        out << "# display tessellation: the engine simulates an exact sphere of radius "
            << rock.radius << " m\n";
    }
    char line[96];
    for (const shapes::Vec3& v : rock.hull.vertices) {
        std::snprintf(line, sizeof line, "v %.17g %.17g %.17g\n", v[0], v[1], v[2]);
        out << line;
    }
    for (const auto& [a, b, c] : rock.hull.triangles) {
        out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
    }
    file.commit();
}

}  // namespace

void register_shape(CLI::App& app) {
    auto args = std::make_shared<ShapeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "shape",
        "Shape measures of a rock (volume, inertia, axes, sphericities); --obj writes "
        "its hull as the engine simulates it");
    std::vector<std::string> names;
    std::string kinds;
    for (const auto& [name, kind] : shape_kinds()) {
        kinds += (kinds.empty() ? "" : ", ") + name;
        names.push_back(name);
    }
    cmd->add_option("--kind", args->kind, "Shape: " + kinds)
        ->required()
        ->check(CLI::IsMember(names));
    cmd->add_option("--size", args->size, "Volume-equivalent diameter (m), default 0.2");
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--obj", args->obj, "Write the hull to this OBJ file (body frame, m)");
    cmd->callback([args] {
        const shapes::RockGeometry rock = make_shape(*args);
        const shapes::ShapeMeasures m = shapes::shape_measures(rock);
        if (args->obj) {
            write_obj(*args->obj, *args, rock);
        }
        if (args->json) {
            std::cout << to_json(*args, rock, m).dump(2) << '\n';
        } else {
            print_text(*args, rock, m);
            if (args->obj) {
                std::cout << "hull written to " << *args->obj << '\n';
            }
        }
    });
}

}  // namespace rockfall::app
