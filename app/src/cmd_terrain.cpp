// `rockfall terrain SCENARIO`: the scenario's terrain mesh (size, extent, how far it departs
// from the reference profile) and, with --obj, the mesh as the engine simulates it; for a
// scenario without one, its reference profile triangulated (optionally roughened) as a mesh.

#include "commands.hpp"
#include "output_file.hpp"
#include "report/terrain_report.hpp"
#include "scenario/scenario_file.hpp"

#include "shapes/mesh_io.hpp"
#include "shapes/slope.hpp"
#include "shapes/terrain.hpp"

#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

namespace rockfall::app {
namespace {

struct TerrainArgs {
    std::string scenario;
    std::optional<std::string> obj;
    bool json = false;
    // Triangulation of a scenario without a terrain (shapes::TerrainGrid).
    std::optional<double> spacing;
    std::optional<double> margin;
    std::optional<double> roughness;
    std::optional<double> wavelength;
    std::optional<std::uint64_t> seed;
};

bool generation_options(const TerrainArgs& args) {
    return args.spacing || args.margin || args.roughness || args.wavelength || args.seed;
}

void run(const TerrainArgs& args) {
    const scenario::ScenarioFile file = scenario::load_scenario(args.scenario);
    const std::shared_ptr<const shapes::Terrain>& terrain = file.scenario.slope.terrain;
    if (terrain && generation_options(args)) {
        throw std::invalid_argument(
            "--spacing, --margin, --roughness, --wavelength and --seed triangulate a profile; " +
            args.scenario + " already has a terrain mesh");
    }
    shapes::TriangleMesh generated;
    std::string comment;
    const std::string file_name = file.path.filename().string();
    if (!terrain) {
        shapes::TerrainGrid grid;
        grid.spacing = args.spacing.value_or(grid.spacing);
        grid.margin = args.margin.value_or(grid.margin);
        grid.roughness = args.roughness.value_or(grid.roughness);
        grid.wavelength = args.wavelength.value_or(grid.wavelength);
        grid.seed = args.seed.value_or(grid.seed);
        generated = shapes::profile_terrain(file.scenario.slope, grid);
        comment = report::profile_mesh_comment(file_name, grid);
    } else {
        comment = report::terrain_mesh_comment(file_name, *terrain);
    }
    const shapes::TriangleMesh& mesh = terrain ? terrain->mesh() : generated;
    if (args.obj) {
        OutputFile out(*args.obj);
        shapes::write_obj(out.stream(), mesh, comment);
        out.commit();
    }
    const std::string path = file.path.string();
    if (terrain) {
        const shapes::ProfileDeviation deviation =
            shapes::profile_deviation(*terrain, shapes::Slope(file.scenario.slope));
        if (args.json) {
            std::cout << report::terrain_json(path, *terrain, deviation).dump(2) << '\n';
        } else {
            report::print_terrain_text(std::cout, path, *terrain, deviation);
        }
    } else if (args.json) {
        std::cout << report::profile_mesh_json(path, mesh).dump(2) << '\n';
    } else {
        report::print_profile_mesh_text(std::cout, path, mesh);
    }
    if (args.obj && !args.json) std::cout << "mesh written to " << *args.obj << '\n';
}

}  // namespace

void register_terrain(CLI::App& app) {
    auto args = std::make_shared<TerrainArgs>();
    CLI::App* cmd = app.add_subcommand(
        "terrain",
        "A scenario's terrain mesh: size, extent and height above the reference profile; --obj "
        "writes it as the engine simulates it, or, for a scenario without one, its profile "
        "triangulated (optionally with a random relief)");
    cmd->add_option("SCENARIO", args->scenario, "Scenario file (.toml)")->required();
    cmd->add_option("--obj", args->obj, "Write the mesh to this OBJ file (slope frame, m)");
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--spacing", args->spacing, "Grid spacing on the surface (m), default 0.25");
    cmd->add_option("--margin", args->margin,
                    "How far the mesh reaches past the crown, end and sides (m), default 0.5");
    cmd->add_option("--roughness", args->roughness,
                    "Root-mean-square height of a smooth random relief (m), default 0");
    cmd->add_option("--wavelength", args->wavelength,
                    "Shortest wavelength of the relief (m, >= 2 spacings), default 1; the longest "
                    "is 8 times it");
    cmd->add_option("--seed", args->seed, "Seed of the relief, default 1");
    cmd->callback([args] { run(*args); });
}

}  // namespace rockfall::app
