// The runs of the seed 001 reproduction: the flume cases as shipped and with Table 2's shapes.

#include "validate_seed001.hpp"

#include "report/marked_rocks.hpp"
#include "report/rock_series.hpp"
#include "scenario/scenario_file.hpp"

#include "engine/pressure_cells.hpp"
#include "engine/simulation.hpp"
#include "shapes/slope.hpp"

#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>
#include <string>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;
namespace seed001 = risk::seed001;

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

// Trajectory sampling for the speeds at 1.4 m of travel, s.
constexpr double trajectory_interval = 0.005;

struct Case {
    seed001::Cluster cluster = seed001::Cluster::c2;
    int angle_deg = 45;
    std::optional<seed001::Shape> shape;
};

fs::path case_file(const Seed001Options& options, const Case& c) {
    return options.flume_dir /
           (seed001::to_string(c.cluster) + "_" + std::to_string(c.angle_deg) + ".toml");
}

// The shape keys of a rock of Table 2's numerical shape, as a scenario writes them.
std::string shape_keys(const Seed001Options& options, seed001::Shape shape) {
    if (shape == seed001::Shape::sphere) return "kind = \"sphere\"\n";
    return "catalogue = \"" + fs::absolute(options.catalogue).generic_string() + "\"\nentry = \"" +
           seed001::to_string(shape) + "\"\n";
}

// The case file, and for a numerical row the same file with every rock of that shape: the
// drawn rocks through [cluster]'s shape keys, the marked rocks at the same spots and sizes.
engine::Scenario case_scenario(const Seed001Options& options, const Case& c) {
    const fs::path file = case_file(options, c);
    scenario::ScenarioFile base = scenario::load_scenario(file);
    if (!c.shape) return std::move(base.scenario);
    std::ostringstream text;
    text.precision(17);
    const std::string keys = shape_keys(options, *c.shape);
    text << "extends = \"" << file.filename().generic_string() << "\"\n"
         << "name = \"" << base.scenario.name << ", every rock a " << seed001::to_string(*c.shape)
         << "\"\n\n[cluster]\n"
         << keys;
    for (const engine::MarkedRock& m : base.scenario.cluster->marked) {
        text << "\n[[cluster.marked]]\nname = \"" << m.name << "\"\n"
             << keys << "size = " << m.rock.size << "\nalong = " << m.along
             << "\nacross = " << m.across << '\n';
    }
    const std::string source =
        file.generic_string() + " with every rock a " + seed001::to_string(*c.shape);
    return scenario::parse_scenario(text.str(), source, options.flume_dir);
}

seed001::RunRecord run_case(const Seed001Options& options, const Case& c, std::uint64_t seed) {
    engine::Scenario scenario = case_scenario(options, c);
    if (options.sample_interval && scenario.wall_cells)
        scenario.wall_cells->sample_interval = *options.sample_interval;
    if (options.max_time) scenario.numerics.max_time = *options.max_time;
    report::SeriesRecorder series;
    engine::RunOptions run;
    run.trajectory_interval = trajectory_interval;
    run.trajectory = [&series](int rock, const engine::RockState& s) { series.add(rock, s); };
    const auto start = std::chrono::steady_clock::now();
    const engine::Outcome outcome = engine::simulate(scenario, seed, run);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;

    const shapes::Slope slope(scenario.slope);
    const engine::PressureMap map = engine::pressure_map(*scenario.wall_cells, slope, outcome);
    seed001::RunRecord record{c.cluster,       c.angle_deg,           c.shape, seed, {},
                              elapsed.count(), outcome.simulated_time};
    // The paper's speeds are its camera's (frames every 0.04 s); forces its pad's readings.
    const report::MarkedRocks marked = report::marked_rocks(outcome, series.series(), &map,
                                                            report::default_camera_interval, {1.4});
    for (const report::MarkedRock& rock : marked.rocks) {
        record.rocks.push_back({rock.name, rock.sampled_peak_force.value_or(nan),
                                rock.wall_hits > 0 ? rock.peak_force : nan,
                                rock.camera_speed.at(0)});
    }
    return record;
}

}  // namespace

std::vector<seed001::RunRecord> run_seed001(const Seed001Options& options) {
    std::vector<Case> cases;
    for (const seed001::Cluster cluster : seed001::clusters) {
        for (const int angle : seed001::angles_deg) {
            if (options.physical) cases.push_back({cluster, angle, std::nullopt});
            if (!options.numerical) continue;
            for (const seed001::Shape shape : seed001::shapes)
                cases.push_back({cluster, angle, shape});
        }
    }
    // Every case loads before any run starts, so a bad file fails at once.
    for (const Case& c : cases) case_scenario(options, c);
    const auto seeds = static_cast<std::size_t>(options.seeds);
    std::vector<seed001::RunRecord> records(cases.size() * seeds);
    const auto count = static_cast<std::int64_t>(records.size());
    risk::run_parallel(
        count, options.threads,
        [&](std::int64_t k) {
            const auto i = static_cast<std::size_t>(k);
            records[i] = run_case(options, cases[i / seeds], options.first_seed + i % seeds);
        },
        0, count, options.progress);
    return records;
}

}  // namespace rockfall::app
