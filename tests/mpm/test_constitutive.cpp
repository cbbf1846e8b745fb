#include "mpm/material.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>
#include <stdexcept>

using namespace rockfall::mpm;
using Catch::Matchers::WithinAbs;
using Catch::Matchers::WithinRel;

namespace {

double mean_stress(const Mat3& s) { return s.trace() / 3.0; }

double deviatoric_q(const Mat3& s) {
    const Mat3 dev = s - mean_stress(s) * Mat3::Identity();
    return std::sqrt(0.5 * dev.squaredNorm());
}

// Mohr-Coulomb triaxial state (tension positive): lateral stress `lateral`, the axial stress
// on the failure envelope, more compressive (compression) or less compressive (extension).
Mat3 triaxial_failure(double phi_deg, double c, double lateral, bool compression) {
    const double s = std::sin(radians(phi_deg));
    const double k = std::cos(radians(phi_deg));
    Mat3 stress = Mat3::Zero();
    stress(0, 0) = lateral;
    stress(1, 1) = lateral;
    if (compression) {
        // sigma1 = sigma2 = lateral, sigma3 = axial: (s1 - s3) = 2 c cos - (s1 + s3) sin.
        stress(2, 2) = (lateral * (1.0 + s) - 2.0 * c * k) / (1.0 - s);
    } else {
        // sigma1 = axial, sigma2 = sigma3 = lateral.
        stress(2, 2) = (2.0 * c * k + lateral * (1.0 - s)) / (1.0 + s);
    }
    return stress;
}

}  // namespace

TEST_CASE("Drucker-Prager cone coefficients match de Souza Neto's formulas", "[mpm][material]") {
    const ConeCoefficients outer = cone_coefficients(30.0, ConeMatch::compression);
    CHECK_THAT(outer.eta, WithinRel(6.0 * 0.5 / (std::sqrt(3.0) * 2.5), 1e-12));
    CHECK_THAT(outer.xi, WithinRel(6.0 * std::cos(radians(30.0)) / (std::sqrt(3.0) * 2.5), 1e-12));
    const ConeCoefficients inner = cone_coefficients(30.0, ConeMatch::extension);
    CHECK_THAT(inner.eta, WithinRel(6.0 * 0.5 / (std::sqrt(3.0) * 3.5), 1e-12));
    const ConeCoefficients plane = cone_coefficients(30.0, ConeMatch::plane_strain);
    CHECK_THAT(plane.eta, WithinRel(std::sqrt(3.0) / std::sqrt(13.0), 1e-12));
    CHECK_THAT(plane.xi, WithinRel(3.0 / std::sqrt(13.0), 1e-12));
}

TEST_CASE("Outer and inner cones pass through Mohr-Coulomb triaxial failure states",
          "[mpm][material]") {
    DruckerPrager params;
    params.friction_angle_deg = 34.6;
    params.cohesion = 2100.0;
    for (const double lateral : {-1.0e3, -1.0e4, -1.0e5}) {
        params.match = ConeMatch::compression;
        const DruckerPragerModel outer(params);
        const Mat3 tc = triaxial_failure(34.6, 2100.0, lateral, true);
        CHECK_THAT(outer.yield_function(tc), WithinAbs(0.0, 1e-9 * std::abs(lateral)));
        params.match = ConeMatch::extension;
        const DruckerPragerModel inner(params);
        const Mat3 te = triaxial_failure(34.6, 2100.0, lateral, false);
        CHECK_THAT(inner.yield_function(te), WithinAbs(0.0, 1e-9 * std::abs(lateral)));
    }
}

TEST_CASE("Drucker-Prager: elastic inside the cone, returns onto it outside", "[mpm][material]") {
    DruckerPrager params;
    params.youngs_modulus = 1.0e7;
    params.cohesion = 1.0e3;
    const DruckerPragerModel model(params);
    const LinearElasticModel elastic(LinearElastic{params.youngs_modulus, params.poisson_ratio});
    Mat3 start = Mat3::Zero();
    start.diagonal().setConstant(-5.0e4);

    SECTION("a small increment stays elastic") {
        Mat3 de = Mat3::Zero();
        de(0, 1) = de(1, 0) = 1e-5;
        double gamma = 0.0;
        double unused = 0.0;
        const Mat3 s = model.update(start, de, gamma);
        CHECK((s - elastic.update(start, de, unused)).norm() < 1e-9);
        CHECK(gamma == 0.0);
    }
    SECTION("a large shear increment returns to the cone at the same mean stress (psi = 0)") {
        for (const double shear : {1e-2, 3e-2, 1e-1}) {
            Mat3 de = Mat3::Zero();
            de(0, 2) = de(2, 0) = shear;
            de(0, 0) = 0.3 * shear;
            de(1, 1) = -0.3 * shear;
            double gamma = 0.0;
            const Mat3 s = model.update(start, de, gamma);
            CHECK_THAT(model.yield_function(s), WithinAbs(0.0, 1e-6));
            CHECK_THAT(mean_stress(s), WithinRel(-5.0e4, 1e-12));
            CHECK(gamma > 0.0);
            // The deviator keeps the trial direction (radial return).
            Mat3 unused_de = de;
            double unused = 0.0;
            const Mat3 trial = elastic.update(start, unused_de, unused);
            const Mat3 dev_trial = trial - mean_stress(trial) * Mat3::Identity();
            const Mat3 dev = s - mean_stress(s) * Mat3::Identity();
            CHECK_THAT((dev / dev.norm()).cwiseProduct(dev_trial / dev_trial.norm()).sum(),
                       WithinAbs(1.0, 1e-12));
        }
    }
    SECTION("dilatancy moves the mean stress by K eta_bar dgamma onto the cone") {
        DruckerPrager dilatant = params;
        dilatant.dilatancy_angle_deg = 10.0;
        const DruckerPragerModel model_psi(dilatant);
        Mat3 de = Mat3::Zero();
        de(0, 2) = de(2, 0) = 1e-2;
        double gamma = 0.0;
        const Mat3 s = model_psi.update(start, de, gamma);
        CHECK_THAT(model_psi.yield_function(s), WithinAbs(0.0, 1e-6));
        const double bulk = params.youngs_modulus / (3.0 * (1.0 - 2.0 * params.poisson_ratio));
        const double eta_bar = cone_coefficients(10.0, params.match).eta;
        CHECK_THAT(mean_stress(s), WithinRel(-5.0e4 - bulk * eta_bar * gamma, 1e-12));
    }
    SECTION("tension is cut off at the tensile strength") {
        Mat3 de = Mat3::Identity() * 1e-2;
        de(0, 1) = de(1, 0) = 1e-2;
        double gamma = 0.0;
        const Mat3 s = model.update(start, de, gamma);
        CHECK_THAT(mean_stress(s), WithinAbs(0.0, 1e-9));
        const ConeCoefficients cone = cone_coefficients(params.friction_angle_deg, params.match);
        CHECK(deviatoric_q(s) <= cone.xi * params.cohesion * (1.0 + 1e-12));
        DruckerPrager strong = params;
        strong.tensile_strength = 1.0e9;
        const DruckerPragerModel capped(strong);
        CHECK_THAT(capped.tension_cutoff(), WithinRel(cone.xi * params.cohesion / cone.eta, 1e-12));
    }
}

TEST_CASE("Material validation names the field, value and range", "[mpm][material]") {
    DruckerPrager bad;
    bad.poisson_ratio = 0.5;
    CHECK_THROWS_WITH(validate(Material{bad}), Catch::Contains("poisson_ratio") &&
                                                   Catch::Contains("0.5") &&
                                                   Catch::Contains("[0, 0.5)"));
    DruckerPrager steep;
    steep.dilatancy_angle_deg = 40.0;
    CHECK_THROWS_WITH(validate(Material{steep}), Catch::Contains("dilatancy_angle_deg"));
    LinearElastic soft;
    soft.youngs_modulus = -1.0;
    CHECK_THROWS_AS(validate(Material{soft}), std::invalid_argument);
    CHECK_NOTHROW(validate(Material{DruckerPrager{}}));
}
