// Rocks on the perforated sheet (issue 13): where a sphere comes to rest on the sheet, in a
// hole or through it, against the closed forms, for the structured contact (the default) and
// Bullet's triangle mesh; and both contacts against each other on a rolling sphere.

#include "plane_scenario.hpp"

#include "engine/simulation.hpp"
#include "shapes/lining.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <vector>

using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall;
using namespace rockfall::engine;
using namespace rockfall::engine::test;

namespace {

const Material kRough{0.4, 0.3, 0.0};

// A sphere of radius `radius` on a horizontal 1.2 m segment 0.6 m wide, dropped 5 mm onto it at
// (x, y); the segment lined with the default sheet when `sheet`.
Scenario drop(double radius, double x, double y, bool sheet, SheetContact contact) {
    Scenario scenario = plane_scenario(0.0, shapes::RockKind::sphere, kRough, 1e-3);
    scenario.slope.segments = {{1.2, 0.0}};
    scenario.slope.width = 0.6;
    scenario.rocks.front().rock.size = 2.0 * radius;
    scenario.rocks.front().release.distance = x;
    scenario.rocks.front().release.lateral = y;
    scenario.rocks.front().release.height = 0.005;
    scenario.numerics.max_time = 2.0;
    scenario.numerics.sheet_contact = contact;
    if (sheet) {
        auto lining = std::make_shared<shapes::Lining>();
        lining->sheet = shapes::PerforatedSheet{};
        scenario.slope.lining = lining;
        scenario.rocks.front().release.height += lining->sheet->thickness;
    }
    return scenario;
}

// Where the rock's centre ends, m.
Vec3 rest_position(const Scenario& scenario) { return trajectory(scenario, 1e-2).back().position; }

// The hole of the default sheet on that segment nearest to (0.6, 0).
shapes::SheetHole middle_hole() {
    const Scenario scenario = drop(0.03, 0.6, 0.0, true, SheetContact::structured);
    const shapes::Slope slope(scenario.slope);
    const shapes::SheetMesh sheet = shapes::perforated_sheet(slope, *scenario.slope.lining->sheet);
    return *std::min_element(sheet.holes.begin(), sheet.holes.end(),
                             [](const shapes::SheetHole& a, const shapes::SheetHole& b) {
                                 return (a.center - Vec3(0.6, 0.0, 0.0)).norm() <
                                        (b.center - Vec3(0.6, 0.0, 0.0)).norm();
                             });
}

const char* name(SheetContact contact) {
    return contact == SheetContact::structured ? "structured" : "mesh";
}

}  // namespace

TEST_CASE("a sphere rests on the sheet, on a hole's rim or through the hole where geometry says",
          "[engine][lining]") {
    const shapes::PerforatedSheet sheet;
    const shapes::SheetHole hole = middle_hole();
    REQUIRE(hole.center.z() == 0.0);
    // The 16-gon's edges are tangent to the circle of the apothem a = r cos(pi / 16) = 24.5 mm.
    const double apothem = hole.radius * std::cos(std::numbers::pi / hole.sides);
    for (const SheetContact contact : {SheetContact::structured, SheetContact::mesh}) {
        INFO(name(contact) << " contact");
        // On the sheet's top between two holes of a row (40 mm from each centre): R + t.
        const double big = 0.03;
        const Vec3 between = hole.center + Vec3(0.0, 0.5 * sheet.hole_spacing, 0.0);
        const Vec3 on_top = rest_position(drop(big, between.x(), between.y(), true, contact));
        CHECK_THAT(on_top.z(), WithinAbs(big + sheet.thickness, 2e-4));
        // Over a hole a sphere sags by R - sqrt(R^2 - a^2) below the top: more than the 1.5 mm
        // of the sheet (a 60 mm sphere rests on the slope surface) unless R > 0.2 m. A 0.5 m
        // sphere sits on the middles of the 16 edges, its centre sqrt(R^2 - a^2) above the top
        // (0.295 mm higher than on the surface).
        const double huge = 0.25;
        const Vec3 on_rim =
            rest_position(drop(huge, hole.center.x(), hole.center.y(), true, contact));
        const double off_centre = (on_rim - hole.center).head<2>().norm();
        INFO("on the rim: " << off_centre * 1e3 << " mm off the centre");
        // Structured: centred (to 1 mm) at the height of the edges' middles. Bullet's triangle
        // contact does not push a sphere on the rim to the centre (without friction it stayed
        // 2.3 mm off as well): it rests near where it landed, 1.5 mm off since resting contacts
        // stopped jittering (docs/contact_model.md, "Resting contacts"; 0.5 mm before), on the
        // rim a little higher than when centred.
        const bool structured = contact == SheetContact::structured;
        CHECK_THAT(on_rim.z(),
                   WithinAbs(sheet.thickness + std::sqrt(huge * huge - apothem * apothem),
                             structured ? 5e-5 : 2e-4));
        CHECK(off_centre < (structured ? 1e-3 : 3e-3));
        const Vec3 sagged =
            rest_position(drop(big, hole.center.x(), hole.center.y(), true, contact));
        CHECK_THAT(sagged.z(), WithinAbs(big, 2e-4));
        // A narrower one drops through onto the slope surface and stays inside the hole.
        const double small = 0.02;
        const Vec3 through =
            rest_position(drop(small, hole.center.x() + 0.003, hole.center.y(), true, contact));
        CHECK_THAT(through.z(), WithinAbs(small, 2e-4));
        CHECK((through - hole.center).head<2>().norm() <= apothem - small + 1e-4);
    }
}

TEST_CASE("a slow sphere in a hole stays in it: the hole's wall holds it", "[engine][lining]") {
    // A 40 mm sphere rolling at 5 cm/s on the slope surface inside a hole meets the 1.5 mm wall:
    // climbing it needs (7/10) v^2 > g h (rolling without slip), v > 0.14 m/s. Against the
    // rim at height t the centre is sqrt(R^2 - (R - t)^2) = 7.6 mm in from it, so it stays
    // within r - 7.6 mm of the hole's centre.
    const shapes::SheetHole hole = middle_hole();
    const double t = shapes::PerforatedSheet{}.thickness;
    const double inside = hole.radius - std::sqrt(0.02 * 0.02 - (0.02 - t) * (0.02 - t));
    for (const SheetContact contact : {SheetContact::structured, SheetContact::mesh}) {
        INFO(name(contact) << " contact");
        Scenario scenario = drop(0.02, hole.center.x(), hole.center.y(), true, contact);
        scenario.rocks.front().release.velocity = Vec3(0.05, 0.02, 0.0);
        scenario.rocks.front().release.spin = Vec3(-0.02, 0.05, 0.0) / 0.02;
        const Vec3 end = rest_position(scenario);
        CHECK_THAT(end.z(), WithinAbs(0.02, 2e-4));
        CHECK((end - hole.center).head<2>().norm() <= inside);
    }
}

TEST_CASE("the structured sheet contact and the sheet's mesh agree on a rolling sphere",
          "[engine][lining][verification]") {
    // A 53 mm sphere (wider than the holes' apothem: it drops onto the slope surface in each
    // hole it crosses and climbs out over the far rim) rolls 1.6 m down 10 deg over the sheet.
    // Off some lines (2 cm off the centre line, say) the rims deflect it sideways out of the
    // flume with either contact; these lines keep it along the slope.
    for (const double across : {0.0, 0.05, -0.04}) {
        double times[2] = {0.0, 0.0};
        for (const SheetContact contact : {SheetContact::structured, SheetContact::mesh}) {
            Scenario scenario = plane_scenario(10.0, shapes::RockKind::sphere, kRough, 1e-3);
            scenario.slope.segments = {{2.0, 10.0}};
            scenario.slope.width = 0.6;
            scenario.rocks.front().rock.size = 0.053;
            scenario.rocks.front().release.distance = 0.2;
            scenario.rocks.front().release.lateral = across;
            auto lining = std::make_shared<shapes::Lining>();
            lining->sheet = shapes::PerforatedSheet{};
            scenario.slope.lining = lining;
            scenario.rocks.front().release.height = 0.002 + lining->sheet->thickness;
            scenario.numerics.max_time = 4.0;
            scenario.numerics.sheet_contact = contact;
            const std::vector<RockState> states = trajectory(scenario, 1e-3);
            const Vec3 start = states.front().position;
            for (const RockState& s : states) {
                if ((s.position - start).norm() >= 1.6) {
                    times[contact == SheetContact::structured ? 0 : 1] = s.time;
                    break;
                }
            }
        }
        std::cout << "sphere rolling over the sheet " << across
                  << " m off the centre line: " << times[0] << " s structured, " << times[1]
                  << " s mesh for 1.6 m\n";
        REQUIRE(times[0] > 0.0);
        REQUIRE(times[1] > 0.0);
        CHECK_THAT(times[0], WithinRel(times[1], 0.05));
    }
}
