#include "mpm/material.hpp"

#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::mpm {
namespace {

void require(bool ok, const char* where, const char* field, double value, const char* unit,
             const char* range) {
    if (!ok) {
        std::ostringstream message;
        message << where << field << " = " << value << (unit[0] != '\0' ? " " : "") << unit
                << ": must be " << range;
        throw std::invalid_argument(message.str());
    }
}

void validate_elastic(double youngs_modulus, double poisson_ratio, const char* where) {
    require(std::isfinite(youngs_modulus) && youngs_modulus > 0.0, where, "youngs_modulus",
            youngs_modulus, "Pa", "> 0");
    require(poisson_ratio >= 0.0 && poisson_ratio < 0.5, where, "poisson_ratio", poisson_ratio, "",
            "in [0, 0.5)");
}

struct Lame {
    double lambda;
    double shear;
    double bulk;
};

Lame lame(double youngs_modulus, double poisson_ratio) {
    const double e = youngs_modulus;
    const double nu = poisson_ratio;
    const double lambda = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
    const double shear = e / (2.0 * (1.0 + nu));
    return {lambda, shear, lambda + 2.0 * shear / 3.0};
}

}  // namespace

void validate(const Material& material, const char* where) {
    if (const auto* elastic = std::get_if<LinearElastic>(&material)) {
        validate_elastic(elastic->youngs_modulus, elastic->poisson_ratio, where);
        return;
    }
    const auto& dp = std::get<DruckerPrager>(material);
    validate_elastic(dp.youngs_modulus, dp.poisson_ratio, where);
    require(dp.friction_angle_deg >= 0.0 && dp.friction_angle_deg <= 70.0, where,
            "friction_angle_deg", dp.friction_angle_deg, "deg", "in [0, 70]");
    require(dp.dilatancy_angle_deg >= 0.0 && dp.dilatancy_angle_deg <= dp.friction_angle_deg, where,
            "dilatancy_angle_deg", dp.dilatancy_angle_deg, "deg", "in [0, friction_angle_deg]");
    require(std::isfinite(dp.cohesion) && dp.cohesion >= 0.0, where, "cohesion", dp.cohesion, "Pa",
            ">= 0");
    require(std::isfinite(dp.tensile_strength) && dp.tensile_strength >= 0.0, where,
            "tensile_strength", dp.tensile_strength, "Pa", ">= 0");
    require(dp.friction_angle_deg > 0.0 || dp.cohesion > 0.0, where, "cohesion", dp.cohesion, "Pa",
            "> 0 when friction_angle_deg = 0 (no strength otherwise)");
}

double p_wave_modulus(const Material& material) {
    return std::visit(
        [](const auto& m) {
            const Lame l = lame(m.youngs_modulus, m.poisson_ratio);
            return l.lambda + 2.0 * l.shear;
        },
        material);
}

ConeCoefficients cone_coefficients(double angle_deg, ConeMatch match) {
    const double phi = radians(angle_deg);
    const double sin_phi = std::sin(phi);
    const double cos_phi = std::cos(phi);
    const double root3 = std::sqrt(3.0);
    switch (match) {
        case ConeMatch::compression:
            return {6.0 * sin_phi / (root3 * (3.0 - sin_phi)),
                    6.0 * cos_phi / (root3 * (3.0 - sin_phi))};
        case ConeMatch::extension:
            return {6.0 * sin_phi / (root3 * (3.0 + sin_phi)),
                    6.0 * cos_phi / (root3 * (3.0 + sin_phi))};
        case ConeMatch::plane_strain: {
            const double tan_phi = std::tan(phi);
            const double root = std::sqrt(9.0 + 12.0 * tan_phi * tan_phi);
            return {3.0 * tan_phi / root, 3.0 / root};
        }
    }
    return {};
}

LinearElasticModel::LinearElasticModel(const LinearElastic& params) {
    const Lame l = lame(params.youngs_modulus, params.poisson_ratio);
    lambda_ = l.lambda;
    shear_ = l.shear;
}

DruckerPragerModel::DruckerPragerModel(const DruckerPrager& params) {
    const Lame l = lame(params.youngs_modulus, params.poisson_ratio);
    lambda_ = l.lambda;
    shear_ = l.shear;
    bulk_ = l.bulk;
    const ConeCoefficients yield = cone_coefficients(params.friction_angle_deg, params.match);
    eta_ = yield.eta;
    xi_c_ = yield.xi * params.cohesion;
    eta_bar_ = cone_coefficients(params.dilatancy_angle_deg, params.match).eta;
    const double apex = eta_ > 0.0 ? xi_c_ / eta_ : std::numeric_limits<double>::infinity();
    tension_cutoff_ = std::min(params.tensile_strength, apex);
}

double DruckerPragerModel::yield_function(const Mat3& stress) const {
    const double p = stress.trace() / 3.0;
    const Mat3 s = stress - p * Mat3::Identity();
    return std::sqrt(0.5 * s.squaredNorm()) + eta_ * p - xi_c_;
}

}  // namespace rockfall::mpm
