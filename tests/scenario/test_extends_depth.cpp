// The depth limit of `extends` chains, on chains generated in a temporary folder.

#include "scenario/scenario_file.hpp"
#include "scenario/soil_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

namespace fs = std::filesystem;
using Catch::Matchers::Contains;
using rockfall::scenario::max_extends_depth;
using rockfall::scenario::ScenarioError;

namespace {

/// level_0.toml extends level_1.toml ... extends level_BASES.toml, which sets gravity; with
/// `one_more`, the last file extends level_(BASES + 1).toml, a file that is never written.
class Chain {
  public:
    Chain(int bases, bool one_more)
        : folder_(fs::temp_directory_path() /
                  ("rockfall_test_extends_" + std::to_string(getpid()))) {
        fs::remove_all(folder_);
        fs::create_directories(folder_);
        for (int i = 0; i <= bases; ++i) {
            std::ofstream file(folder_ / name(i));
            file << "name = \"level " << i << "\"\n";
            if (i < bases || one_more) file << "extends = \"" << name(i + 1) << "\"\n";
            if (i == bases) file << "gravity = 9.5\n";
        }
    }
    Chain(const Chain&) = delete;
    Chain& operator=(const Chain&) = delete;
    ~Chain() {
        std::error_code ignored;
        fs::remove_all(folder_, ignored);
    }
    fs::path file(int level) const { return folder_ / name(level); }
    static std::string name(int level) { return "level_" + std::to_string(level) + ".toml"; }

  private:
    fs::path folder_;
};

}  // namespace

TEST_CASE("extends chains are followed up to max_extends_depth bases", "[scenario][errors]") {
    REQUIRE(max_extends_depth == 32);
    SECTION("a chain of exactly the limit loads, every base merged") {
        const Chain chain(max_extends_depth, false);
        const rockfall::scenario::ScenarioFile loaded =
            rockfall::scenario::load_scenario(chain.file(0));
        CHECK(loaded.scenario.name == "level 0");
        CHECK(loaded.scenario.gravity == 9.5);
    }
    SECTION("one base more is refused at the extends that goes too deep, before reading it") {
        const Chain chain(max_extends_depth, true);
        try {
            rockfall::scenario::load_scenario(chain.file(0));
            FAIL("a chain deeper than the limit loaded");
        } catch (const ScenarioError& error) {
            REQUIRE(error.problems().size() == 1);
            const rockfall::scenario::ScenarioProblem& problem = error.problems()[0];
            CHECK(fs::path(problem.file).filename() == Chain::name(max_extends_depth));
            CHECK(problem.line == 2);
            // level_33.toml does not exist: the limit is checked before the base is read.
            CHECK_THAT(error.what(), Contains("extends = \"level_33.toml\": the chain of base "
                                              "scenarios goes 33 files deep here; the most is 32"));
        }
    }
    SECTION("the depth counts from the file loaded: from level 1, level_33.toml is read") {
        const Chain chain(max_extends_depth, true);
        CHECK_THROWS_WITH(rockfall::scenario::load_scenario(chain.file(1)),
                          Contains("level_33.toml' named by extends: no such file"));
    }
    SECTION("soil scenario files follow the same rule") {
        const Chain chain(max_extends_depth, true);
        CHECK_THROWS_WITH(rockfall::scenario::load_soil_scenario(chain.file(0)),
                          Contains("goes 33 files deep here; the most is 32"));
    }
}
