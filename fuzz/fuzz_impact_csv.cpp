// Impact CSV files (`rockfall fit`, `envelope`): scenario::CsvTable and impact_rows.

#include "fuzz_support.hpp"
#include "scenario/impact_csv.hpp"

#include <cmath>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    fuzz::expect_clear_refusal([&] {
        const scenario::CsvTable table =
            scenario::CsvTable::parse(fuzz::text_of(data, size), "fuzz_impacts.csv");
        for (const risk::ImpactRow& row : scenario::impact_rows(table)) {
            fuzz::require(std::isfinite(row.velocity) && row.velocity > 0 && row.mass > 0 &&
                              std::isfinite(row.mass) && std::isfinite(row.peak_force) &&
                              row.peak_force > 0,
                          "an impact row outside its documented ranges was accepted");
        }
    });
    return 0;
}
