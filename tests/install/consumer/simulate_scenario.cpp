// One release of a scenario file through the installed rockfall::scenario (toml++, Bullet), and
// a missing results database refused by rockfall::db (SQLite).

#include "scenario/scenario_file.hpp"

#include "db/results_db.hpp"
#include "engine/simulation.hpp"

#include <cmath>
#include <cstdio>

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: simulate_scenario SCENARIO.toml\n");
        return 2;
    }
    const rockfall::scenario::ScenarioFile file = rockfall::scenario::load_scenario(argv[1]);
    const rockfall::engine::Outcome outcome = rockfall::engine::simulate(file.scenario, 3);
    if (outcome.rocks.empty() || !std::isfinite(outcome.rocks.front().reach)) {
        std::printf("simulate_scenario: FAILED: no finite reach\n");
        return 1;
    }
    std::printf("reach: %.3f m past the toe\n", outcome.rocks.front().reach);
    try {
        rockfall::db::ResultsDb::open("no_such_results.db", false);
    } catch (const rockfall::db::DatabaseError& e) {
        std::printf("database refused: %s\n", e.what());
        return 0;
    }
    std::printf("simulate_scenario: FAILED: a missing database was opened\n");
    return 1;
}
