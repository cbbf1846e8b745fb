// `rockfall terrain SCENARIO`: the scenario's terrain mesh (size, extent, how far it departs
// from the reference profile) and, with --obj, the mesh as the engine simulates it; for a
// scenario without one, its reference profile triangulated (optionally roughened) as a mesh.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "report/text_format.hpp"
#include "scenario/scenario_file.hpp"

#include "shapes/mesh_io.hpp"
#include "shapes/slope.hpp"
#include "shapes/terrain.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
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

// Heights of the mesh's vertices above the reference profile, inside the slope's footprint.
struct Deviation {
    double max = 0.0;
    double rms = 0.0;
    std::size_t vertices = 0;
};

Deviation deviation(const shapes::Terrain& terrain, const shapes::Slope& slope) {
    Deviation out;
    double squares = 0.0;
    const double half = 0.5 * slope.spec().width;
    for (const shapes::Vec3& v : terrain.mesh().vertices) {
        if (v.x() < 0.0 || v.x() > slope.end_x() || std::abs(v.y()) > half) continue;
        const double dz = v.z() - slope.surface_height(v.x());
        out.max = std::max(out.max, std::abs(dz));
        squares += dz * dz;
        ++out.vertices;
    }
    if (out.vertices > 0) out.rms = std::sqrt(squares / static_cast<double>(out.vertices));
    return out;
}

void describe(const scenario::ScenarioFile& file, const shapes::Terrain& terrain, bool json) {
    const shapes::Slope slope(file.scenario.slope);
    const Deviation d = deviation(terrain, slope);
    const auto array = [](const shapes::Vec3& v) { return nlohmann::json{v[0], v[1], v[2]}; };
    if (json) {
        std::cout << nlohmann::json{{"scenario", file.path.string()},
                                    {"name", terrain.name()},
                                    {"vertices", terrain.mesh().vertices.size()},
                                    {"triangles", terrain.mesh().triangles.size()},
                                    {"dropped_triangles", terrain.dropped_triangles()},
                                    {"lower_m", array(terrain.lower())},
                                    {"upper_m", array(terrain.upper())},
                                    {"profile_deviation_max_m", d.max},
                                    {"profile_deviation_rms_m", d.rms}}
                         .dump(2)
                  << '\n';
        return;
    }
    std::cout << "terrain: " << terrain.name() << " (" << file.path.string() << ")\n"
              << "mesh: " << terrain.mesh().vertices.size() << " vertices, "
              << terrain.mesh().triangles.size() << " triangles";
    if (terrain.dropped_triangles() > 0) {
        std::cout << " (" << terrain.dropped_triangles() << " degenerate triangles dropped)";
    }
    std::cout << "\nbounding box: " << report::triple(terrain.lower()) << " to "
              << report::triple(terrain.upper()) << " m\nheight above the reference profile, "
              << d.vertices << " vertices over the footprint: largest |dz| "
              << report::short_number(d.max) << " m, rms " << report::short_number(d.rms) << " m\n";
}

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
    if (!terrain) {
        shapes::TerrainGrid grid;
        grid.spacing = args.spacing.value_or(grid.spacing);
        grid.margin = args.margin.value_or(grid.margin);
        grid.roughness = args.roughness.value_or(grid.roughness);
        grid.wavelength = args.wavelength.value_or(grid.wavelength);
        grid.seed = args.seed.value_or(grid.seed);
        generated = shapes::profile_terrain(file.scenario.slope, grid);
        comment = "rockfall terrain: the reference profile of " + file.path.filename().string() +
                  "\nspacing " + report::short_number(grid.spacing) + " m, margin " +
                  report::short_number(grid.margin) + " m, relief rms " +
                  report::short_number(grid.roughness) + " m, shortest wavelength " +
                  report::short_number(grid.wavelength) + " m, seed " + std::to_string(grid.seed) +
                  "\nslope frame (m): x downslope from the crown, y across, z up";
    } else {
        comment = "rockfall terrain: " + terrain->name() + " of " + file.path.filename().string() +
                  " as the engine simulates it\nslope frame (m): x downslope from the crown, y "
                  "across, z up";
    }
    const shapes::TriangleMesh& mesh = terrain ? terrain->mesh() : generated;
    if (args.obj) {
        AtomicFile out(*args.obj);
        shapes::write_obj(out.stream(), mesh, comment);
        out.commit();
    }
    if (terrain) {
        describe(file, *terrain, args.json);
    } else if (args.json) {
        std::cout << nlohmann::json{{"scenario", file.path.string()},
                                    {"name", nullptr},
                                    {"vertices", mesh.vertices.size()},
                                    {"triangles", mesh.triangles.size()}}
                         .dump(2)
                  << '\n';
    } else {
        std::cout << "terrain: none (" << file.path.string()
                  << " uses its profile segments); triangulated profile: " << mesh.vertices.size()
                  << " vertices, " << mesh.triangles.size() << " triangles\n";
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
