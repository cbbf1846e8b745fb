// Shape catalogues: TOML lists and folders of meshes, their errors, and the shipped samples.

#include "shapes/catalogue.hpp"
#include "shapes/measures.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::GeometryError;

const fs::path meshes = ROCKFALL_MESH_DATA_DIR;
const fs::path samples = ROCKFALL_SAMPLES_DIR;

// A catalogue file written next to the test meshes' copy in a fresh temporary folder.
class Scratch {
  public:
    Scratch()
        : folder_(fs::temp_directory_path() /
                  ("rockfall_test_catalogue_" + std::to_string(getpid()))) {
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        fs::copy_file(meshes / "cube.obj", folder_ / "cube.obj");
        fs::copy_file(meshes / "cube.stl", folder_ / "box.stl");
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;
    ~Scratch() { fs::remove_all(folder_); }
    fs::path write(const std::string& name, const std::string& text) const {
        std::ofstream(folder_ / name) << text;
        return folder_ / name;
    }
    const fs::path& folder() const { return folder_; }

  private:
    fs::path folder_;
};

std::string error_of(const fs::path& catalogue) {
    try {
        rockfall::shapes::read_catalogue(catalogue);
    } catch (const GeometryError& error) {
        return error.what();
    }
    FAIL("no GeometryError for " << catalogue);
    return "";
}

}  // namespace

TEST_CASE("a TOML catalogue names meshes relative to itself, with optional scaling",
          "[shapes][catalogue]") {
    const Scratch scratch;
    const fs::path file = scratch.write("list.toml", R"(
[[shape]]
name = "plain"
file = "cube.obj"

[[shape]]
name = "in mm"
file = "cube.obj"
scale = 0.001
size = 0.5

[[shape]]
name = "long"
file = "box.stl"
long_axis = 0.3
)");
    const auto catalogue = rockfall::shapes::read_catalogue(file);
    REQUIRE(catalogue.entries.size() == 3);
    CHECK(catalogue.entries[0].file == scratch.folder() / "cube.obj");
    CHECK(catalogue.entries[0].origin == file.string() + ":2");
    CHECK(catalogue.entries[1].scaling.scale == 0.001);

    const auto plain =
        rockfall::shapes::load_entry(rockfall::shapes::find_entry(catalogue, "plain"));
    CHECK(plain.name == "plain");
    CHECK_THAT(rockfall::shapes::shape_measures(plain.hull).properties.volume,
               WithinRel(0.008, 1e-6));
    const auto sized =
        rockfall::shapes::load_entry(rockfall::shapes::find_entry(catalogue, "in mm"));
    CHECK_THAT(rockfall::shapes::shape_measures(sized.hull).equivalent_diameter,
               WithinRel(0.5, 1e-12));
    const auto longest = rockfall::shapes::load_entry(catalogue.entries[2]);
    CHECK_THAT(rockfall::shapes::shape_measures(longest.hull).axis_lengths[0],
               WithinRel(0.3, 1e-12));
    CHECK_THROWS_WITH(rockfall::shapes::find_entry(catalogue, "granite"),
                      Contains("no entry named 'granite'; entries: plain, in mm, long"));
}

TEST_CASE("a folder catalogue holds every mesh file in it, named by stem", "[shapes][catalogue]") {
    const Scratch scratch;
    scratch.write("notes.txt", "not a mesh");
    const auto catalogue = rockfall::shapes::read_catalogue(scratch.folder());
    REQUIRE(catalogue.entries.size() == 2);
    CHECK(catalogue.entries[0].name == "box");
    CHECK(catalogue.entries[1].name == "cube");
    CHECK(rockfall::shapes::load_entry(catalogue.entries[0]).hull.vertices.size() == 8);
    // Two files with one stem are ambiguous.
    fs::copy_file(meshes / "cube.ply", scratch.folder() / "cube.ply");
    CHECK_THAT(error_of(scratch.folder()), Contains("two entries are named 'cube'"));
}

TEST_CASE("bad catalogues are GeometryErrors with file and line", "[shapes][catalogue]") {
    const Scratch scratch;
    const std::pair<std::string, std::string> cases[] = {
        {"[[shape]]\nname = \"a\"\nfile = \"cube.obj\"\ncolour = \"grey\"\n",
         "bad_key.toml:4: shape[0].colour: unknown key"},
        {"[[shape]]\nname = \"a\"\n", "bad_file.toml:1: shape[0].file is missing"},
        {"[[shape]]\nname = \"\"\nfile = \"cube.obj\"\n",
         "bad_name.toml:2: shape[0].name: must be a non-empty string"},
        {"[[shape]]\nname = \"a\"\nfile = \"cube.obj\"\nscale = -2\n",
         "bad_scale.toml:4: shape[0].scale = -2: must be a finite number > 0"},
        {"[[shape]]\nname = \"a\"\nfile = \"cube.obj\"\nsize = 0.2\nlong_axis = 0.3\n",
         "bad_both.toml:1: shape[0]: give size or long_axis, not both"},
        {"[[shape]]\nname = \"a\"\nfile = \"cube.obj\"\n[[shape]]\nname = \"a\"\nfile = "
         "\"box.stl\"\n",
         "two entries are named 'a'"},
        {"[[shape]\n", "bad_syntax.toml:1: TOML syntax error"},
        {"rocks = 3\n", "bad_top.toml:1: rocks: unknown key"},
        {"# nothing\n", "lists no [[shape]]"},
    };
    const char* names[] = {"bad_key.toml",    "bad_file.toml", "bad_name.toml",
                           "bad_scale.toml",  "bad_both.toml", "bad_twice.toml",
                           "bad_syntax.toml", "bad_top.toml",  "bad_empty.toml"};
    for (std::size_t i = 0; i < std::size(cases); ++i) {
        INFO(names[i]);
        CHECK_THAT(error_of(scratch.write(names[i], cases[i].first)), Contains(cases[i].second));
    }
    CHECK_THAT(error_of(scratch.folder() / "missing.toml"), Contains("no such file or folder"));
    CHECK_THAT(error_of(scratch.folder() / "cube.obj"),
               Contains("must be a folder of meshes or a .toml file"));
    // A missing mesh shows when the entry is loaded, naming entry, line and file.
    const auto catalogue = rockfall::shapes::read_catalogue(
        scratch.write("missing_mesh.toml", "[[shape]]\nname = \"ghost\"\nfile = \"ghost.obj\"\n"));
    CHECK_THROWS_WITH(rockfall::shapes::load_entry(catalogue.entries[0]),
                      Contains("entry 'ghost' (") && Contains("missing_mesh.toml:1") &&
                          Contains("ghost.obj': no such file"));
}

TEST_CASE("the shipped sample catalogues load: shapes and sizes as documented",
          "[shapes][catalogue]") {
    const auto catalogue = rockfall::shapes::read_catalogue(samples / "rocks" / "catalogue.toml");
    CHECK(catalogue.entries.size() == 10);
    for (const auto& entry : catalogue.entries) {
        INFO(entry.name);
        const auto m = rockfall::shapes::shape_measures(rockfall::shapes::load_entry(entry).hull);
        CHECK_THAT(m.equivalent_diameter, WithinRel(entry.name == "elongated" ? 0.30 : 0.20, 1e-6));
        if (entry.name.rfind("psi_", 0) == 0) {
            CHECK_THAT(m.wadell_sphericity, WithinAbs(std::stod(entry.name.substr(4)), 1e-3));
        }
    }
    for (const char* folder : {"obj", "stl"}) {
        INFO(folder);
        CHECK(rockfall::shapes::read_catalogue(samples / "rocks" / folder).entries.size() == 10);
    }
}
