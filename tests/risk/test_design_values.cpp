#include "risk/design_values.hpp"

#include <catch2/catch.hpp>

#include <limits>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

namespace {

// Speeds 1, 2, ..., 20 m/s and heights 0.1, ..., 2.0 m, in a shuffled order. The type 7 95th
// percentile: h = (20 - 1) 0.95 = 18.05, so x[18] + 0.05 (x[19] - x[18]) = 19.05 m/s and
// 1.905 m.
std::vector<double> speeds() {
    std::vector<double> v;
    for (int i = 0; i < 20; ++i) v.push_back(static_cast<double>((i * 7) % 20 + 1));
    return v;
}

std::vector<double> heights() {
    std::vector<double> h;
    for (double v : speeds()) h.push_back(v / 10.0);
    return h;
}

}  // namespace

TEST_CASE("UNI design values with the default factors", "[risk][design]") {
    const DesignValues d = uni_design_values(speeds(), heights(), 1000.0);
    CHECK(d.percentile == 0.95);
    CHECK(d.speed_count == 20);
    CHECK(d.height_count == 20);
    CHECK_THAT(d.characteristic_speed, WithinRel(19.05, 1e-12));
    CHECK_THAT(d.characteristic_height, WithinRel(1.905, 1e-12));
    // gamma_Tr gamma_Dp = 1.10 x 1.10 = 1.21: v_d = 23.0505 m/s, h_d = 2.30505 m;
    // m_d = 1000 x 1.10 x 1.00 = 1100 kg; E_d = 1100 x 23.0505^2 / 2 = 292229.05 J.
    CHECK_THAT(d.design_speed, WithinRel(23.0505, 1e-12));
    CHECK_THAT(d.design_height, WithinRel(2.30505, 1e-12));
    CHECK_THAT(d.design_mass, WithinRel(1100.0, 1e-12));
    CHECK_THAT(d.design_energy, WithinRel(292229.05264, 1e-10));
}

TEST_CASE("UNI design values with the favourable factors and another percentile",
          "[risk][design]") {
    const PartialFactors calibrated{1.02, 1.02, 1.02, 1.0};
    DesignValues d = uni_design_values(speeds(), heights(), 1000.0, 0.95, calibrated);
    // 1.02 x 1.02 = 1.0404: v_d = 19.81962 m/s; E_d = 1020 x 19.81962^2 / 2 = 200336.842 J.
    CHECK_THAT(d.design_speed, WithinRel(19.81962, 1e-12));
    CHECK_THAT(d.design_height, WithinRel(1.981962, 1e-12));
    CHECK_THAT(d.design_energy, WithinRel(200336.84184, 1e-10));
    // Median: h = 9.5, 10 + 0.5 x 1 = 10.5 m/s.
    d = uni_design_values(speeds(), heights(), 1000.0, 0.5, calibrated);
    CHECK_THAT(d.characteristic_speed, WithinRel(10.5, 1e-12));
}

TEST_CASE("UNI design values reject bad input", "[risk][design]") {
    CHECK_THROWS_WITH(uni_design_values({}, heights(), 1000.0),
                      Contains("speeds: the sample is empty"));
    CHECK_THROWS_WITH(uni_design_values(speeds(), {0.1, -0.2}, 1000.0),
                      Contains("heights[1] = -0.2 m: must be finite and >= 0"));
    CHECK_THROWS_WITH(uni_design_values(speeds(), heights(), -5.0), Contains("mass = -5 kg"));
    CHECK_THROWS_WITH(uni_design_values(speeds(), heights(), 1000.0, 1.0),
                      Contains("percentile = 1") && Contains("must be in (0, 1)"));
    PartialFactors unsafe;
    unsafe.trajectory = 0.9;
    CHECK_THROWS_WITH(uni_design_values(speeds(), heights(), 1000.0, 0.95, unsafe),
                      Contains("gamma_Tr = 0.9") && Contains(">= 1"));
    CHECK_THROWS_WITH(
        uni_design_values({std::numeric_limits<double>::infinity()}, heights(), 1000.0),
        Contains("speeds[0] = inf m/s"));
}
