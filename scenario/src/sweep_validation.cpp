// Checks of a sweep spec against its base scenario. The scenario's ranges and cross-field rules
// (scenario_validation.cpp) are not restated here: each end of a support is put into a copy of
// the base scenario and judged by the same rules, and their problems are reported on the sweep's
// key.

#include "scenario/scenario_file.hpp"
#include "sweep_reader.hpp"

#include "risk/distribution.hpp"

#include <cmath>
#include <functional>
#include <set>

namespace rockfall::scenario {
namespace detail {
namespace {

// One input whose support the scenario's rules judge.
struct Probe {
    std::string sweep_key;
    const risk::Distribution& distribution;
    std::string_view unit;
    // The key of the same input in a one-rock scenario, and how to set it.
    std::string scenario_key;
    std::function<void(engine::RockRelease&, double)> set;
    // Whether the rules depend on the shape (size only): then every drawn shape is tried.
    bool per_kind = false;
};

// "uniform [0.005, 0.4] m: its lower end 0.005 m: must be in [0.01, 10]" from the rule's
// "0.005 m: must be in [0.01, 10]"; a fixed value keeps the rule's own message.
std::string on_support(const Probe& probe, const char* end, double value,
                       const std::string& message) {
    if (probe.distribution.family == risk::Distribution::Family::fixed) return message;
    std::string text = risk::describe(probe.distribution) +
                       (probe.unit.empty() ? "" : " " + std::string(probe.unit)) + ": its " + end +
                       " " + message;
    if (std::isinf(value)) text += " (truncate the distribution with min and max)";
    return text;
}

std::vector<Probe> probes(const risk::SweepSpec& spec) {
    std::vector<Probe> list = {
        {"sweep.rock.size", spec.size, "m", "rocks[0].size",
         [](engine::RockRelease& r, double v) { r.rock.size = v; }, true},
        {"sweep.rock.density", spec.density, "kg/m3", "rocks[0].density",
         [](engine::RockRelease& r, double v) { r.rock.density = v; }},
        {"sweep.rock.material.friction", spec.friction, "", "rocks[0].material.friction",
         [](engine::RockRelease& r, double v) { r.rock.material.friction = v; }},
        {"sweep.rock.material.restitution", spec.restitution, "", "rocks[0].material.restitution",
         [](engine::RockRelease& r, double v) { r.rock.material.restitution = v; }},
        {"sweep.rock.material.rolling_resistance", spec.rolling_resistance, "",
         "rocks[0].material.rolling_resistance",
         [](engine::RockRelease& r, double v) { r.rock.material.rolling_resistance = v; }},
    };
    for (std::size_t i = 0; i < spec.zones.size(); ++i) {
        list.push_back({"sweep.release.zones[" + std::to_string(i) + "].distance",
                        spec.zones[i].distance, "m", "rocks[0].release.distance",
                        [](engine::RockRelease& r, double v) { r.release.distance = v; }});
    }
    return list;
}

}  // namespace

std::vector<ScenarioProblem> find_sweep_problems(const risk::SweepSpec& spec,
                                                 const engine::Scenario& base,
                                                 const SourceMap* sources) {
    std::vector<ScenarioProblem> problems;
    // Keys the scenario's rules found a problem with.
    std::set<std::string> judged;
    const auto place = [&](const std::string& key, const std::string& message) {
        for (const ScenarioProblem& p : problems) {
            if (p.key == key && p.message == message) return;
        }
        Location where = sources != nullptr ? sources->find(key) : Location{};
        problems.push_back({std::move(where.file), where.line, key, message});
    };

    if (!base.rocks.empty()) {
        // Lateral positions are drawn inside the band where each rock fits: keep the probe's
        // rock on the centre line so that only the probed input is judged.
        engine::Scenario probe_base = base;
        probe_base.rocks = {base.rocks.front()};
        probe_base.rocks.front().release.lateral = 0.0;
        const engine::RockSpec& base_rock = base.rocks.front().rock;
        const std::vector<risk::DrawableShape> shapes_drawn = risk::drawable_shapes(spec, base);
        for (const Probe& probe : probes(spec)) {
            if (!risk::find_problems(probe.distribution).empty()) continue;
            const risk::Interval support = risk::support(probe.distribution);
            std::vector<risk::DrawableShape> drawn = {{"", base_rock.kind, base_rock.shape, 0.0}};
            if (probe.per_kind) drawn = shapes_drawn;
            for (const auto& [end, value] :
                 {std::pair("lower end", support.lower), std::pair("upper end", support.upper)}) {
                for (const risk::DrawableShape& shape : drawn) {
                    engine::Scenario probe_scenario = probe_base;
                    engine::RockRelease& rock = probe_scenario.rocks.front();
                    rock.rock.kind = shape.kind;
                    rock.rock.shape = shape.shape;
                    probe.set(rock, value);
                    for (const ScenarioProblem& p : find_problems(probe_scenario, nullptr)) {
                        if (p.key == probe.scenario_key) {
                            place(probe.sweep_key, on_support(probe, end, value, p.message));
                            judged.insert(probe.sweep_key);
                        }
                    }
                }
            }
        }
    }
    // The scenario's rules speak first: a size out of range is reported as such, not as a rock
    // that does not fit.
    for (const risk::SweepProblem& problem : risk::find_problems(spec, base)) {
        if (judged.count(problem.key) == 0) place(problem.key, problem.message);
    }
    return problems;
}

}  // namespace detail

void validate_sweep(const risk::SweepSpec& spec, const engine::Scenario& base) {
    std::vector<ScenarioProblem> problems = detail::find_problems(base, nullptr);
    if (problems.empty()) problems = detail::find_sweep_problems(spec, base, nullptr);
    if (!problems.empty()) throw ScenarioError(std::move(problems));
}

}  // namespace rockfall::scenario
