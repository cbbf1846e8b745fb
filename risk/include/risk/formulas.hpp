#pragma once
/// Impact design formulas: the peak load of a rock hitting a structure, from its mass and
/// impact velocity (or equivalent fall height).
///
/// Japan Road Association, Rock Fall Measures Handbook (2000), eq. (3) of seed 000:
///   P = 2.108 (m g)^(2/3) lambda^(2/5) H^(3/5)   [kN]
/// with m in tonnes, g = 9.81 m/s2 (so m g is in kN), lambda the Lame constant of the hit
/// material in kN/m2 and H = v^2 / (2 g) the equivalent fall height in m. It is Hertz contact
/// of two elastic spheres, so it holds for compact rocks and elastic impacts; the formula's
/// numeric factor 2.108 only works in those units, hence the conversions at the API boundary.
/// Seed 000 (eqs. 4 and 5) multiplies it by alpha (scatter of the measured load, identified
/// on the mean + 1 sigma regression) and beta (rock shape, identified on the mean regression),
/// with lambda = 500 MN/m2 identified for about 20 cm model rocks hitting a concrete wall.

#include <optional>
#include <string_view>

namespace rockfall::risk {

/// Gravity the handbook formula is written with, in m/s2 (fixed by the handbook, not the scene).
inline constexpr double jra_gravity = 9.81;

/// Lame constant seed 000 identified for rocks hitting a concrete wall: 500 MN/m2, in Pa.
inline constexpr double seed_lambda = 5.0e8;

/// Lame constant Kawase et al. (2003) identified for a weight hitting concrete: 120 MN/m2, in Pa.
inline constexpr double kawase_lambda = 1.2e8;

/// The rock shape classes of seed 000's proposal (its spherical, massive and planar models).
enum class ImpactShape {
    /// Near-spherical rock: alpha 1.3, beta 1.
    sphere,
    /// Blocky rock: alpha 1.6, beta 0.5.
    massive,
    /// Flat rock: alpha 1.7, beta 0.4.
    planar,
};

/// Every shape class, in the order above.
inline constexpr ImpactShape all_impact_shapes[] = {ImpactShape::sphere, ImpactShape::massive,
                                                    ImpactShape::planar};

/// Coefficients of P = alpha beta 2.108 (m g)^(2/3) lambda^(2/5) H^(3/5).
struct ImpactCoefficients {
    /// Lame constant of the hit material, in Pa (> 0); the formula uses it in kN/m2.
    double lambda = seed_lambda;
    /// Factor for the scatter of the measured load (> 0, dimensionless); 1 in the handbook.
    double alpha = 1.0;
    /// Factor for the rock shape (> 0, dimensionless); 1 in the handbook.
    double beta = 1.0;
};

/// The handbook formula as published: alpha = beta = 1 and the given Lame constant, in Pa.
ImpactCoefficients jra_coefficients(double lambda);

/// Seed 000's preset for a shape: lambda 500 MN/m2 and that shape's alpha and beta
/// (sphere 1.3 and 1; massive 1.6 and 0.5; planar 1.7 and 0.4).
ImpactCoefficients seed_coefficients(ImpactShape shape);

/// The shape named "sphere", "massive" or "planar"; throws std::invalid_argument otherwise.
ImpactShape parse_impact_shape(std::string_view name);

/// The shape of that name, or nothing for any other name (rock kinds without a shape class).
std::optional<ImpactShape> find_impact_shape(std::string_view name);

/// The lower-case name of a shape, as parse_impact_shape reads it.
std::string_view to_string(ImpactShape shape);

/// Equivalent fall height H = v^2 / (2 g) with g = jra_gravity, in m, for an impact velocity
/// in m/s (finite, > 0). Throws std::invalid_argument otherwise.
double jra_equivalent_height(double velocity);

/// Impact velocity v = sqrt(2 g H) with g = jra_gravity, in m/s, for an equivalent fall
/// height in m (finite, > 0): the inverse of jra_equivalent_height. Throws
/// std::invalid_argument otherwise.
double jra_impact_velocity(double height);

/// Peak impact load P in N of a rock of mass in kg (finite, > 0) hitting at a velocity in
/// m/s (finite, > 0), by the handbook formula with the given coefficients (each finite and
/// > 0). Validity: compact rocks in elastic impact; seed 000's coefficients were identified
/// for model rocks of about 20 cm and 10 kg at a few m/s. Throws std::invalid_argument naming
/// the field, value, unit and allowed range.
double jra_impact_force(double mass, double velocity, const ImpactCoefficients& coefficients);

/// The same load from the equivalent fall height in m (finite, > 0) instead of the velocity.
double jra_impact_force_from_height(double mass, double height,
                                    const ImpactCoefficients& coefficients);

}  // namespace rockfall::risk
