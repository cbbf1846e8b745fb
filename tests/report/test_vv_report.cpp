// The verification and validation report (report/vv_report.hpp): a check's error and verdict,
// the HTML's sections and check rows, well-formed markup without script, the same bytes
// twice, JSON and text carrying the same checks, and seed 001's section from runs.

#include "report/vv_report.hpp"
#include "svg_check.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>
#include <sstream>
#include <string>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using report::make_check;

namespace {

constexpr double no_value = std::numeric_limits<double>::quiet_NaN();

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) {
        ++n;
    }
    return n;
}

// Two sections, three checks (one MISS), a figure, a text table and a left-out item.
report::VvReport sample_report() {
    report::VvReport r;
    r.version = "9.8.7";
    r.build = "Test, GNU 12 & <co>";
    r.quick = true;
    r.settings = {{"seed 001", "1 cluster seed(s) from 1"}};
    report::VvSection motion;
    motion.id = "engine";
    motion.title = "Engine";
    motion.notes = {"Free fall at dt 1 ms; tolerance 0.2 % because of the step's lag."};
    motion.tables.push_back(
        {"Free fall",
         {make_check("free_fall.drop", "drop in 1 s", "m", 4.905, "g t^2 / 2", 4.91, 0.002),
          make_check("bounce.ratio", "speed ratio", "", 0.3, "e", 0.35, 0.025)}});
    report::Plot plot;
    plot.title = "Drop";
    plot.x_label = "t (s)";
    plot.y_label = "z (m)";
    plot.series = {report::line_series("z", "#1f77b4", {0.0, 1.0}, {10.0, 5.1})};
    motion.figures.push_back({plot, "The drop against time."});
    report::VvSection shapes;
    shapes.id = "shapes";
    shapes.title = "Shapes";
    shapes.tables.push_back(
        {"Sphericity",
         {make_check("sphericity.cube", "cube", "", 0.806, "Wadell 1935", 0.8060, 0.001, false)}});
    shapes.text_tables.push_back({"Trends", {"trend", "verdict"}, {{"a < b", "holds"}}});
    r.sections = {motion, shapes};
    r.left_out = {{"the heap test", "--quick"}};
    return r;
}

std::string html_of(const report::VvReport& r) {
    std::ostringstream out;
    report::write_vv_html(out, r);
    return out.str();
}

}  // namespace

TEST_CASE("a check's error is relative to |reference| or absolute in its unit", "[report][vv]") {
    const report::VvCheck relative = make_check("a", "a", "m", -2.0, "", -2.1, 0.06);
    CHECK_THAT(relative.error(), WithinRel(-0.05, 1e-12));
    CHECK(relative.pass());
    const report::VvCheck tight = make_check("b", "b", "m", -2.0, "", -2.1, 0.04);
    CHECK_FALSE(tight.pass());
    const report::VvCheck absolute = make_check("c", "c", "", 0.0, "", 0.0015, 0.001, false);
    CHECK_THAT(absolute.error(), WithinAbs(0.0015, 1e-15));
    CHECK_FALSE(absolute.pass());
    const report::VvCheck edge = make_check("d", "d", "", 1.0, "", 1.0005, 0.001, false);
    CHECK(edge.pass());
}

TEST_CASE("a check without a simulated value, or with a zero relative reference, is a MISS",
          "[report][vv]") {
    const report::VvCheck none = make_check("a", "a", "m", 1.0, "", no_value, 1.0);
    CHECK(std::isnan(none.error()));
    CHECK_FALSE(none.pass());
    const report::VvCheck zero = make_check("b", "b", "m", 0.0, "", 0.0, 0.1);
    CHECK_FALSE(zero.pass());
    const report::VvCheck infinite = make_check("c", "c", "m", 1.0, "", INFINITY, 0.1);
    CHECK_FALSE(infinite.pass());
}

TEST_CASE("the HTML has every section and check row, no script, and is well-formed",
          "[report][vv][html]") {
    const report::VvReport r = sample_report();
    const std::string html = html_of(r);
    CHECK(test::xml_problem(html).empty());
    INFO(test::xml_problem(html));
    for (const std::string id : {"summary", "engine", "shapes"}) {
        CHECK(count(html, "<section id=\"" + id + "\">") == 1);
        CHECK(count(html, "<a href=\"#" + id + "\">") == 1);
    }
    for (const report::VvCheck* c : report::all_checks(r)) {
        CHECK(count(html, "<tr id=\"check-" + c->id + "\">") == 1);
    }
    CHECK(report::all_checks(r).size() == 3);
    CHECK(count(html, ">PASS</td>") == 2);
    CHECK(count(html, ">MISS</td>") == 1);
    CHECK(count(html, "<figure>") == 1);
    CHECK(count(html, "<svg") == 1);
    CHECK(count(html, "<script") == 0);
    CHECK(count(html, "@media print") == 1);
    // Version and build, escaped; the left-out item; the verdict counts of the summary.
    CHECK(count(html, "rockfall 9.8.7 (Test, GNU 12 &amp; &lt;co&gt;)") >= 2);
    CHECK(count(html, "the heap test (--quick)") == 1);
    CHECK(count(html, "Summary: 3 checks: 2 PASS, 1 MISS") >= 1);
    CHECK(count(html, "quick run") >= 1);
}

TEST_CASE("the same report renders to the same bytes", "[report][vv][html]") {
    const report::VvReport r = sample_report();
    CHECK(html_of(r) == html_of(r));
    report::VvReport other = r;
    other.sections[0].tables[0].checks[0].simulated = 4.95;
    CHECK(html_of(other) != html_of(r));
}

TEST_CASE("JSON and text carry the same checks and verdicts", "[report][vv]") {
    const report::VvReport r = sample_report();
    const nlohmann::json j = report::vv_json(r);
    REQUIRE(j.at("checks").size() == 3);
    CHECK(j.at("passed") == 2);
    CHECK(j.at("missed") == 1);
    CHECK(j.at("version") == "9.8.7");
    CHECK(j.at("quick") == true);
    CHECK(j.at("checks")[1].at("id") == "bounce.ratio");
    CHECK(j.at("checks")[1].at("section") == "engine");
    CHECK(j.at("checks")[1].at("verdict") == "MISS");
    CHECK(j.at("checks")[2].at("relative") == false);
    report::VvReport missing = r;
    missing.sections[0].tables[0].checks[0].simulated = no_value;
    CHECK(report::vv_json(missing).at("checks")[0].at("simulated").is_null());

    std::ostringstream text;
    report::print_vv_summary(text, r);
    CHECK(count(text.str(), "  MISS\n") == 1);
    CHECK(count(text.str(), "  PASS\n") == 2);
    CHECK(count(text.str(), "3 checks: 2 PASS, 1 MISS") == 1);
    // A section's own text replaces its check lines.
    report::VvReport own = r;
    own.sections[1].text = "  the shapes' own table\n";
    std::ostringstream replaced;
    report::print_vv_summary(replaced, own);
    CHECK(count(replaced.str(), "the shapes' own table") == 1);
    CHECK(count(replaced.str(), "  PASS\n") == 1);
}

TEST_CASE("seed 001's section has a check per cell that ran, and its figures",
          "[report][vv][seed001]") {
    namespace seed001 = risk::seed001;
    report::ReproductionInfo info;
    info.source = "samples/seed_flume";
    info.seeds = 1;
    info.runs = 1;
    info.sample_interval = 1e-3;
    SECTION("no runs: no checks, no figure") {
        const report::VvSection s = report::seed001_section(seed001::compare({}), info);
        CHECK(s.tables.empty());
        CHECK(s.figures.empty());
        CHECK(s.text_tables.empty());
    }
    SECTION("one physical run: its 24 force and 24 speed cells, the published value beside it") {
        seed001::RunRecord run;
        run.cluster = seed001::Cluster::c2;
        run.angle_deg = 45;
        const double yellow = seed001::published_force(seed001::Marked::yellow, run.cluster, 45);
        run.rocks = {{"yellow", 1.1 * yellow, 1.2 * yellow, 3.0},
                     {"green", no_value, no_value, no_value},
                     {"blue", 100.0, 110.0, 2.0},
                     {"red", 100.0, 110.0, 2.0}};
        const report::VvSection s = report::seed001_section(seed001::compare({run}), info);
        REQUIRE(s.tables.size() == 2);
        REQUIRE(s.tables[0].checks.size() == 4);  // the cells of C2, 45 deg that ran
        const report::VvCheck& c = s.tables[0].checks[0];
        CHECK(c.id == "seed001.peak_force_yellow_c2_45_deg");
        CHECK(c.reference == yellow);
        CHECK_THAT(c.simulated, WithinRel(1.1 * yellow, 1e-12));
        CHECK(c.pass());
        CHECK_FALSE(s.tables[0].checks[1].pass());  // green never touched the wall
        CHECK(s.text_tables.empty());               // no numerical rows: no trends
        CHECK(s.figures.size() == 2);
    }
}
