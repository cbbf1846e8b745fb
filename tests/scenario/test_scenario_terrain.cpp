// Terrain meshes in scenario files ([slope.terrain]): the keys, their errors, the stored text
// that stands alone, and the sample scenario through engine::simulate.

#include "scenario/scenario_file.hpp"
#include "scenario_errors.hpp"

#include "engine/simulation.hpp"
#include "shapes/mesh_io.hpp"
#include "shapes/terrain.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using rockfall::engine::Scenario;
using rockfall::scenario::ScenarioError;
using rockfall::shapes::Vec3;

const fs::path samples = ROCKFALL_SAMPLES_DIR;
const fs::path meshes = ROCKFALL_MESH_DATA_DIR;

// A folder of its own with the seed profile triangulated every 0.5 m, shifted by -shift (so
// that offset = shift puts it back), as seed.obj.
class Folder {
  public:
    explicit Folder(const Vec3& shift = Vec3::Zero())
        : path_(fs::temp_directory_path() / ("rockfall_test_terrain_" + std::to_string(getpid()) +
                                             "_" + std::to_string(counter_++))) {
        fs::create_directories(path_);
        rockfall::shapes::TerrainGrid grid;
        grid.spacing = 0.5;
        rockfall::shapes::TriangleMesh mesh =
            rockfall::shapes::profile_terrain(rockfall::shapes::SlopeSpec{}, grid);
        for (Vec3& v : mesh.vertices) v -= shift;
        std::ofstream out(path_ / "seed.obj");
        rockfall::shapes::write_obj(out, mesh, "seed profile");
    }
    ~Folder() { fs::remove_all(path_); }
    Folder(const Folder&) = delete;
    Folder& operator=(const Folder&) = delete;

    const fs::path& path() const { return path_; }
    // Writes `text` as scenario.toml and loads it.
    rockfall::scenario::ScenarioFile load(const std::string& text) const {
        std::ofstream(path_ / "scenario.toml") << text;
        return rockfall::scenario::load_scenario(path_ / "scenario.toml");
    }

  private:
    static inline int counter_ = 0;
    fs::path path_;
};

// The problem reported for `key` when scenario text (written in tests/data/meshes) is parsed.
rockfall::scenario::ScenarioProblem problem(const std::string& text, const std::string& key) {
    const ScenarioError error = rockfall::test::parse_error(
        [](const std::string& t) {
            rockfall::scenario::parse_scenario(t, (meshes / "inline.toml").string(), meshes);
        },
        text);
    const rockfall::scenario::ScenarioProblem found = rockfall::test::problem_for(error, key);
    CHECK(found.line > 0);
    return found;
}

}  // namespace

TEST_CASE("a terrain mesh replaces the slabs; the stored text stands alone and reads back",
          "[scenario][scenario][terrain]") {
    const Folder folder;
    const rockfall::scenario::ScenarioFile file =
        folder.load("name = \"mesh\"\n[slope.terrain]\nmesh = \"seed.obj\"\n");
    const auto& terrain = file.scenario.slope.terrain;
    REQUIRE(terrain);
    CHECK(terrain->name() == "seed");
    CHECK(terrain->mesh().triangles.size() > 500);

    // The text names no file: the mesh itself is in it.
    CHECK_THAT(file.text, Contains("[slope.terrain]\nname = \"seed\"\nvertices = [\n    ["));
    CHECK_THAT(file.text, Contains("triangles = [\n    [0, "));
    CHECK(file.text.find("seed.obj") == std::string::npos);
    const rockfall::scenario::ScenarioFile back =
        rockfall::scenario::parse_scenario_file(file.text, "stored scenario", "/nonexistent");
    REQUIRE(back.scenario.slope.terrain);
    CHECK(back.scenario.slope.terrain->name() == "seed");
    CHECK(back.scenario.slope.terrain->mesh().vertices == terrain->mesh().vertices);
    CHECK(back.scenario.slope.terrain->mesh().triangles == terrain->mesh().triangles);
    // The written form is a fixed point and runs exactly as the file.
    CHECK(rockfall::scenario::format_scenario(back.scenario) ==
          rockfall::scenario::format_scenario(file.scenario));
    CHECK(rockfall::engine::simulate(back.scenario, 2).state_hash ==
          rockfall::engine::simulate(file.scenario, 2).state_hash);
}

TEST_CASE("scale and offset place a survey in the slope frame", "[scenario][scenario][terrain]") {
    const Vec3 shift(100.0, -20.0, 50.0);
    const Folder folder(shift);
    // The same mesh in millimetres would need scale = 0.001; here it is only shifted.
    const Scenario s = folder
                           .load(
                               "[slope.terrain]\nmesh = \"seed.obj\"\nname = \"survey\"\n"
                               "scale = 1.0\noffset = [100.0, -20.0, 50.0]\n")
                           .scenario;
    REQUIRE(s.slope.terrain);
    CHECK(s.slope.terrain->name() == "survey");
    CHECK_THAT(s.slope.terrain->lower().x(), WithinAbs(-0.5, 1e-4));
    CHECK_THAT(s.slope.terrain->lower().y(), WithinAbs(-3.0, 1e-4));
    CHECK_THAT(s.slope.terrain->upper().z(),
               WithinAbs(rockfall::shapes::Slope({}).surface_height(0), 1e-4));
    // Without the offset it lies far from the footprint.
    const ScenarioError error = rockfall::test::load_error(
        [&](const fs::path&) { folder.load("[slope.terrain]\nmesh = \"seed.obj\"\n"); },
        folder.path());
    CHECK_THAT(rockfall::test::problem_for(error, "slope.terrain").message,
               Contains("must cover the slope's footprint, x in [0, 16.1421") &&
                   Contains("place it in the slope frame with offset and scale"));
}

TEST_CASE("an inline terrain: vertices and triangles", "[scenario][scenario][terrain]") {
    // Two triangles covering the seed slope's footprint as one plane through its crown and end.
    const std::string text =
        "[slope.terrain]\nvertices = [[-1, -3, 6.2], [17, -3, 0], [17, 3, 0], [-1, 3, 6.2]]\n"
        "triangles = [[0, 1, 2], [0, 2, 3]]\n";
    const Scenario s = rockfall::scenario::parse_scenario(text, "inline.toml");
    REQUIRE(s.slope.terrain);
    CHECK(s.slope.terrain->name() == "terrain");
    CHECK(s.slope.terrain->mesh().triangles.size() == 2);
    CHECK_THAT(s.slope.terrain->ground(8.0, 0.0)->height, WithinAbs(6.2 * 9.0 / 18.0, 1e-12));
}

TEST_CASE("terrain key problems name the key, the value and the reason",
          "[scenario][scenario][terrain]") {
    CHECK_THAT(problem("[slope.terrain]\nmesh = \"missing.obj\"\n", "slope.terrain.mesh").message,
               Contains("\"missing.obj\": mesh file '") && Contains("missing.obj': no such file"));
    CHECK_THAT(
        problem("[slope.terrain]\nmesh = \"cube_points.obj\"\n", "slope.terrain.mesh").message,
        Contains("contains no triangles (only points or lines)"));
    CHECK_THAT(problem("[slope.terrain]\nmesh = \"cube.obj\"\n", "slope.terrain.mesh").message,
               Contains("outside the accepted [1, 10000] m"));
    CHECK_THAT(problem("[slope.terrain]\nmesh = \"cube.obj\"\nscale = -2\n", "slope.terrain.scale")
                   .message,
               Contains("-2: must be > 0"));
    CHECK_THAT(problem("[slope.terrain]\nscale = 2\n", "slope.terrain.mesh").message,
               Contains("missing: a terrain needs mesh = \"file\""));
    CHECK_THAT(problem("[slope.terrain]\nmesh = \"cube.obj\"\nvertices = [[0, 0, 0]]\n",
                       "slope.terrain.vertices")
                   .message,
               Contains("give either mesh or vertices with triangles, not both"));
    CHECK_THAT(
        problem("[slope.terrain]\nvertices = [[0, 0, 0]]\n", "slope.terrain.triangles").message,
        Contains("vertices and triangles go together"));
    CHECK_THAT(problem("[slope.terrain]\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                       "triangles = [[0, 1, -2]]\n",
                       "slope.terrain.triangles[0]")
                   .message,
               Contains("[ 0, 1, -2 ]: must be a triangle [i, j, k] of 3 vertex indices"));
    CHECK_THAT(problem("[slope.terrain]\nvertices = [[0, 0, 0], [1, 0, 0], [0, 1, 0]]\n"
                       "triangles = [[0, 1, 5]]\n",
                       "slope.terrain.vertices")
                   .message,
               Contains("triangle 0 refers to vertex 5, outside [0, 3)"));
    CHECK_THAT(problem("[slope.terrain]\nmesh = \"cube.obj\"\nmesh_scale = 2\n",
                       "slope.terrain.mesh_scale")
                   .message,
               Contains("unknown key"));
    // A hole under the release point.
    CHECK_THAT(problem("[slope.terrain]\n"
                       "vertices = [[-1, -3, 6.2], [17, -3, 0], [17, 3, 0], [-1, 3, 6.2], "
                       "[-1, 0, 6.2]]\ntriangles = [[0, 1, 2], [4, 2, 3]]\n",
                       "rocks[0].release.distance")
                   .message,
               Contains("has no surface under the release point"));
}

TEST_CASE("the terrain sample runs through engine::simulate", "[scenario][scenario][terrain]") {
    const rockfall::scenario::ScenarioFile file =
        rockfall::scenario::load_scenario(samples / "terrain" / "survey_slope.toml");
    REQUIRE(file.scenario.slope.terrain);
    CHECK(file.scenario.slope.terrain->name() == "survey");
    const auto run = rockfall::engine::simulate(file.scenario, 1);
    REQUIRE(run.rocks.size() == 1);
    CHECK(run.rocks[0].stop == rockfall::engine::StopReason::at_rest);
    // The sphere rolls to the reaction wall, 5 m past the toe, as on the seed slope.
    CHECK(run.rocks[0].reach > 4.5);
    CHECK(run.rocks[0].stations[0].reached);
}
