// Japan Road Association impact formula and seed 000's shape presets (see formulas.hpp).

#include "risk/formulas.hpp"

#include "validation.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

// The handbook's units: tonnes, kN and kN/m2.
constexpr double kg_per_tonne = 1.0e3;
constexpr double n_per_kn = 1.0e3;
constexpr double pa_per_kn_m2 = 1.0e3;

// Numeric factor of the handbook formula, valid only with m g in kN, lambda in kN/m2, H in m.
constexpr double jra_factor = 2.108;

using detail::require_positive;

void require_valid(const ImpactCoefficients& coefficients) {
    require_positive("lambda", coefficients.lambda, "Pa");
    require_positive("alpha", coefficients.alpha, "(dimensionless)");
    require_positive("beta", coefficients.beta, "(dimensionless)");
}

}  // namespace

ImpactCoefficients jra_coefficients(double lambda) {
    require_positive("lambda", lambda, "Pa");
    return {lambda, 1.0, 1.0};
}

// Seed 000, eqs. (4) and (5) and the paragraph after (5).
ImpactCoefficients seed_coefficients(ImpactShape shape) {
    switch (shape) {
        case ImpactShape::sphere:
            return {seed_lambda, 1.3, 1.0};
        case ImpactShape::massive:
            return {seed_lambda, 1.6, 0.5};
        case ImpactShape::planar:
            return {seed_lambda, 1.7, 0.4};
    }
    throw std::invalid_argument("unknown impact shape");
}

std::optional<ImpactShape> find_impact_shape(std::string_view name) {
    for (const ImpactShape shape : all_impact_shapes) {
        if (name == to_string(shape)) return shape;
    }
    return std::nullopt;
}

ImpactShape parse_impact_shape(std::string_view name) {
    if (const auto shape = find_impact_shape(name)) return *shape;
    throw std::invalid_argument("shape = \"" + std::string(name) +
                                "\": must be sphere, massive or planar");
}

std::string_view to_string(ImpactShape shape) {
    switch (shape) {
        case ImpactShape::sphere:
            return "sphere";
        case ImpactShape::massive:
            return "massive";
        case ImpactShape::planar:
            return "planar";
    }
    return "unknown";
}

double jra_equivalent_height(double velocity) {
    require_positive("velocity", velocity, "m/s");
    return velocity * velocity / (2.0 * jra_gravity);
}

double jra_impact_velocity(double height) {
    require_positive("height", height, "m");
    return std::sqrt(2.0 * jra_gravity * height);
}

double jra_impact_force(double mass, double velocity, const ImpactCoefficients& coefficients) {
    require_positive("mass", mass, "kg");
    return jra_impact_force_from_height(mass, jra_equivalent_height(velocity), coefficients);
}

double jra_impact_force_from_height(double mass, double height,
                                    const ImpactCoefficients& coefficients) {
    require_positive("mass", mass, "kg");
    require_positive("height", height, "m");
    require_valid(coefficients);
    const double weight_kn = mass / kg_per_tonne * jra_gravity;
    const double lambda_kn_m2 = coefficients.lambda / pa_per_kn_m2;
    const double load_kn = coefficients.alpha * coefficients.beta * jra_factor *
                           std::pow(weight_kn, 2.0 / 3.0) * std::pow(lambda_kn_m2, 0.4) *
                           std::pow(height, 0.6);
    return load_kn * n_per_kn;
}

}  // namespace rockfall::risk
