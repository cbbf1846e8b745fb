// `rockfall shape (FILE | --kind K | --generate G)`: the shape measures of one rock (or of
// every entry of a catalogue), and its hull as OBJ or STL.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/shape_report.hpp"
#include "scenario/shape_source.hpp"

#include "shapes/measures.hpp"
#include "shapes/mesh_io.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

// The command line of `rockfall shape`: what to describe, and where the output goes.
struct ShapeArgs {
    scenario::ShapeRequest request;
    bool json = false;
    std::optional<std::string> obj;
    std::optional<std::string> stl;
};

report::ShapeView view(const scenario::ShapeResult& shape) {
    return {shape.label, shape.source, &shape.rock, shape.stretch};
}

// The simulated hull as OBJ or STL (committed only when complete).
void write_meshes(const ShapeArgs& args, const scenario::ShapeResult& shape) {
    if (args.obj) {
        OutputFile file(*args.obj);
        shapes::write_obj(file.stream(), shape.rock.hull, report::shape_mesh_header(view(shape)));
        file.commit();
    }
    if (args.stl) {
        OutputFile file(*args.stl);
        shapes::write_stl(file.stream(), shape.rock.hull, shape.label);
        file.commit();
    }
}

void print_catalogue(const ShapeArgs& args) {
    if (args.obj || args.stl) {
        throw std::invalid_argument("--obj and --stl write one rock: give --entry NAME");
    }
    const std::vector<scenario::ShapeResult> shapes = scenario::catalogue_shapes(args.request);
    nlohmann::json entries = nlohmann::json::array();
    if (!args.json) report::print_catalogue_header(std::cout, *args.request.file);
    for (const scenario::ShapeResult& shape : shapes) {
        const shapes::ShapeMeasures m = shapes::shape_measures(shape.rock);
        if (args.json) {
            entries.push_back(report::shape_json(view(shape), m));
        } else {
            report::print_catalogue_row(std::cout, view(shape), m);
        }
    }
    if (args.json) {
        std::cout << nlohmann::json{{"catalogue", *args.request.file}, {"entries", entries}}.dump(2)
                  << '\n';
    }
}

void run(const ShapeArgs& args) {
    const scenario::ShapeRequest& request = args.request;
    if (request.file && scenario::is_catalogue(*request.file) && !request.entry && !request.kind &&
        !request.generate) {
        print_catalogue(args);
        return;
    }
    const scenario::ShapeResult shape = scenario::make_shape(request);
    const shapes::ShapeMeasures m = shapes::shape_measures(shape.rock);
    write_meshes(args, shape);
    if (args.json) {
        std::cout << report::shape_json(view(shape), m).dump(2) << '\n';
        return;
    }
    report::print_shape_text(std::cout, view(shape), m);
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
    for (const std::string& name : scenario::shape_kind_names())
        kinds += (kinds.empty() ? "" : ", ") + name;
    cmd->add_option("FILE", args->request.file,
                    "Mesh file (.obj, .stl, .ply, .off, .gltf, .glb, ...; coordinates in m), or "
                    "a catalogue (folder of meshes or .toml list)");
    cmd->add_option("--kind", args->request.kind, "Shape: " + kinds)
        ->check(CLI::IsMember(scenario::shape_kind_names()));
    cmd->add_option("--generate", args->request.generate,
                    "Random rock from --seed: ellipsoid (--ratios) or sphericity (--sphericity)")
        ->check(CLI::IsMember(scenario::generator_names()));
    cmd->add_option("--entry", args->request.entry,
                    "Catalogue entry (without it: list every entry)");
    cmd->add_option("--size", args->request.size,
                    "Volume-equivalent diameter (m); default 0.2, a mesh keeps its own");
    cmd->add_option("--long-axis", args->request.long_axis,
                    "Scale to this long axis a (m) instead");
    cmd->add_option("--scale", args->request.scale,
                    "Factor from the mesh file's units to m (mm: 0.001)");
    cmd->add_option("--seed", args->request.seed, "Seed of a generated rock, default 1");
    cmd->add_option("--ratios", args->request.ratios, "Axis ratios a b c of --generate ellipsoid")
        ->expected(3);
    cmd->add_option("--sphericity", args->request.sphericity,
                    "Target Wadell sphericity of --generate sphericity");
    cmd->add_option("--points", args->request.points,
                    "Points of a generated rock's cloud, default 80");
    cmd->add_option("--roughness", args->request.roughness,
                    "Radial scatter of a generated rock's points, default 0.1");
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--obj", args->obj, "Write the hull to this OBJ file (body frame, m)");
    cmd->add_option("--stl", args->stl, "Write the hull to this ASCII STL file (body frame, m)");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
