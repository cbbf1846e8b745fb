#include "risk/impact_fit.hpp"
#include "risk/impact_identification.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

using Catch::Matchers::Contains;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;
using namespace rockfall::risk;

namespace {

// Standard normal deviates by Box-Muller from a fixed mt19937_64 stream, so the synthetic
// data are the same with every standard library.
class Normal {
  public:
    explicit Normal(std::uint64_t seed) : engine_(seed) {}
    double operator()() {
        const double u1 = uniform();
        const double u2 = uniform();
        return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
    }

  private:
    // In (0, 1]: 53 random bits, shifted off zero.
    double uniform() { return (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53; }
    std::mt19937_64 engine_;
};

// n rows with velocities spread evenly over [3, 10] m/s, masses alternating between the
// given ones, loads alpha beta P_JRA(lambda) exp(sigma z) with sigma = ln(alpha): the mean of
// ln P is the formula's with alpha = 1 and the mean + 1 sigma line is alpha times it.
std::vector<ImpactRow> synthetic(int n, ImpactCoefficients truth, std::vector<double> masses,
                                 bool noisy) {
    Normal normal(20240601);
    const double sigma = std::log(truth.alpha);
    const ImpactCoefficients mean_formula{truth.lambda, 1.0, truth.beta};
    std::vector<ImpactRow> rows;
    for (int i = 0; i < n; ++i) {
        const double v = 3.0 + 7.0 * i / (n - 1);
        const double m = masses[static_cast<std::size_t>(i) % masses.size()];
        const double scatter = noisy ? std::exp(sigma * normal()) : 1.0;
        rows.push_back({v, jra_impact_force(m, v, mean_formula) * scatter, m, ImpactShape::sphere});
    }
    return rows;
}

}  // namespace

TEST_CASE("linear regression matches a hand computation", "[risk][fit]") {
    // x = 1..4, y = 2, 4, 5, 8: Sxx = 5, Sxy = 9.5, slope 1.9, intercept 4.75 - 1.9 x 2.5 = 0;
    // residuals 0.1, 0.2, -0.7, 0.4: SSR = 0.70, sd = sqrt(0.70 / 2) = 0.591608;
    // Syy = 18.75, R^2 = 1 - 0.70 / 18.75 = 0.962667.
    const ImpactRegression r = fit_regression({1, 2, 3, 4}, {2, 4, 5, 8}, RegressionForm::linear);
    CHECK_THAT(r.a, WithinAbs(0.0, 1e-12));
    CHECK_THAT(r.b, WithinRel(1.9, 1e-12));
    CHECK_THAT(r.sigma, WithinRel(std::sqrt(0.35), 1e-12));
    CHECK_THAT(r.r_squared, WithinRel(1.0 - 0.70 / 18.75, 1e-12));
    CHECK_THAT(r.mean(2.0), WithinRel(3.8, 1e-12));
    CHECK_THAT(r.upper(2.0), WithinRel(3.8 + std::sqrt(0.35), 1e-12));
}

TEST_CASE("power regression recovers an exact power law", "[risk][fit]") {
    std::vector<double> v;
    std::vector<double> p;
    for (double x = 2.0; x <= 10.0; x += 1.0) {
        v.push_back(x);
        p.push_back(2000.0 * std::pow(x, 1.2));
    }
    const ImpactRegression r = fit_regression(v, p, RegressionForm::power);
    CHECK_THAT(r.a, WithinRel(2000.0, 1e-12));
    CHECK_THAT(r.b, WithinRel(1.2, 1e-12));
    CHECK_THAT(r.sigma, WithinAbs(0.0, 1e-12));
    CHECK_THAT(r.r_squared, WithinRel(1.0, 1e-12));
    CHECK_THAT(r.upper(5.0), WithinRel(r.mean(5.0), 1e-12));
}

TEST_CASE("fit recovers lambda exactly from noise-free data of two masses", "[risk][fit]") {
    // 10.5 kg and 84 kg (8x, so 4x the load): the m^(2/3) scaling must bring them together.
    const ImpactFit fit = fit_impacts(synthetic(40, {3.0e8, 1.0, 1.0}, {10.5, 84.0}, false));
    CHECK(fit.count == 40);
    CHECK(fit.lambda_identified);
    CHECK_THAT(fit.reference_mass, WithinRel(47.25, 1e-12));  // median of 20 x 10.5, 20 x 84
    CHECK_THAT(fit.coefficients.lambda, WithinRel(3.0e8, 1e-9));
    CHECK_THAT(fit.coefficients.alpha, WithinRel(1.0, 1e-9));
    CHECK(fit.coefficients.beta == 1.0);
    CHECK_THAT(fit.regression.b, WithinRel(1.2, 1e-9));  // P ~ v^(6/5)
    CHECK_THAT(fit.mean_mismatch, WithinAbs(0.0, 1e-9));
    CHECK_THAT(fit.velocity_min, WithinRel(3.0, 1e-12));
    CHECK_THAT(fit.velocity_max, WithinRel(10.0, 1e-12));
    CHECK(fit.mass_min == 10.5);
    CHECK(fit.mass_max == 84.0);
}

TEST_CASE("fit recovers lambda and alpha from noisy synthetic data", "[risk][fit][verification]") {
    // lambda = 500 MN/m2 and alpha = 1.3 (seed 000's sphere), 400 rows, sigma(ln P) = ln 1.3.
    // ln kappa is the mean of n residuals: sd sigma / sqrt(n) = 0.0131, and lambda ~ kappa^2.5,
    // so sd(ln lambda) = 0.033: 10 % is three of them. alpha = exp(sigma_hat) with
    // sd(sigma_hat) = sigma / sqrt(2 (n - 2)) = 0.0093: 4 % is more than three.
    const ImpactFit fit = fit_impacts(synthetic(400, {5.0e8, 1.3, 1.0}, {10.5}, true));
    CHECK_THAT(fit.coefficients.lambda, WithinRel(5.0e8, 0.10));
    CHECK_THAT(fit.coefficients.alpha, WithinRel(1.3, 0.04));
    CHECK_THAT(fit.regression.sigma, WithinRel(std::log(1.3), 0.04));
    CHECK_THAT(fit.regression.b, WithinAbs(1.2, 0.1));
    // The power regression's band is proportional, so alpha = exp(sigma) exactly.
    CHECK_THAT(fit.coefficients.alpha, WithinRel(std::exp(fit.regression.sigma), 1e-12));
    CHECK(fit.regression.r_squared > 0.5);
    CHECK(fit.regression.r_squared < 1.0);
}

TEST_CASE("fit with lambda fixed identifies beta, then alpha", "[risk][fit]") {
    // Seed 000's massive rock: lambda 500 MN/m2, beta 0.5, alpha 1.6.
    FitOptions options;
    options.lambda = 5.0e8;
    const ImpactFit exact = fit_impacts(synthetic(30, {5.0e8, 1.6, 0.5}, {12.0}, false), options);
    CHECK_FALSE(exact.lambda_identified);
    CHECK(exact.coefficients.lambda == 5.0e8);
    CHECK_THAT(exact.coefficients.beta, WithinRel(0.5, 1e-9));

    const ImpactFit noisy = fit_impacts(synthetic(400, {5.0e8, 1.6, 0.5}, {12.0}, true), options);
    // beta ~ kappa: sd(ln beta) = ln(1.6) / sqrt(400) = 0.0235; 8 % is more than three.
    CHECK_THAT(noisy.coefficients.beta, WithinRel(0.5, 0.08));
    CHECK_THAT(noisy.coefficients.alpha, WithinRel(1.6, 0.05));
    CHECK_THAT(noisy.envelope(8.0),
               WithinRel(jra_impact_force(12.0, 8.0, noisy.coefficients), 1e-12));
}

TEST_CASE("linear regression identification stays close to a near-straight formula",
          "[risk][fit]") {
    // Noise-free P ~ v^1.2 on [3, 10] m/s is close to a line; the log least-squares match of
    // the formula to that line recovers lambda to within the curvature the line cannot follow
    // (measured: the formula is 6.7 % off the line at 3 m/s, the low end).
    FitOptions options;
    options.form = RegressionForm::linear;
    const ImpactFit fit = fit_impacts(synthetic(40, {5.0e8, 1.0, 1.0}, {10.5}, false), options);
    CHECK(fit.regression.r_squared > 0.99);
    CHECK_THAT(fit.coefficients.lambda, WithinRel(5.0e8, 0.05));
    CHECK(fit.mean_mismatch < 0.08);
    CHECK(fit.mean_mismatch > 0.01);
}

TEST_CASE("fit rejects bad rows naming them", "[risk][fit]") {
    std::vector<ImpactRow> rows = synthetic(5, {5.0e8, 1.0, 1.0}, {10.5}, false);
    CHECK_THROWS_WITH(fit_impacts({rows[0], rows[1]}), Contains("2 rows: needs at least 3"));
    rows[1].mass = -1.0;
    CHECK_THROWS_WITH(fit_impacts(rows),
                      Contains("rows[1].mass = -1 kg") && Contains("must be finite and > 0"));
    rows = synthetic(5, {5.0e8, 1.0, 1.0}, {10.5}, false);
    rows[3].velocity = 0.0;
    CHECK_THROWS_WITH(fit_impacts(rows), Contains("rows[3].velocity = 0 m/s"));
    rows = synthetic(5, {5.0e8, 1.0, 1.0}, {10.5}, false);
    for (ImpactRow& row : rows) row.velocity = 6.0;
    CHECK_THROWS_WITH(fit_impacts(rows), Contains("at least 2 distinct velocities"));
    FitOptions options;
    options.lambda = -1.0;
    CHECK_THROWS_WITH(fit_impacts(synthetic(5, {5.0e8, 1.0, 1.0}, {10.5}, false), options),
                      Contains("lambda = -1 Pa"));
    // Loads 10, 6, 1, 1 N at 1..4 m/s: the line 12.5 - 3.2 v is -0.3 N at 4 m/s, inside the
    // data, where no formula (always > 0) can match it.
    const std::vector<ImpactRow> falling = {
        {1.0, 10.0, 10.0}, {2.0, 6.0, 10.0}, {3.0, 1.0, 10.0}, {4.0, 1.0, 10.0}};
    options = {};
    options.form = RegressionForm::linear;
    CHECK_THROWS_WITH(fit_impacts(falling, options), Contains("use the power regression"));
    CHECK_THROWS_WITH(parse_regression_form("cubic"), Contains("must be power or linear"));
    CHECK(parse_regression_form("linear") == RegressionForm::linear);
}

TEST_CASE("identification over shapes takes lambda from the spheres, then beta per shape",
          "[risk][fit]") {
    // Noise-free spheres at lambda 300 MN/m2 and planar rocks with beta 0.4 at the same lambda;
    // two massive rows are too few to fit and are listed.
    std::vector<ImpactRow> rows = synthetic(12, {3.0e8, 1.0, 1.0}, {10.0}, false);
    for (ImpactRow planar : synthetic(12, {3.0e8, 1.0, 0.4}, {10.0}, false)) {
        planar.shape = ImpactShape::planar;
        rows.push_back(planar);
    }
    for (ImpactRow massive : synthetic(2, {3.0e8, 1.0, 0.5}, {10.0}, false)) {
        massive.shape = ImpactShape::massive;
        rows.push_back(massive);
    }
    CHECK(shape_counts(rows) == "sphere 12, massive 2, planar 12");

    const Identification id = identify_shapes(rows, IdentificationOptions{}, "rows.csv");
    REQUIRE(id.fits.size() == 2);
    CHECK(id.fits[0].shape == ImpactShape::sphere);
    CHECK(id.fits[0].lambda_source == LambdaSource::identified);
    CHECK_THAT(id.fits[0].fit.coefficients.lambda, WithinRel(3.0e8, 1e-9));
    CHECK(id.fits[1].shape == ImpactShape::planar);
    CHECK(id.fits[1].lambda_source == LambdaSource::spheres);
    CHECK(id.fits[1].rows.size() == 12);
    CHECK_THAT(id.fits[1].fit.coefficients.lambda, WithinRel(3.0e8, 1e-9));
    CHECK_THAT(id.fits[1].fit.coefficients.beta, WithinRel(0.4, 1e-9));
    REQUIRE(id.too_few.size() == 1);
    CHECK(id.too_few[0] == std::pair<ImpactShape, std::size_t>{ImpactShape::massive, 2});

    IdentificationOptions given;
    given.lambda = 3.0e8;
    given.shape = "planar";
    const Identification planar = identify_shapes(rows, given, "rows.csv");
    REQUIRE(planar.fits.size() == 1);
    CHECK(planar.fits[0].lambda_source == LambdaSource::given);
    CHECK(planar.too_few.empty());

    IdentificationOptions massive;
    massive.shape = "massive";
    CHECK_THROWS_WITH(identify_shapes(rows, massive, "rows.csv"),
                      Contains("rows.csv has 2 rows of shape massive: a fit needs 3"));
    CHECK_THROWS_WITH(identify_shapes({rows.back()}, IdentificationOptions{}, "one.csv"),
                      Contains("one.csv: no shape has the 3 rows a fit needs (it has: massive 1)"));
}
