#pragma once
/// Identification of the impact formula's coefficients from measured or simulated wall
/// impacts, as seed 000 did for its proposal (formulas.hpp): regress the peak load on the
/// impact velocity, take the mean and the mean + 1 sigma regression lines, identify the Lame
/// constant lambda (or, with lambda fixed, the shape factor beta) so that the formula matches
/// the mean line, then alpha so that alpha times it matches the mean + 1 sigma line.
///
/// Seed 000 does not state the form of its regression (its Figure 7 is not in the text), so
/// both usual forms are offered; the power law is the default because the formula itself is a
/// power law in v (P ~ v^(6/5)) and because its scatter band is proportional to the load, which
/// is what a multiplicative alpha can match. "Matches" is a least-squares fit of ln(formula)
/// to ln(line) at the rows' velocities, so the identification weighs the velocities where the
/// data are; with the power regression it gives alpha = exp(sigma) exactly.
///
/// Rows of different masses are brought to one reference mass by the formula's own mass law,
/// P ~ m^(2/3), before the regression; with a single mass this changes nothing.

#include "risk/formulas.hpp"

#include <cstddef>
#include <optional>
#include <string_view>
#include <vector>

namespace rockfall::risk {

/// One measured or simulated wall impact.
struct ImpactRow {
    /// Impact velocity just before the hit, m/s (finite, > 0).
    double velocity = 0.0;
    /// Peak normal force on the wall, N (finite, > 0).
    double peak_force = 0.0;
    /// Rock mass, kg (finite, > 0).
    double mass = 0.0;
    /// Shape class of the rock.
    ImpactShape shape = ImpactShape::sphere;
};

/// Form of the regression of peak load P on impact velocity v.
enum class RegressionForm {
    /// P = a v^b, least squares on ln P against ln v; sigma is the residual sd of ln P.
    power,
    /// P = a + b v, least squares on P; sigma is the residual sd of P, in N.
    linear,
};

/// Lower-case name of a form ("power", "linear").
std::string_view to_string(RegressionForm form);

/// The form named "power" or "linear"; throws std::invalid_argument otherwise.
RegressionForm parse_regression_form(std::string_view name);

/// A fitted regression line of peak load on impact velocity, with its scatter.
struct ImpactRegression {
    /// Form of the line.
    RegressionForm form = RegressionForm::power;
    /// power: the factor a of P = a v^b, N (s/m)^b; linear: the intercept a, N.
    double a = 0.0;
    /// power: the exponent b (dimensionless); linear: the slope b, N s/m.
    double b = 0.0;
    /// Residual standard deviation with n - 2 degrees of freedom: of ln P (power,
    /// dimensionless) or of P in N (linear); >= 0.
    double sigma = 0.0;
    /// Coefficient of determination, on ln P for the power form, on P for the linear one.
    double r_squared = 0.0;

    /// The mean line at an impact velocity in m/s, N (for the power form, the line of the
    /// mean of ln P, i.e. the median under lognormal scatter).
    double mean(double velocity) const;
    /// The mean + 1 sigma line at an impact velocity in m/s, N: mean * exp(sigma) for the
    /// power form, mean + sigma for the linear one.
    double upper(double velocity) const;
};

/// Fits a regression of peak_force on velocity to points (velocities in m/s, forces in N;
/// same size, at least 3 points, at least 2 distinct velocities, all finite and > 0).
/// Throws std::invalid_argument otherwise.
ImpactRegression fit_regression(const std::vector<double>& velocities,
                                const std::vector<double>& forces, RegressionForm form);

/// What to identify and how.
struct FitOptions {
    /// Form of the regression.
    RegressionForm form = RegressionForm::power;
    /// Lame constant held fixed, Pa (> 0): then beta is identified on the mean line. Unset:
    /// lambda is identified with beta = 1 (seed 000's procedure for spheres).
    std::optional<double> lambda;
    /// Mass the rows are scaled to, kg (> 0); unset: the median mass of the rows.
    std::optional<double> reference_mass;
};

/// The identified coefficients with the fit's quality and the range it is valid for.
struct ImpactFit {
    /// Number of rows.
    std::size_t count = 0;
    /// Range of the rows' impact velocities, m/s.
    double velocity_min = 0.0;
    double velocity_max = 0.0;
    /// Range of the rows' masses and the reference mass the regression is at, kg.
    double mass_min = 0.0;
    double mass_max = 0.0;
    double reference_mass = 0.0;
    /// The regression of the rows' peak loads, scaled to the reference mass.
    ImpactRegression regression;
    /// lambda (Pa), alpha and beta: the formula alpha beta P_JRA(lambda) is the envelope.
    ImpactCoefficients coefficients;
    /// true: lambda was identified (beta = 1); false: lambda was given and beta identified.
    bool lambda_identified = true;
    /// Largest |formula / line - 1| over the rows' velocities: the formula with alpha = 1
    /// against the mean line, and with alpha against the mean + 1 sigma line.
    double mean_mismatch = 0.0;
    double upper_mismatch = 0.0;

    /// The identified envelope alpha beta P_JRA(lambda) at the reference mass, N, for an
    /// impact velocity in m/s (> 0).
    double envelope(double velocity) const;
};

/// Identifies the formula's coefficients from rows (at least 3, at least 2 distinct
/// velocities; every value finite and > 0; their shapes are not looked at, so select one
/// shape first). Throws std::invalid_argument on bad input, naming the row.
ImpactFit fit_impacts(const std::vector<ImpactRow>& rows, const FitOptions& options = {});

}  // namespace rockfall::risk
