// Rock scenario files (scenario::parse_scenario_file), with extends and mesh paths resolved in
// samples/. A scenario that loads must also load again from the text it stands for (the text a
// results database stores and `simulate --from` replays).

#include "fuzz_support.hpp"
#include "scenario/scenario_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    fuzz::expect_clear_refusal([&] {
        const scenario::ScenarioFile file = scenario::parse_scenario_file(
            fuzz::text_of(data, size), "fuzz.toml", ROCKFALL_SAMPLES_DIR);
        try {
            const scenario::ScenarioFile again = scenario::parse_scenario_file(
                file.text, "fuzz.toml (as stored)", ROCKFALL_SAMPLES_DIR);
            fuzz::require(again.has_sweep == file.has_sweep,
                          "the stored text lost or gained the [sweep] table");
        } catch (const std::exception& e) {
            std::fprintf(stderr, "fuzz: a loaded scenario's text does not load again: %s\n",
                         e.what());
            std::abort();
        }
    });
    return 0;
}
