// The HTML report of a results database: its sections and figures, numbers equal to the
// query's, the same bytes twice, and a well-formed document for the thin databases (no wall
// hit, one sample, none, a soil flow).

#include "report/html_report.hpp"
#include "report/query_report.hpp"
#include "report/text_format.hpp"
#include "svg_check.hpp"
#include "synthetic.hpp"

#include "db/queries.hpp"
#include "db/results_db.hpp"
#include "db/soil_run.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <random>
#include <sstream>
#include <string>

namespace fs = std::filesystem;
using namespace rockfall;

namespace {

// A directory of its own per test, removed afterwards.
class Scratch {
  public:
    Scratch() {
        std::random_device device;
        path_ = fs::temp_directory_path() / ("rockfall_html_" + std::to_string(device()));
        fs::create_directories(path_);
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    fs::path operator/(const std::string& name) const { return path_ / name; }

  private:
    fs::path path_;
};

db::ResultsDb sweep_db(const fs::path& path, std::int64_t samples,
                       db::testing::SyntheticOptions options = {}) {
    db::ResultsDb db = db::ResultsDb::create(path, db::testing::synthetic_run(options, samples));
    std::vector<db::SampleRecord> records;
    for (std::int64_t i = 0; i < samples; ++i) {
        records.push_back(db::testing::synthetic_record(options, i));
    }
    if (!records.empty()) db.write_batch(records);
    db.finish("complete", "2026-01-01T00:00:10Z");
    return db;
}

std::string report_of(const db::ResultsDb& db, report::HtmlReportOptions options = {}) {
    options.database = db.path().filename().string();
    options.generator = "rockfall test";
    std::ostringstream out;
    report::write_html_report(out, db, options);
    return out.str();
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

bool has_section(const std::string& html, const std::string& id) {
    return html.find("<section id=\"" + id + "\">") != std::string::npos;
}

}  // namespace

TEST_CASE("a sweep's report has every section, its figures and well-formed markup",
          "[report][html]") {
    Scratch dir;
    const db::ResultsDb db = sweep_db(dir / "sweep.db", 400);
    const std::string html = report_of(db);
    CHECK(test::xml_problem(html).empty());
    for (const char* id : {"provenance", "convergence", "reach", "stations", "wall", "envelope",
                           "worst", "scenario"}) {
        INFO(id);
        CHECK(has_section(html, id));
    }
    // Convergence, reach by shape and by zone, envelope.
    CHECK(count(html, "<figure>") == 4);
    CHECK(count(html, "<svg ") == 4);
    CHECK(count(html, "</svg>") == 4);
    // Ids are global in a page: each figure's clip path is its own.
    for (int k = 1; k <= 4; ++k) {
        CHECK(count(html, "id=\"fig" + std::to_string(k) + "-plot-area\"") == 1);
        CHECK(count(html, "url(#fig" + std::to_string(k) + "-plot-area)") == 1);
    }
    CHECK(count(html, "id=\"plot-area\"") == 0);
    // Self-contained: no script, nothing fetched.
    CHECK(html.find("<script") == std::string::npos);
    CHECK(html.find("src=") == std::string::npos);
    CHECK(html.find("@media print") != std::string::npos);
    CHECK(html.find("size: A4") != std::string::npos);
    CHECK(html.find("pressure map of the wall's cells") != std::string::npos);
}

TEST_CASE("the report's numbers are the query's", "[report][html]") {
    Scratch dir;
    const db::ResultsDb db = sweep_db(dir / "sweep.db", 300);
    const std::string html = report_of(db);
    const db::Summary summary = db::summarize(db, 0.95);
    REQUIRE(summary.wall.count > 0);
    CHECK(html.find(report::share_text(summary.wall, "95")) != std::string::npos);
    CHECK(html.find(report::share_text(summary.wall_samples, "95")) != std::string::npos);
    REQUIRE(!summary.stations.empty());
    for (const db::StationShare& s : summary.stations) {
        CHECK(html.find(report::share_text(s.reached, "95")) != std::string::npos);
    }
    const db::PercentileTable force =
        db::percentiles(db, db::Quantity::peak_force, {0.95}, {}, 0.95);
    CHECK(html.find("<td class=\"n\">" + report::fmt("%.4g", force.groups[0].rows[0].value) +
                    "</td>") != std::string::npos);
    // The worst rock by reach and its replay command.
    const db::WorstSample worst = db::worst_samples(db, db::Quantity::reach, 1).at(0);
    CHECK(html.find("\nrockfall simulate --from sweep.db --sample " + std::to_string(worst.sample) +
                    "\n") != std::string::npos);
    // The convergence ends at the summary's share of samples on the wall, with its interval.
    CHECK(html.find("<td>" + std::to_string(summary.samples) + "</td><td class=\"n\">" +
                    report::share_text(summary.wall_samples, "95")) != std::string::npos);
}

TEST_CASE("the same database gives the same bytes", "[report][html]") {
    Scratch dir;
    const db::ResultsDb db = sweep_db(dir / "sweep.db", 120);
    report::HtmlReportOptions options;
    options.distance = 3.0;
    const std::string first = report_of(db, options);
    CHECK(first == report_of(db, options));
    // And the options matter: another distance gives another report.
    options.distance = 5.0;
    CHECK(first != report_of(db, options));
}

TEST_CASE("thin databases still give a well-formed report", "[report][html]") {
    Scratch dir;
    SECTION("no wall hit") {
        db::testing::SyntheticOptions far;
        far.wall_distance = 1.0e3;
        const std::string html = report_of(sweep_db(dir / "far.db", 50, far));
        CHECK(test::xml_problem(html).empty());
        CHECK(has_section(html, "reach"));
        CHECK_FALSE(has_section(html, "wall"));
        CHECK_FALSE(has_section(html, "envelope"));
        CHECK(html.find("wall impacts (no rock hit the wall)") != std::string::npos);
    }
    SECTION("one sample") {
        const std::string html = report_of(sweep_db(dir / "one.db", 1));
        CHECK(test::xml_problem(html).empty());
        CHECK(has_section(html, "convergence"));
        CHECK(has_section(html, "worst"));
    }
    SECTION("no sample") {
        const std::string html = report_of(sweep_db(dir / "none.db", 0));
        CHECK(test::xml_problem(html).empty());
        CHECK(has_section(html, "provenance"));
        CHECK_FALSE(has_section(html, "convergence"));
        CHECK(html.find("convergence (no samples stored)") != std::string::npos);
    }
    SECTION("a soil flow") {
        db::SoilRunRecord r;
        r.run = db::testing::synthetic_run({}, 1);
        r.run.scenario_name = "soil <flow> & wall";
        r.run.method = "mpm";
        r.dimension = 2;
        r.wall_distance_from_toe = 0.5;
        r.sample_interval = 0.01;
        r.filter_window = 0.05;
        r.peak_force = 5705.25;
        r.peak_time = 0.03;
        for (int k = 1; k <= 6; ++k) {
            r.load.push_back({0.01 * k, {100.0 * k, 0.0, 0.0}, {90.0 * k, 0.0, 0.0}});
        }
        db::write_soil_run(dir / "soil.db", r);
        const std::string html = report_of(db::ResultsDb::open_any(dir / "soil.db", false));
        CHECK(test::xml_problem(html).empty());
        CHECK(has_section(html, "wall-load"));
        CHECK(count(html, "<figure>") == 1);
        CHECK(html.find("5705 N/m at 0.03 s") != std::string::npos);
        CHECK(html.find("soil &lt;flow&gt; &amp; wall") != std::string::npos);
    }
}

TEST_CASE("bad options are refused by name", "[report][html]") {
    report::HtmlReportOptions options;
    options.confidence = 1.5;
    CHECK_THROWS_WITH(report::validate(options), Catch::Contains("--confidence = 1.5"));
    options = {};
    options.formula.name = "jra";
    CHECK_THROWS_WITH(report::validate(options), Catch::Contains("needs --lambda"));
    options = {};
    options.factors.survey = 0.9;
    CHECK_THROWS_WITH(report::validate(options), Catch::Contains("gamma_Dp = 0.9"));
    options = {};
    options.worst = 0;
    CHECK_THROWS_WITH(report::validate(options), Catch::Contains("--worst = 0"));
}
