// [sweep] tables: the input is the table's body (keys and [sweep.*] sub-tables) over the
// default scenario. A table that loads must give samples the scenario rules accept.

#include "fuzz_support.hpp"
#include "scenario/scenario_file.hpp"

#include "risk/sampling.hpp"

#include <algorithm>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    const std::string text = "[sweep]\n" + std::string(fuzz::text_of(data, size));
    fuzz::expect_clear_refusal([&] {
        const scenario::ScenarioFile file =
            scenario::parse_scenario_file(text, "fuzz_sweep.toml", ROCKFALL_SAMPLES_DIR);
        fuzz::require(file.has_sweep, "a [sweep] table was not read as one");
        const std::int64_t draws = std::min<std::int64_t>(file.sweep.samples, 3);
        for (std::int64_t i = 0; i < draws; ++i) {
            const risk::SampleInputs inputs = risk::draw_sample(file.sweep, file.scenario, i);
            const engine::Scenario sample = risk::sample_scenario(file.scenario, inputs);
            try {
                scenario::validate_scenario(sample);
            } catch (const scenario::ScenarioError& e) {
                std::fprintf(stderr, "fuzz: sample %lld of a valid sweep is invalid: %s\n",
                             static_cast<long long>(i), e.what());
                std::abort();
            }
        }
    });
    return 0;
}
