#include "helpers.hpp"

#include "mpm/load_window.hpp"
#include "mpm/soil.hpp"
#include "mpm/vtk.hpp"
#include "shapes/slope.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numeric>
#include <stdexcept>
#include <string>

using namespace rockfall::mpm;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

// The seed flow in 2D with the wall 0.5 m past the toe, so that the soil reaches it.
SoilScenario quick_2d() { return test::quick_2d(0.2); }

}  // namespace

TEST_CASE("Soil scenario defaults are the seed's Table 1", "[mpm][soil]") {
    const SoilScenario s;
    CHECK(s.material.youngs_modulus == 1.0e6);
    CHECK(s.density == 1640.0);
    CHECK(s.material.poisson_ratio == 0.30);
    CHECK(s.material.friction_angle_deg == 34.6);
    CHECK(s.material.dilatancy_angle_deg == 0.0);
    CHECK(s.material.cohesion == 2100.0);
    CHECK(s.material.tensile_strength == 0.0);
    CHECK(s.boundaries.basal_friction_angle_deg == 30.0);
    CHECK(s.numerics.cell_size == 0.20);
    CHECK(s.release.bed_angle_deg == 66.0);
    CHECK_NOTHROW(validate(s));
}

TEST_CASE("Soil scenario validation lists every problem", "[mpm][soil]") {
    SoilScenario s;
    s.release.thickness = -0.1;
    s.numerics.dimension = 4;
    s.material.poisson_ratio = 0.7;
    try {
        validate(s);
        FAIL("validate accepted an invalid scenario");
    } catch (const std::invalid_argument& e) {
        const std::string what = e.what();
        CHECK_THAT(what, Catch::Contains("release.thickness = -0.1 m: must be > 0"));
        CHECK_THAT(what, Catch::Contains("numerics.dimension = 4: must be 2 or 3"));
        CHECK_THAT(what, Catch::Contains("material.poisson_ratio"));
    }
}

TEST_CASE("Window means of a step history are exact at any width and position", "[mpm][soil]") {
    // Steps of 0.1 s: 0 until 0.3 s, then a 0.1 s impact of 10, then 2 to the end (1.0 s).
    const std::vector<double> ends{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0};
    const std::vector<double> load{0, 0, 0, 10, 2, 2, 2, 2, 2, 2};
    const StepHistory<double> h(ends, load, 0.0);
    CHECK(h.end() == 1.0);
    CHECK_THAT(h.integral(0.35), WithinAbs(0.5, 1e-12));
    CHECK_THAT(h.integral(2.0), WithinAbs(2.2, 1e-12));
    // Clipped at the start: [0, 0.35] holds 0.5 over 0.35 s.
    CHECK_THAT(h.window_mean(0.1, 0.5), WithinRel(0.5 / 0.35, 1e-12));
    CHECK_THAT(h.window_mean(0.9, 0.2), WithinRel(2.0, 1e-12));
    // A 0.1 s window finds the impact whatever a sample grid would do: a grid with a boundary
    // at 0.35 s reads 6 in both halves.
    const WindowPeak narrow = peak_window_mean(h, 0.1);
    CHECK_THAT(narrow.value, WithinRel(10.0, 1e-12));
    CHECK_THAT(narrow.centre, WithinAbs(0.35, 1e-12));
    // 0.25 s: the whole impact plus 0.15 s of the rest, (1 + 0.3) / 0.25 = 5.2.
    CHECK_THAT(peak_window_mean(h, 0.25).value, WithinRel(5.2, 1e-12));
    // Longer than the run: its mean.
    const WindowPeak whole = peak_window_mean(h, 3.0);
    CHECK_THAT(whole.value, WithinRel(2.2, 1e-12));
    CHECK_THAT(whole.centre, WithinAbs(0.5, 1e-12));
    // Unequal steps, vectors.
    const std::vector<double> uneven{0.05, 0.3, 0.31};
    const std::vector<Vec3> loads{Vec3(1, 0, 0), Vec3(0, 4, 0), Vec3(0, 0, 100)};
    const StepHistory<Vec3> v(uneven, loads, Vec3::Zero());
    CHECK((v.window_mean(0.155, 0.31) - Vec3(0.05, 1.0, 1.0) / 0.31).norm() < 1e-12);
    CHECK_THROWS_AS(StepHistory<double>({0.1, 0.1}, {1.0, 2.0}, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(StepHistory<double>({0.1}, {1.0, 2.0}, 0.0), std::invalid_argument);
    CHECK_THROWS_AS(peak_window_mean(h, 0.0), std::invalid_argument);
    // A step that blew up: the windows before it still count.
    const StepHistory<double> blown({0.1, 0.2, 0.3}, {4.0, 1.0, std::nan("")}, 0.0);
    CHECK_THAT(peak_window_mean(blown, 0.1).value, WithinRel(4.0, 1e-12));
}

TEST_CASE("Quick 2D soil flow loads the wall and heaps against it", "[mpm][soil]") {
    const SoilScenario s = quick_2d();
    int frames = 0;
    const SoilOutcome o = run_soil(s, [&](const ParticleFrame& f) {
        CHECK(f.position.size() == f.mass.size());
        ++frames;
    });
    REQUIRE(o.status == SoilStatus::completed);
    CHECK(o.dimension == 2);
    CHECK(frames == 51);
    CHECK_THAT(o.mass, WithinRel(s.density * s.release.length * s.release.thickness, 1e-12));
    REQUIRE(o.sample_time.size() == 500);
    CHECK(o.wall_impulse > 0.0);
    // The sampled load carries the whole impulse.
    const double sampled =
        std::accumulate(o.wall_force.begin(), o.wall_force.end(), 0.0) * s.output.sample_interval;
    CHECK_THAT(sampled, WithinRel(o.wall_impulse, 1e-9));
    // The peaks are taken over every window position: at least what the sample grid reads.
    CHECK(o.peak_wall_force > 0.0);
    CHECK(o.peak_wall_force >= *std::max_element(o.wall_force.begin(), o.wall_force.end()));
    CHECK(o.peak_wall_force_filtered <= o.peak_wall_force);
    const double interior_filtered =
        *std::max_element(o.wall_force_filtered.begin() + 5, o.wall_force_filtered.end() - 5);
    CHECK(o.peak_wall_force_filtered >= interior_filtered);
    // The filter is 0.05 s wide: centred on a sample's middle it spans that sample and two on
    // either side (a rounding of the half-width once made it seven samples).
    REQUIRE(s.output.filter_window == 0.05);
    for (std::size_t k = 2; k + 2 < o.wall_force.size(); ++k) {
        const double five = (o.wall_force[k - 2] + o.wall_force[k - 1] + o.wall_force[k] +
                             o.wall_force[k + 1] + o.wall_force[k + 2]) /
                            5.0;
        CHECK_THAT(o.wall_force_filtered[k], WithinAbs(five, 1e-9 * o.peak_wall_force));
    }
    // The load vectors: x is the normal load above, nothing acts across a plane-strain section,
    // and the fixed (no-slip) wall also takes shear along its face.
    REQUIRE(o.wall_load.size() == o.wall_force.size());
    REQUIRE(o.wall_load_filtered.size() == o.wall_force.size());
    REQUIRE(o.step_wall_load.size() == o.step_wall_force.size());
    double largest_shear = 0.0;
    for (std::size_t k = 0; k < o.wall_force.size(); ++k) {
        CHECK(o.wall_load[k].x() == o.wall_force[k]);
        CHECK(o.wall_load_filtered[k].x() == o.wall_force_filtered[k]);
        CHECK(o.wall_load[k].y() == 0.0);
        largest_shear = std::max(largest_shear, std::abs(o.wall_load[k].z()));
    }
    CHECK(largest_shear > 0.01 * o.peak_wall_force);
    // The soil stops against the wall.
    const rockfall::shapes::Slope slope(s.slope);
    CHECK(o.deposit.runout_x <= slope.wall_x() + 0.05);
    CHECK(o.deposit.runout_x > slope.toe_x());
    CHECK(o.centre_of_mass.back().z() < o.centre_of_mass.front().z() - 5.0);
    CHECK(o.kinetic_energy.back() <
          1e-3 * *std::max_element(o.kinetic_energy.begin(), o.kinetic_energy.end()));
    const double height =
        *std::max_element(o.deposit.profile_height.begin(), o.deposit.profile_height.end());
    CHECK(height > s.release.thickness);
}

TEST_CASE("A tilting bed holds the soil until it is steeper than the bed friction", "[mpm][soil]") {
    SoilScenario s = quick_2d();
    s.release.initial_bed_angle_deg = 0.0;
    s.release.tilt_duration = 3.0;
    s.output.duration = 3.0;
    s.output.sample_interval = 0.05;
    const SoilOutcome o = run_soil(s);
    REQUIRE(o.status == SoilStatus::completed);
    // Until 22 deg (t = 1 s) the soil turns with the bed: its centre of mass keeps its distance
    // from the hinge (the crown) and stays behind it.
    const rockfall::shapes::Slope slope(s.slope);
    const Vec3 hinge(0.0, 0.0, slope.profile().front().y());
    const double start = (o.centre_of_mass.front() - hinge).norm();
    const std::size_t one_second = 19;
    REQUIRE(o.sample_time[one_second] == Approx(1.0));
    WARN("distance from the hinge: " << start << " m at 0 s, "
                                     << (o.centre_of_mass[one_second] - hinge).norm()
                                     << " m at 1 s; x at 3 s: " << o.centre_of_mass.back().x());
    CHECK_THAT((o.centre_of_mass[one_second] - hinge).norm(), WithinRel(start, 0.02));
    CHECK(o.centre_of_mass[one_second].x() < hinge.x());
    // By the end (66 deg) it has slid off the bed onto the slope.
    CHECK(o.centre_of_mass.back().x() > hinge.x());
}

TEST_CASE("No soil leaks under the slope at the bed's hinge", "[mpm][soil]") {
    // The 66 deg bed and the 43 deg first segment, each box ending normal to its surface, left
    // a 23 deg wedge open below the hinge: at 0.05 m cells and 4 particles per cell edge the
    // soil turning onto the slope fell through it (and the run blew up at about 1 s). The bed's
    // continuation at its steepest angle closes it.
    SoilScenario s = quick_2d();
    s.numerics.cell_size = 0.05;
    s.numerics.particles_per_cell = 4;
    s.output.duration = 1.2;
    s.output.frame_interval = 0.1;
    const rockfall::shapes::Slope slope(s.slope);
    double deepest = 0.0;  // how far below the slope's surface a particle got, m
    int frames = 0;
    const SoilOutcome o = run_soil(s, [&](const ParticleFrame& f) {
        ++frames;
        for (const Vec3& x : f.position) {
            if (x.x() > slope.profile().front().x()) {
                deepest = std::max(deepest, slope.surface_height(x.x()) - x.z());
            }
        }
    });
    REQUIRE(o.status == SoilStatus::completed);
    CHECK(frames == 13);
    WARN("deepest particle below the slope surface: " << deepest << " m");
    // Particles act on the nodes around them, so they may sit up to a cell inside the
    // boundary's node layer, never further.
    CHECK(deepest < s.numerics.cell_size);
}

TEST_CASE("3D seed flow leaves the bed and moves down the slope", "[mpm][soil]") {
    SoilScenario s;
    s.numerics.threads = 1;
    s.output.duration = 1.0;
    const SoilOutcome o = run_soil(s);
    REQUIRE(o.status == SoilStatus::completed);
    CHECK(o.dimension == 3);
    CHECK(o.particles == 35 * 29 * 3);
    CHECK(o.centre_of_mass.back().x() > o.centre_of_mass.front().x() + 0.5);
    CHECK_THAT(o.centre_of_mass.back().y(), WithinAbs(0.0, 1e-6));
    CHECK(o.front_x.back() > 1.0);
}

TEST_CASE("VTK writer: legacy binary POLYDATA of the expected size", "[mpm][soil]") {
    ParticleFrame frame;
    frame.time = 1.5;
    for (int i = 0; i < 3; ++i) {
        frame.position.emplace_back(i, 0.0, 1.0);
        frame.velocity.emplace_back(0.0, 0.0, -i);
        frame.mass.push_back(1.0);
        frame.mean_stress.push_back(-100.0);
        frame.deviatoric_stress.push_back(50.0);
        frame.plastic_shear_strain.push_back(0.0);
    }
    const auto path = std::filesystem::temp_directory_path() / "rockfall_mpm_test_frame.vtk";
    write_vtk(path, frame);
    std::ifstream in(path, std::ios::binary);
    std::string first;
    std::string second;
    std::getline(in, first);
    std::getline(in, second);
    CHECK(first == "# vtk DataFile Version 3.0");
    CHECK_THAT(second, Catch::Contains("t = 1.5 s"));
    // Points and velocities (3 x 3 doubles each), vertices (3 x 2 int32), 4 scalar fields.
    const auto binary = 2 * 3 * 3 * 8 + 3 * 2 * 4 + 4 * 3 * 8;
    CHECK(std::filesystem::file_size(path) > static_cast<std::uintmax_t>(binary));
    CHECK(std::filesystem::file_size(path) < static_cast<std::uintmax_t>(binary + 400));
    std::filesystem::remove(path);
    CHECK_THROWS_AS(write_vtk("/nonexistent-dir/frame.vtk", frame), std::runtime_error);
}
