// ParaView output (report/vtk_output.hpp): the .pvd lists the frames with their times, a .vtp
// holds the rocks' hulls posed by their states, the static surface holds every solid, and the
// engine's geometry hook gives the hulls of a cluster's rocks sitting in their box.

#include "report/vtk_output.hpp"
#include "scenario/scenario_file.hpp"

#include "engine/simulation.hpp"
#include "shapes/lining.hpp"
#include "shapes/release_box.hpp"

#include <catch2/catch.hpp>

#include <regex>
#include <sstream>
#include <string>
#include <vector>

using Catch::Matchers::WithinAbs;
using namespace rockfall;
using engine::RockState;
using engine::Vec3;

namespace {

// The whitespace-separated numbers of the first <DataArray ... Name="name" ...> of a VTK XML
// file (the Points array when name is empty).
std::vector<double> data_array(const std::string& xml, const std::string& name) {
    const std::string key = name.empty() ? "<Points>" : "Name=\"" + name + "\"";
    std::size_t at = xml.find(key);
    REQUIRE(at != std::string::npos);
    at = xml.find('>', xml.find("<DataArray", name.empty() ? at : xml.rfind('<', at))) + 1;
    const std::size_t end = xml.find("</DataArray>", at);
    std::istringstream in(xml.substr(at, end - at));
    std::vector<double> values;
    for (double v; in >> v;) values.push_back(v);
    return values;
}

long attribute(const std::string& xml, const std::string& name) {
    std::smatch m;
    REQUIRE(std::regex_search(xml, m, std::regex(name + "=\"([0-9]+)\"")));
    return std::stol(m[1]);
}

RockState posed(double t, const Vec3& position, const Eigen::Quaterniond& q, const Vec3& v) {
    RockState s;
    s.time = t;
    s.position = position;
    s.orientation = q;
    s.velocity = v;
    return s;
}

}  // namespace

TEST_CASE("frames are taken every interval and the .pvd lists them with their times",
          "[report][vtk]") {
    report::FrameRecorder recorder(0.02);
    // The engine samples every 10 ms; two rocks, the second gone after 30 ms.
    for (int k = 0; k <= 6; ++k) {
        const double t = 0.01 * k + 1e-4;
        recorder.add(0, posed(t, Vec3(k, 0, 0), Eigen::Quaterniond::Identity(), Vec3::Zero()));
        if (k <= 3)
            recorder.add(1, posed(t, Vec3(0, k, 0), Eigen::Quaterniond::Identity(), Vec3::Zero()));
    }
    const std::vector<report::RockFrame> frames = recorder.frames();
    REQUIRE(frames.size() == 4);
    CHECK_THAT(frames[1].time, WithinAbs(0.0201, 1e-12));
    CHECK(frames[1].rocks.at(0).position.x() == 2.0);  // the first sample of the frame
    CHECK(frames[1].rocks.size() == 2);
    CHECK(frames[3].rocks.size() == 1);

    std::vector<report::PvdEntry> entries;
    for (std::size_t k = 0; k < frames.size(); ++k) {
        entries.push_back({frames[k].time, "rocks_0000" + std::to_string(k) + ".vtp"});
    }
    std::ostringstream pvd;
    report::write_pvd(pvd, entries);
    const std::string text = pvd.str();
    CHECK(text.find("type=\"Collection\"") != std::string::npos);
    const std::regex dataset("<DataSet timestep=\"([0-9.e-]+)\"[^>]*file=\"([^\"]+)\"");
    std::vector<std::pair<double, std::string>> listed;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
         it != std::sregex_iterator(); ++it) {
        listed.emplace_back(std::stod((*it)[1]), (*it)[2]);
    }
    REQUIRE(listed.size() == 4);
    for (std::size_t k = 0; k < 4; ++k) {
        CHECK_THAT(listed[k].first, WithinAbs(frames[k].time, 1e-9));
        CHECK(listed[k].second == entries[k].file);
    }
}

TEST_CASE("a rock frame's .vtp holds every hull placed by its rock's pose", "[report][vtk]") {
    const std::vector<shapes::RockGeometry> rocks = {
        shapes::make_rock(shapes::RockKind::massive, 0.2),
        shapes::make_rock(shapes::RockKind::planar, 0.3)};
    report::RockFrame frame;
    frame.time = 0.5;
    const Eigen::Quaterniond turn(Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()));
    frame.rocks[0] = posed(0.5, Vec3(1, 2, 3), turn, Vec3(3, 4, 0));
    frame.rocks[1] = posed(0.5, Vec3(-1, 0, 0.5), Eigen::Quaterniond::Identity(), Vec3::Zero());
    const report::VtkSurface surface = report::rocks_surface(rocks, frame);
    std::ostringstream out;
    report::write_vtp(out, surface, frame.time);
    const std::string xml = out.str();

    const std::size_t points = rocks[0].hull.vertices.size() + rocks[1].hull.vertices.size();
    const std::size_t polys = rocks[0].hull.triangles.size() + rocks[1].hull.triangles.size();
    CHECK(attribute(xml, "NumberOfPoints") == static_cast<long>(points));
    CHECK(attribute(xml, "NumberOfPolys") == static_cast<long>(polys));
    const std::vector<double> xyz = data_array(xml, "");
    REQUIRE(xyz.size() == 3 * points);
    CHECK(data_array(xml, "connectivity").size() == 3 * polys);
    CHECK(data_array(xml, "offsets").back() == 3.0 * static_cast<double>(polys));
    CHECK_THAT(data_array(xml, "TimeValue").at(0), WithinAbs(0.5, 1e-12));
    // Rock 1's vertices: position + R p_body.
    for (std::size_t i = 0; i < rocks[0].hull.vertices.size(); ++i) {
        const Vec3 expected = Vec3(1, 2, 3) + turn.toRotationMatrix() * rocks[0].hull.vertices[i];
        for (int d = 0; d < 3; ++d) CHECK_THAT(xyz[3 * i + d], WithinAbs(expected[d], 1e-8));
    }
    const std::vector<double> rock = data_array(xml, "rock");
    const std::vector<double> speed = data_array(xml, "speed_m_s");
    REQUIRE(rock.size() == polys);
    CHECK(rock.front() == 1.0);
    CHECK(rock.back() == 2.0);
    CHECK_THAT(speed.front(), WithinAbs(5.0, 1e-12));
    CHECK(speed.back() == 0.0);
}

TEST_CASE("the static surface holds the slope's solids, the lining and the extra walls",
          "[report][vtk]") {
    engine::Scenario scenario;
    scenario.slope.segments = {{1.0, 30.0}, {1.0, 0.0}};
    scenario.slope.width = 0.4;
    scenario.slope.wall.distance_from_toe = 0.5;
    scenario.slope.bars.enabled = false;
    scenario.slope.bars.segments.clear();
    auto lining = std::make_shared<shapes::Lining>();
    lining->spheres = shapes::SphereLayer{0.02, 0.04, {0}};
    lining->sheet = shapes::PerforatedSheet{};
    lining->sheet->segments = {1};
    scenario.slope.lining = lining;
    const shapes::Slope slope(scenario.slope);
    const std::vector<shapes::Sphere> spheres = shapes::lining_spheres(slope, *lining);
    const shapes::SheetMesh sheet = shapes::perforated_sheet(slope, *lining->sheet);
    const shapes::OrientedBox extra = slope.solids().front();

    const report::VtkSurface surface = report::static_surface(scenario, {extra});
    const std::size_t boxes = slope.solids().size() + 1;
    CHECK(surface.triangles.size() ==
          12 * boxes + 20 * spheres.size() + sheet.mesh.triangles.size());
    std::ostringstream out;
    report::write_vtp(out, surface, std::nan(""));
    const std::string xml = out.str();
    CHECK(xml.find("TimeValue") == std::string::npos);
    const std::vector<double> part = data_array(xml, "part");
    REQUIRE(part.size() == surface.triangles.size());
    const auto count = [&part](report::ScenePart p) {
        return std::count(part.begin(), part.end(), static_cast<double>(static_cast<int>(p)));
    };
    CHECK(count(report::ScenePart::lining_sphere) == static_cast<long>(20 * spheres.size()));
    CHECK(count(report::ScenePart::sheet) == static_cast<long>(sheet.mesh.triangles.size()));
    CHECK(count(report::ScenePart::release_box) == 12);
    CHECK(count(report::ScenePart::reaction_wall) == 12);
    // Every icosahedron vertex lies on its sphere.
    const std::vector<double> xyz = data_array(xml, "");
    const std::size_t first = 3 * 8 * boxes;
    const Vec3 v(xyz[first], xyz[first + 1], xyz[first + 2]);
    CHECK_THAT((v - spheres.front().center).norm(), WithinAbs(spheres.front().radius, 1e-8));
}

TEST_CASE("the engine gives a cluster's rock geometries, which sit in the box at t = 0",
          "[report][vtk][engine]") {
    // Seed 001's lined flume at 45 deg with 6 rocks of its cluster, just past the gate's opening.
    engine::Scenario scenario =
        scenario::load_scenario(ROCKFALL_SAMPLES_DIR "/flume_45.toml").scenario;
    scenario.cluster->grading.count = 6;
    scenario.numerics.max_time = 0.05;

    engine::RunGeometry geometry;
    report::FrameRecorder frames(0.02);
    engine::RunOptions options;
    options.geometry = [&geometry](const engine::RunGeometry& g) { geometry = g; };
    options.trajectory = [&frames](int rock, const RockState& s) { frames.add(rock, s); };
    const engine::Outcome outcome = engine::simulate(scenario, 3, options);
    REQUIRE(geometry.rocks.size() == outcome.rocks.size());
    REQUIRE(geometry.rocks.size() == 6);
    REQUIRE(geometry.solids.size() == 1);  // the box's back wall
    for (std::size_t i = 0; i < 6; ++i) {
        CHECK_THAT(geometry.rocks[i].nominal_size, WithinAbs(outcome.rocks[i].size, 1e-12));
    }
    const report::RockFrame first = frames.frames().front();
    REQUIRE(first.time == 0.0);
    const report::VtkSurface surface = report::rocks_surface(geometry.rocks, first);
    // Every hull vertex inside the box, settled in it. 2 mm slack: twice the hulls' 1 mm
    // collision margin (the drawn hull's sharp corners stand out of the margin-rounded collision
    // shape by up to (sqrt(3) - 1) margin at a cube's corner, more at sharper ones). The box's
    // floor is the sphere layer's top, and a corner sinks into the hollows between its spheres
    // (3.6 mm seen with seed 3; a 1 mm-rounded point passes between three 8 mm spheres at 16 mm
    // spacing), so the floor's bound is the layer's base; but no corner is inside a sphere.
    const shapes::Slope slope(scenario.slope);
    const std::vector<shapes::Sphere> spheres =
        shapes::lining_spheres(slope, *scenario.slope.lining);
    REQUIRE(!spheres.empty());
    const double radius = spheres.front().radius;
    shapes::OrientedBox box = shapes::release_box_region(slope, scenario.cluster->box);
    box.half_extents += Vec3::Constant(2e-3);
    // The floor is the box's -z face (its local z is the slope's normal).
    box.center -= box.rotation.col(2) * radius;
    box.half_extents.z() += radius;
    for (const Vec3& p : surface.points) {
        CHECK(shapes::signed_distance(box, p) <= 0.0);
        for (const shapes::Sphere& sphere : spheres) {
            if ((p - sphere.center).norm() < sphere.radius - 2e-3) {
                FAIL_CHECK("a hull corner " << sphere.radius - (p - sphere.center).norm()
                                            << " m inside a lining sphere");
            }
        }
    }
    // The back wall lies against the box's upslope face, outside it.
    CHECK(shapes::signed_distance(box, geometry.solids.front().center) > 0.0);
}
