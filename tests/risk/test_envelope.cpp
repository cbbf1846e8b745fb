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

TEST_CASE("every impact is compared with its shape's formula", "[risk][envelope]") {
    // Two rows of the same mass and velocity: a sphere at exactly the seed preset's load and
    // a planar rock at twice its preset's load.
    ImpactRow sphere{2.5, 0.0, 10.0, ImpactShape::sphere};
    sphere.peak_force = jra_impact_force(10.0, 2.5, seed_coefficients(ImpactShape::sphere));
    ImpactRow planar{2.5, 0.0, 10.0, ImpactShape::planar};
    planar.peak_force = 2.0 * jra_impact_force(10.0, 2.5, seed_coefficients(ImpactShape::planar));
    const std::vector<ImpactRow> rows = {sphere, planar};

    const std::vector<ComparedImpact> compared = compare_with_formula(rows, EnvelopeFormula{});
    REQUIRE(compared.size() == 2);
    CHECK_THAT(compared[0].ratio, WithinRel(1.0, 1e-12));
    CHECK_THAT(compared[1].ratio, WithinRel(2.0, 1e-12));
    CHECK(ratios_of(compared, rows, ImpactShape::planar) == std::vector<double>{compared[1].ratio});
    CHECK(ratios_of(compared, rows, ImpactShape::massive).empty());
    CHECK(worst_impacts(compared, 5) == std::vector<std::size_t>{1, 0});
    CHECK(worst_impacts(compared, 1) == std::vector<std::size_t>{1});

    // An explicit beta replaces every shape's preset; jra is alpha = beta = 1 at the lambda.
    EnvelopeFormula given;
    given.beta = 1.0;
    CHECK(envelope_coefficients(given, ImpactShape::planar).beta == 1.0);
    EnvelopeFormula jra{"jra", 5e8, std::nullopt, std::nullopt};
    const ImpactCoefficients c = envelope_coefficients(jra, ImpactShape::massive);
    CHECK(c.alpha == 1.0);
    CHECK(c.beta == 1.0);
    CHECK(c.lambda == 5e8);
    EnvelopeFormula no_lambda;
    no_lambda.name = "jra";
    CHECK_THROWS_WITH(envelope_coefficients(no_lambda, ImpactShape::sphere),
                      Contains("needs lambda"));
    EnvelopeFormula unknown;
    unknown.name = "uni";
    CHECK_THROWS_WITH(envelope_coefficients(unknown, ImpactShape::sphere),
                      Contains("must be seed or jra"));
}
