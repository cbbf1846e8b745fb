#include "risk/envelope.hpp"

#include <catch2/catch.hpp>

#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

TEST_CASE("envelope statistics of known ratios", "[risk][envelope]") {
    // 0.1, 0.2, ..., 2.0 in reverse: 10 are above 1 (1.0 itself is on the envelope, not
    // above). Median (1.0 + 1.1) / 2; p95: h = 19 x 0.95 = 18.05, 1.9 + 0.05 x 0.1 = 1.905.
    std::vector<double> ratios;
    for (int i = 20; i >= 1; --i) ratios.push_back(0.1 * i);
    const EnvelopeStats s = envelope_stats(ratios);
    CHECK(s.count == 20);
    CHECK(s.above == 10);
    CHECK(s.share == 0.5);
    const Interval wilson = wilson_interval(10, 20, 0.95);
    CHECK(s.interval.lower == wilson.lower);
    CHECK(s.interval.upper == wilson.upper);
    // Wilson for 10 / 20 at 95 %: 0.5 -+ 0.2007.
    CHECK_THAT(s.interval.lower, WithinRel(0.29929, 1e-4));
    CHECK_THAT(s.min, WithinRel(0.1, 1e-12));
    CHECK_THAT(s.max, WithinRel(2.0, 1e-12));
    CHECK_THAT(s.mean, WithinRel(1.05, 1e-12));
    CHECK_THAT(s.median, WithinRel(1.05, 1e-12));
    CHECK_THAT(s.p95, WithinRel(1.905, 1e-12));
}

TEST_CASE("envelope statistics reject bad ratios", "[risk][envelope]") {
    CHECK_THROWS_WITH(envelope_stats({}), Contains("no ratios"));
    CHECK_THROWS_WITH(envelope_stats({0.5, -1.0}), Contains("ratio[1] = -1"));
    CHECK_THROWS_WITH(envelope_stats({0.5}, 1.5), Contains("confidence"));
}
