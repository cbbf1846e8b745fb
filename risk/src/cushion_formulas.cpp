// Labiouse et al. (1996) and ASTRA (2008) cushion impact formulas (see cushion_formulas.hpp).

#include "risk/cushion_formulas.hpp"

#include "validation.hpp"

#include <cmath>
#include <numbers>

namespace rockfall::risk {
namespace {

using detail::require_positive;

// The published units: tonnes, kN, kN/m2 and kJ.
constexpr double kg_per_tonne = 1.0e3;
constexpr double n_per_kn = 1.0e3;
constexpr double pa_per_kn_m2 = 1.0e3;

// Numeric factors, valid only in those units.
constexpr double labiouse_factor = 1.765;
constexpr double astra_factor = 2.8;

// m v^2 / 2 with m in t: the kinetic energy in kJ (= W H of the fall-height form).
double energy_kj(double mass, double velocity) {
    return 0.5 * mass / kg_per_tonne * velocity * velocity;
}

// The inputs both formulas share: a sphere of mass and radius hitting a cushion of modulus M_E.
void require_sphere_on_cushion(double mass, double velocity, double radius,
                               double cushion_modulus) {
    require_positive("mass", mass, "kg");
    require_positive("velocity", velocity, "m/s");
    require_positive("radius", radius, "m");
    require_positive("cushion modulus M_E", cushion_modulus, "Pa");
}

}  // namespace

double labiouse_impact_force(const LabiouseInputs& in) {
    require_sphere_on_cushion(in.mass, in.velocity, in.radius, in.cushion_modulus);
    const double modulus_kn_m2 = in.cushion_modulus / pa_per_kn_m2;
    const double force_kn = labiouse_factor * std::pow(modulus_kn_m2, 0.4) *
                            std::pow(in.radius, 0.2) *
                            std::pow(energy_kj(in.mass, in.velocity), 0.6);
    return force_kn * n_per_kn;
}

double astra_impact_force(const AstraInputs& in) {
    require_sphere_on_cushion(in.mass, in.velocity, in.radius, in.cushion_modulus);
    require_positive("cushion thickness", in.cushion_thickness, "m");
    detail::require_range("friction angle", in.friction_angle_deg, "deg", 0.0, 90.0, true, true);
    const double modulus_kn_m2 = in.cushion_modulus / pa_per_kn_m2;
    const double tan_phi = std::tan(in.friction_angle_deg * std::numbers::pi / 180.0);
    const double force_kn = astra_factor / std::sqrt(in.cushion_thickness) *
                            std::pow(in.radius, 0.7) * std::pow(modulus_kn_m2, 0.4) *
                            std::pow(tan_phi, 0.2) * std::pow(energy_kj(in.mass, in.velocity), 0.6);
    return force_kn * n_per_kn;
}

double equivalent_radius(double mass, double density) {
    require_positive("mass", mass, "kg");
    require_positive("density", density, "kg/m3");
    return std::cbrt(3.0 * mass / (4.0 * std::numbers::pi * density));
}

}  // namespace rockfall::risk
