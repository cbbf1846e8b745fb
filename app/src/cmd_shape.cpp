// `rockfall shape (FILE | --kind K | --generate G)`: the shape measures of one rock (or of
// every entry of a catalogue), and its hull as OBJ or STL.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "shape_source.hpp"
#include "text_format.hpp"

#include "shapes/measures.hpp"
#include "shapes/mesh_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

// Density for the moments in kg m2: a common granite value; per unit density is printed too.
constexpr double kReportDensity = 2600.0;

std::string fmt(double value) { return app::fmt("%.6g", value); }

std::string triple(const shapes::Vec3& v) { return fmt(v[0]) + " " + fmt(v[1]) + " " + fmt(v[2]); }

void print_text(const ShapeResult& shape, const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    const shapes::RockGeometry& rock = shape.rock;
    std::cout << "shape: " << shape.label << " (" << shape.source << ")\n"
              << "kind: " << shapes::to_string(rock.kind) << '\n'
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
              << "Krumbein sphericity: " << fmt(m.krumbein_sphericity) << '\n';
    if (shape.stretch) std::cout << "stretch t (axes 1 : t : t^2): " << fmt(*shape.stretch) << '\n';
    std::cout << "hull: " << rock.hull.vertices.size() << " vertices, "
              << rock.hull.triangles.size() << " triangles"
              << (rock.radius > 0.0 ? " (display only: simulated as an exact sphere)" : "") << '\n';
}

nlohmann::json to_json(const ShapeResult& shape, const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    const shapes::RockGeometry& rock = shape.rock;
    const auto array = [](const shapes::Vec3& v) { return nlohmann::json{v[0], v[1], v[2]}; };
    nlohmann::json out = {{"name", shape.label},
                          {"source", shape.source},
                          {"kind", shapes::to_string(rock.kind)},
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
    if (shape.stretch) out["stretch"] = *shape.stretch;
    return out;
}

std::string header(const ShapeResult& shape) {
    std::string text = "rockfall shape: " + shape.label + " (" + shape.source +
                       ")\nthe simulated hull in the body frame (m; centroid at the origin, "
                       "principal axes along x, y, z, long axis x)";
    if (shape.rock.radius > 0.0) {
        text += "\ndisplay tessellation: the engine simulates an exact sphere of radius " +
                fmt(shape.rock.radius) + " m";
    }
    return text;
}

// The simulated hull as OBJ or STL (committed only when complete).
void write_meshes(const ShapeArgs& args, const ShapeResult& shape) {
    if (args.obj) {
        AtomicFile file(*args.obj);
        shapes::write_obj(file.stream(), shape.rock.hull, header(shape));
        file.commit();
    }
    if (args.stl) {
        AtomicFile file(*args.stl);
        shapes::write_stl(file.stream(), shape.rock.hull, shape.label);
        file.commit();
    }
}

void print_catalogue(const ShapeArgs& args) {
    if (args.obj || args.stl) {
        throw std::invalid_argument("--obj and --stl write one rock: give --entry NAME");
    }
    const std::vector<ShapeResult> shapes = catalogue_shapes(args);
    nlohmann::json entries = nlohmann::json::array();
    if (!args.json) {
        std::cout << "catalogue " << *args.file << "\n"
                  << "name                 D (m)      Wadell  Krumbein  a b c (m)\n";
    }
    for (const ShapeResult& shape : shapes) {
        const shapes::ShapeMeasures m = shapes::shape_measures(shape.rock);
        if (args.json) {
            entries.push_back(to_json(shape, m));
            continue;
        }
        std::string name = shape.label;
        name.resize(std::max<std::size_t>(name.size(), 20), ' ');
        std::cout << name << ' ' << app::fmt("%-10.4g", m.equivalent_diameter) << ' '
                  << app::fmt("%-7.3f", m.wadell_sphericity) << ' '
                  << app::fmt("%-9.3f", m.krumbein_sphericity) << ' ' << triple(m.axis_lengths)
                  << '\n';
    }
    if (args.json) {
        std::cout << nlohmann::json{{"catalogue", *args.file}, {"entries", entries}}.dump(2)
                  << '\n';
    }
}

void run(const ShapeArgs& args) {
    if (args.file && is_catalogue(*args.file) && !args.entry && !args.kind && !args.generate) {
        print_catalogue(args);
        return;
    }
    const ShapeResult shape = make_shape(args);
    const shapes::ShapeMeasures m = shapes::shape_measures(shape.rock);
    write_meshes(args, shape);
    if (args.json) {
        std::cout << to_json(shape, m).dump(2) << '\n';
        return;
    }
    print_text(shape, m);
    if (args.obj) std::cout << "hull written to " << *args.obj << '\n';
    if (args.stl) std::cout << "hull written to " << *args.stl << '\n';
}

}  // namespace

void register_shape(CLI::App& app) {
    auto args = std::make_shared<ShapeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "shape",
        "Shape measures of a rock (volume, inertia, axes, sphericities) from a mesh file, a "
        "catalogue, a kind or a generator; --obj / --stl write its hull as the engine "
        "simulates it");
    std::string kinds;
    for (const std::string& name : shape_kind_names()) kinds += (kinds.empty() ? "" : ", ") + name;
    cmd->add_option("FILE", args->file,
                    "Mesh file (.obj, .stl, .ply, .off, .gltf, .glb, ...; coordinates in m), or "
                    "a catalogue (folder of meshes or .toml list)");
    cmd->add_option("--kind", args->kind, "Shape: " + kinds)
        ->check(CLI::IsMember(shape_kind_names()));
    cmd->add_option("--generate", args->generate,
                    "Random rock from --seed: ellipsoid (--ratios) or sphericity (--sphericity)")
        ->check(CLI::IsMember(generator_names()));
    cmd->add_option("--entry", args->entry, "Catalogue entry (without it: list every entry)");
    cmd->add_option("--size", args->size,
                    "Volume-equivalent diameter (m); default 0.2, a mesh keeps its own");
    cmd->add_option("--long-axis", args->long_axis, "Scale to this long axis a (m) instead");
    cmd->add_option("--scale", args->scale, "Factor from the mesh file's units to m (mm: 0.001)");
    cmd->add_option("--seed", args->seed, "Seed of a generated rock, default 1");
    cmd->add_option("--ratios", args->ratios, "Axis ratios a b c of --generate ellipsoid")
        ->expected(3);
    cmd->add_option("--sphericity", args->sphericity,
                    "Target Wadell sphericity of --generate sphericity");
    cmd->add_option("--points", args->points, "Points of a generated rock's cloud, default 80");
    cmd->add_option("--roughness", args->roughness,
                    "Radial scatter of a generated rock's points, default 0.1");
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--obj", args->obj, "Write the hull to this OBJ file (body frame, m)");
    cmd->add_option("--stl", args->stl, "Write the hull to this ASCII STL file (body frame, m)");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
