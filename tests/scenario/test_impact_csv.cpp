#include "scenario/csv_table.hpp"
#include "scenario/impact_csv.hpp"

#include <catch2/catch.hpp>

#include <string>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;
using namespace rockfall::scenario;
using rockfall::risk::ImpactShape;

namespace {

std::vector<rockfall::risk::ImpactRow> rows_of(const std::string& text) {
    return impact_rows(CsvTable::parse(text, "impacts.csv"));
}

}  // namespace

TEST_CASE("CSV table reads a header, skips comments and trims fields", "[scenario][csv]") {
    const CsvTable t =
        CsvTable::parse("# measured at the wall\n\n a , b\n1, 2.5\n# note\n3 ,x\n", "t.csv");
    CHECK(t.header() == std::vector<std::string>{"a", "b"});
    CHECK(t.rows() == 2);
    CHECK(t.find("b") == 1u);
    CHECK_FALSE(t.find("c").has_value());
    CHECK(t.number(0, 1) == 2.5);
    CHECK(t.text(1, 1) == "x");
    // Line numbers count every line, comments and blanks included.
    CHECK_THROWS_WITH(t.number(1, 1),
                      Contains("t.csv:6: column 2 (b) = \"x\": not a finite number"));
    CHECK_THROWS_WITH(t.require("c"),
                      Contains("t.csv:3: missing column c (the header names: a, b)"));
    // A spreadsheet's byte-order mark and CR LF line ends.
    const CsvTable excel = CsvTable::parse(
        "\xEF\xBB\xBF"
        "a,b\r\n1,2\r\n",
        "x.csv");
    CHECK(excel.header() == std::vector<std::string>{"a", "b"});
    CHECK(excel.number(0, 1) == 2.0);
}

TEST_CASE("CSV table rejects empty files and ragged rows", "[scenario][csv]") {
    CHECK_THROWS_WITH(CsvTable::parse("", "e.csv"), Contains("e.csv: empty file"));
    CHECK_THROWS_WITH(CsvTable::parse("# only a comment\n", "e.csv"), Contains("empty file"));
    CHECK_THROWS_WITH(CsvTable::parse("a,b\n1,2\n3\n", "r.csv"),
                      Contains("r.csv:3: 1 fields, but the header (line 1) names 2 columns"));
    CHECK_THROWS_AS(CsvTable::read("does-not-exist.csv"), CsvError);
    const CsvTable t = CsvTable::parse("a\n1e400\n nan\n\n", "n.csv");
    CHECK_THROWS_WITH(t.number(0, 0), Contains("\"1e400\": not a finite number"));
    CHECK_THROWS_WITH(t.number(1, 0), Contains("n.csv:3: column 1 (a) = \"nan\""));
}

TEST_CASE("impact rows in kN or N, columns in any order", "[scenario][csv]") {
    auto rows = rows_of(
        "shape,mass_kg,peak_force_kN,velocity_m_s,seed\n"
        "sphere,10.5,233.02,8,1\n"
        "planar,12,100,6.5,2\n");
    REQUIRE(rows.size() == 2);
    CHECK(rows[0].velocity == 8.0);
    CHECK_THAT(rows[0].peak_force, WithinRel(233020.0, 1e-12));
    CHECK(rows[0].mass == 10.5);
    CHECK(rows[0].shape == ImpactShape::sphere);
    CHECK(rows[1].shape == ImpactShape::planar);
    rows = rows_of("velocity_m_s,peak_force_N,mass_kg,shape\n8,233020,10.5,massive\n");
    CHECK(rows[0].peak_force == 233020.0);
    CHECK(rows[0].shape == ImpactShape::massive);
}

TEST_CASE("impact CSV errors name the line and column", "[scenario][csv]") {
    CHECK_THROWS_WITH(rows_of("velocity_m_s,peak_force_kN,shape\n8,100,sphere\n"),
                      Contains("impacts.csv:1: missing column mass_kg"));
    CHECK_THROWS_WITH(rows_of("velocity_m_s,mass_kg,shape\n8,10,sphere\n"),
                      Contains("exactly one of peak_force_kN and peak_force_N (it names neither)"));
    CHECK_THROWS_WITH(
        rows_of("velocity_m_s,peak_force_kN,peak_force_N,mass_kg,shape\n8,1,1000,10,sphere\n"),
        Contains("it names both"));
    CHECK_THROWS_WITH(rows_of("velocity_m_s,peak_force_kN,mass_kg,shape\n"),
                      Contains("impacts.csv: no data rows"));
    CHECK_THROWS_WITH(
        rows_of("velocity_m_s,peak_force_kN,mass_kg,shape\n8,100,10,sphere\n7,fast,10,sphere\n"),
        Contains("impacts.csv:3: column 2 (peak_force_kN) = \"fast\": not a finite number"));
    CHECK_THROWS_WITH(rows_of("velocity_m_s,peak_force_kN,mass_kg,shape\n8,100,-10,sphere\n"),
                      Contains("impacts.csv:2: column 3 (mass_kg) = -10 kg: must be > 0"));
    CHECK_THROWS_WITH(rows_of("velocity_m_s,peak_force_kN,mass_kg,shape\n0,100,10,sphere\n"),
                      Contains("column 1 (velocity_m_s) = 0 m/s: must be > 0"));
    CHECK_THROWS_WITH(rows_of("velocity_m_s,peak_force_kN,mass_kg,shape\n8,100,10,cube\n"),
                      Contains("impacts.csv:2: column 4 (shape)") &&
                          Contains("must be sphere, massive or planar"));
}
