// Measured wall-load records (`rockfall soil --measured`): scenario::CsvTable and
// measured_history.

#include "fuzz_support.hpp"
#include "scenario/load_record.hpp"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    fuzz::expect_clear_refusal([&] {
        const scenario::CsvTable table =
            scenario::CsvTable::parse(fuzz::text_of(data, size), "fuzz_record.csv");
        const risk::LoadHistory history = scenario::measured_history(table);
        fuzz::require(history.time.size() >= 2, "a record of fewer than two rows was accepted");
        for (std::size_t i = 1; i < history.time.size(); ++i)
            fuzz::require(history.time[i] > history.time[i - 1],
                          "a record whose times do not increase was accepted");
    });
    return 0;
}
