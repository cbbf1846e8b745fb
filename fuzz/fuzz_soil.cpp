// Soil scenario files (scenario::parse_soil_scenario), extends resolved in samples/soil/.

#include "fuzz_support.hpp"
#include "scenario/soil_file.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    fuzz::expect_clear_refusal([&] {
        scenario::parse_soil_scenario(fuzz::text_of(data, size), "fuzz_soil.toml",
                                      ROCKFALL_SAMPLES_DIR "/soil");
    });
    return 0;
}
