#include "report/soil_report.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <sstream>

using rockfall::db::SoilRunRecord;

TEST_CASE("Soil summary: a run that ended non-finite has no runout and says why",
          "[report][soil]") {
    SoilRunRecord record;
    record.dimension = 2;
    record.outcome = "non_finite";
    record.message = "non-finite stable time step at t = 0.98 s";
    record.cell_size = 0.05;
    record.runout_x = std::numeric_limits<double>::quiet_NaN();
    record.runout_past_toe = std::numeric_limits<double>::quiet_NaN();
    std::ostringstream out;
    rockfall::report::print_soil_summary(out, record, "test.toml");
    const std::string text = out.str();
    CHECK_THAT(text, Catch::Contains("runout: none (the run ended non_finite, before the soil "
                                     "came to rest)"));
    CHECK_THAT(text, Catch::Contains("non_finite"));
    CHECK(text.find("runout nan") == std::string::npos);

    record.outcome = "completed";
    record.runout_x = 9.12;
    record.runout_past_toe = 0.48;
    std::ostringstream done;
    rockfall::report::print_soil_summary(done, record, "test.toml");
    CHECK_THAT(done.str(), Catch::Contains("runout 0.48 m past the toe (x 9.12 m)"));
}
