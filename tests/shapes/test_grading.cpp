#include "shapes/grading.hpp"
#include "shapes/random.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <stdexcept>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using rockfall::shapes::Grading;
using rockfall::shapes::GradingStats;
using rockfall::shapes::make_generator;

namespace {

struct Mean {
    double d50 = 0.0;
    double cu = 0.0;
    // Standard errors of the means, from the spread over the clusters.
    double d50_error = 0.0;
    double cu_error = 0.0;
};

// The grading of `clusters` clusters drawn with seeds 0, 1, ...: means of d50 and Cu.
Mean mean_grading(const Grading& grading, int clusters) {
    double sum50 = 0.0, square50 = 0.0, sumcu = 0.0, squarecu = 0.0;
    for (int seed = 0; seed < clusters; ++seed) {
        auto generator = make_generator(static_cast<std::uint64_t>(seed));
        const std::vector<double> sizes = cluster_sizes(grading, generator);
        REQUIRE(static_cast<int>(sizes.size()) == grading.count);
        for (const double d : sizes) {
            REQUIRE(d >= grading.d_min);
            REQUIRE(d <= grading.d_max);
        }
        const GradingStats stats = rockfall::shapes::grading_of(sizes);
        sum50 += stats.d50;
        square50 += stats.d50 * stats.d50;
        sumcu += stats.cu;
        squarecu += stats.cu * stats.cu;
    }
    const double n = clusters;
    Mean mean;
    mean.d50 = sum50 / n;
    mean.cu = sumcu / n;
    mean.d50_error = std::sqrt((square50 / n - mean.d50 * mean.d50) / (n - 1.0));
    mean.cu_error = std::sqrt((squarecu / n - mean.cu * mean.cu) / (n - 1.0));
    return mean;
}

}  // namespace

TEST_CASE("grading_of interpolates the mass-passing curve as documented", "[grading]") {
    // Rocks of 1 m and 2 m: mass fractions 1/9 and 8/9, plotted at 1/18 and 1/9 + 4/9.
    const GradingStats two = rockfall::shapes::grading_of({2.0, 1.0});
    const auto at = [](double p) {
        const double t = (p - 1.0 / 18.0) / (5.0 / 9.0 - 1.0 / 18.0);
        return std::pow(2.0, t);
    };
    CHECK_THAT(two.d10, WithinRel(at(0.10), 1e-12));
    CHECK_THAT(two.d30, WithinRel(at(0.30), 1e-12));
    CHECK_THAT(two.d50, WithinRel(at(0.50), 1e-12));
    CHECK_THAT(two.d60, WithinRel(2.0, 1e-12));  // beyond the last plotted point
    CHECK_THAT(two.cu, WithinRel(2.0 / at(0.10), 1e-12));
    CHECK_THAT(two.cc, WithinRel(at(0.30) * at(0.30) / (at(0.10) * 2.0), 1e-12));
    CHECK(two.count == 2);
    CHECK_THAT(two.total_volume, WithinRel(std::numbers::pi / 6.0 * 9.0, 1e-12));

    const GradingStats same = rockfall::shapes::grading_of({0.05, 0.05, 0.05});
    CHECK_THAT(same.d10, WithinRel(0.05, 1e-12));
    CHECK_THAT(same.cu, WithinRel(1.0, 1e-12));
    CHECK_THAT(same.cc, WithinRel(1.0, 1e-12));

    CHECK_THROWS_WITH(rockfall::shapes::grading_of({}), Contains("no rock sizes"));
    CHECK_THROWS_WITH(rockfall::shapes::grading_of({0.05, -0.01}),
                      Contains("size[1] = -0.01 m: must be finite and > 0"));
}

TEST_CASE("the fitted grading model passes d50 at half the mass", "[grading]") {
    for (const Grading& grading :
         {rockfall::shapes::seed001_c1(), rockfall::shapes::seed001_c2()}) {
        const auto model = rockfall::shapes::grading_model(grading);
        CHECK_THAT(mass_passing(model, grading.d50), WithinAbs(0.5, 1e-9));
        CHECK(mass_passing(model, grading.d_min) == 0.0);
        CHECK(mass_passing(model, grading.d_max) == 1.0);
        // Cu 1.52 over 1.5349 standard deviations (z(0.6) - z(0.1)) of ln d untruncated gives
        // sigma 0.273; the truncation cuts the tails, so the fit widens it.
        CHECK(model.sigma > std::log(1.52) / 1.5349);
        CHECK(model.sigma < 0.35);
    }
}

TEST_CASE("a large cluster follows its grading", "[grading][verification]") {
    // 100000 rocks: the standard errors of d50 and Cu are about 0.15 % (the spread over
    // 99-rock clusters, 4.7 % and 4.8 %, over sqrt(1000)); 0.6 % is four of them.
    for (Grading grading : {rockfall::shapes::seed001_c1(), rockfall::shapes::seed001_c2()}) {
        grading.count = rockfall::shapes::max_cluster_rocks;
        auto generator = make_generator(7);
        const GradingStats stats = rockfall::shapes::grading_of(cluster_sizes(grading, generator));
        CHECK_THAT(stats.d50, WithinRel(grading.d50, 0.006));
        CHECK_THAT(stats.cu, WithinRel(grading.cu, 0.006));
    }
}

TEST_CASE("clusters C1 and C2 match d50 and Cu over 200 seeds", "[grading][verification]") {
    // Over 200 clusters the standard error of the mean d50 and Cu is under 0.5 % (per-cluster
    // spread 4.7 to 6.5 %); 2 % allows four standard errors and the small-sample bias of the
    // plotting-position estimate (Cu of 53 rocks reads about 0.3 % low).
    for (const Grading& grading :
         {rockfall::shapes::seed001_c1(), rockfall::shapes::seed001_c2()}) {
        const Mean mean = mean_grading(grading, 200);
        CHECK(4.0 * mean.d50_error < 0.02 * grading.d50);
        CHECK(4.0 * mean.cu_error < 0.02 * grading.cu);
        CHECK_THAT(mean.d50, WithinRel(grading.d50, 0.02));
        CHECK_THAT(mean.cu, WithinRel(grading.cu, 0.02));
    }
}

TEST_CASE("cluster sizes are reproducible from the seed", "[grading]") {
    const Grading grading = rockfall::shapes::seed001_c2();
    auto first = make_generator(42);
    auto again = make_generator(42);
    auto other = make_generator(43);
    const std::vector<double> a = cluster_sizes(grading, first);
    CHECK(a == cluster_sizes(grading, again));
    CHECK(a != cluster_sizes(grading, other));
}

TEST_CASE("a cluster by volume stops nearest the volume", "[grading]") {
    Grading grading = rockfall::shapes::seed001_c2();
    grading.count = 0;
    grading.total_volume = 0.010;
    const double largest = std::numbers::pi / 6.0 * std::pow(grading.d_max, 3);
    for (std::uint64_t seed = 0; seed < 50; ++seed) {
        auto generator = make_generator(seed);
        const std::vector<double> sizes = cluster_sizes(grading, generator);
        const GradingStats stats = rockfall::shapes::grading_of(sizes);
        // Off by at most half the rock that crossed the volume.
        REQUIRE(std::abs(stats.total_volume - grading.total_volume) <= 0.5 * largest);
        // About 0.010 m3 / 5.8e-5 m3 (the mean C2 rock) = 171 rocks.
        REQUIRE(stats.count > 120);
        REQUIRE(stats.count < 240);
        // The same draws by count give the same rocks.
        Grading by_count = rockfall::shapes::seed001_c2();
        by_count.count = stats.count;
        auto again = make_generator(seed);
        REQUIRE(cluster_sizes(by_count, again) == sizes);
    }
    // A volume below one rock still gives one rock.
    grading.total_volume = 1e-9;
    auto generator = make_generator(1);
    CHECK(cluster_sizes(grading, generator).size() == 1);
}

TEST_CASE("bad gradings name the field, value and range", "[grading]") {
    auto generator = make_generator(1);
    Grading grading;
    grading.cu = 0.9;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.cu = 0.9: must be in (1, 1.79"));
    grading.cu = 2.5;
    CHECK_THROWS_AS(cluster_sizes(grading, generator), std::invalid_argument);
    grading = Grading{};
    grading.d50 = 0.12;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.d50 = 0.12 m: must be in (d_min, d_max) = (0.03, 0.1) m"));
    grading = Grading{};
    grading.total_volume = 0.01;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.count = 99 and grading.total_volume = 0.01 m3: give "
                               "exactly one of them"));
    grading.count = 0;
    grading.total_volume = 0.0;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator), Contains("give exactly one of them"));
    grading.total_volume = -1.0;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.total_volume = -1 m3: must be finite and > 0"));
    grading.total_volume = 1000.0;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator), Contains("more than 100000"));
    grading = Grading{};
    grading.count = -3;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.count = -3: must be in [1, 100000]"));
    grading = Grading{};
    grading.d_min = 0.0;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.d_min = 0 m: must be in [0.001, 100] m"));
    grading = Grading{};
    grading.d_max = 0.03;
    CHECK_THROWS_WITH(cluster_sizes(grading, generator),
                      Contains("grading.d_max = 0.03 m: must be larger than d_min = 0.03 m"));
}
