// Identification of the impact formula's coefficients from impacts (see impact_fit.hpp).

#include "risk/impact_fit.hpp"

#include "validation.hpp"

#include "risk/statistics.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

// The formula's exponents (seed 000 eq. 3): P ~ (m g)^(2/3) lambda^(2/5).
constexpr double mass_exponent = 2.0 / 3.0;
constexpr double lambda_exponent = 0.4;

struct LeastSquares {
    double intercept = 0.0;
    double slope = 0.0;
    double residual_sd = 0.0;
    double r_squared = 0.0;
};

// Ordinary least squares of y on x, with the scatter about the line.
LeastSquares least_squares(const std::vector<double>& x, const std::vector<double>& y) {
    assert(x.size() == y.size() && x.size() >= 3);
    const double n = static_cast<double>(x.size());
    const LineFit line = fit_line(x, y);
    LeastSquares fit;
    fit.slope = line.slope;
    fit.intercept = line.intercept;
    double residuals = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double r = y[i] - (fit.intercept + fit.slope * x[i]);
        residuals += r * r;
    }
    fit.residual_sd = std::sqrt(residuals / (n - 2.0));
    fit.r_squared = line.syy > 0.0 ? 1.0 - residuals / line.syy : 1.0;
    return fit;
}

std::string indexed(const char* name, std::size_t i, const char* field) {
    return std::string(name) + '[' + std::to_string(i) + "]." + field;
}

void require_points(const std::vector<double>& velocities, const std::vector<double>& forces) {
    if (velocities.size() != forces.size()) {
        throw std::invalid_argument("regression: " + std::to_string(velocities.size()) +
                                    " velocities but " + std::to_string(forces.size()) + " forces");
    }
    if (velocities.size() < 3) {
        throw std::invalid_argument("regression: " + std::to_string(velocities.size()) +
                                    " points: needs at least 3 (the scatter has n - 2 degrees "
                                    "of freedom)");
    }
    for (std::size_t i = 0; i < velocities.size(); ++i) {
        detail::require_positive(indexed("points", i, "velocity").c_str(), velocities[i], "m/s");
        detail::require_positive(indexed("points", i, "peak_force").c_str(), forces[i], "N");
    }
    const auto [low, high] = std::minmax_element(velocities.begin(), velocities.end());
    if (*low == *high) {
        throw std::invalid_argument("regression: every point has the velocity " +
                                    std::to_string(*low) +
                                    " m/s: needs at least 2 distinct velocities");
    }
}

double log_of(double x) { return std::log(x); }

// Largest |a_i / b_i - 1|.
double largest_mismatch(const std::vector<double>& a, const std::vector<double>& b) {
    double worst = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) worst = std::max(worst, std::abs(a[i] / b[i] - 1));
    return worst;
}

}  // namespace

std::string_view to_string(RegressionForm form) {
    switch (form) {
        case RegressionForm::power:
            return "power";
        case RegressionForm::linear:
            return "linear";
    }
    return "unknown";
}

RegressionForm parse_regression_form(std::string_view name) {
    for (const RegressionForm form : {RegressionForm::power, RegressionForm::linear}) {
        if (name == to_string(form)) return form;
    }
    throw std::invalid_argument("regression = \"" + std::string(name) +
                                "\": must be power or linear");
}

double ImpactRegression::mean(double velocity) const {
    return form == RegressionForm::power ? a * std::pow(velocity, b) : a + b * velocity;
}

double ImpactRegression::upper(double velocity) const {
    return form == RegressionForm::power ? mean(velocity) * std::exp(sigma)
                                         : mean(velocity) + sigma;
}

ImpactRegression fit_regression(const std::vector<double>& velocities,
                                const std::vector<double>& forces, RegressionForm form) {
    require_points(velocities, forces);
    ImpactRegression regression;
    regression.form = form;
    if (form == RegressionForm::power) {
        std::vector<double> log_v(velocities.size());
        std::vector<double> log_p(forces.size());
        std::transform(velocities.begin(), velocities.end(), log_v.begin(), log_of);
        std::transform(forces.begin(), forces.end(), log_p.begin(), log_of);
        const LeastSquares fit = least_squares(log_v, log_p);
        regression.a = std::exp(fit.intercept);
        regression.b = fit.slope;
        regression.sigma = fit.residual_sd;
        regression.r_squared = fit.r_squared;
    } else {
        const LeastSquares fit = least_squares(velocities, forces);
        regression.a = fit.intercept;
        regression.b = fit.slope;
        regression.sigma = fit.residual_sd;
        regression.r_squared = fit.r_squared;
    }
    return regression;
}

double ImpactFit::envelope(double velocity) const {
    return jra_impact_force(reference_mass, velocity, coefficients);
}

ImpactFit fit_impacts(const std::vector<ImpactRow>& rows, const FitOptions& options) {
    if (rows.size() < 3) {
        throw std::invalid_argument("impact fit: " + std::to_string(rows.size()) +
                                    " rows: needs at least 3");
    }
    std::vector<double> velocities;
    std::vector<double> masses;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        detail::require_positive(indexed("rows", i, "velocity").c_str(), rows[i].velocity, "m/s");
        detail::require_positive(indexed("rows", i, "peak_force").c_str(), rows[i].peak_force, "N");
        detail::require_positive(indexed("rows", i, "mass").c_str(), rows[i].mass, "kg");
        velocities.push_back(rows[i].velocity);
        masses.push_back(rows[i].mass);
    }
    if (options.reference_mass) {
        detail::require_positive("reference mass", *options.reference_mass, "kg");
    }
    if (options.lambda) detail::require_positive("lambda", *options.lambda, "Pa");

    ImpactFit fit;
    fit.count = rows.size();
    const auto [v_low, v_high] = std::minmax_element(velocities.begin(), velocities.end());
    const auto [m_low, m_high] = std::minmax_element(masses.begin(), masses.end());
    fit.velocity_min = *v_low;
    fit.velocity_max = *v_high;
    fit.mass_min = *m_low;
    fit.mass_max = *m_high;
    fit.reference_mass = options.reference_mass.value_or(median(masses));

    std::vector<double> scaled(rows.size());
    for (std::size_t i = 0; i < rows.size(); ++i) {
        scaled[i] = rows[i].peak_force * std::pow(fit.reference_mass / rows[i].mass, mass_exponent);
    }
    fit.regression = fit_regression(velocities, scaled, options.form);

    // The formula is kappa g(v) with g the handbook formula at the reference lambda; the
    // least-squares fit of ln(kappa g) to ln(line) makes ln kappa the mean log ratio.
    const ImpactCoefficients reference{seed_lambda, 1.0, 1.0};
    std::vector<double> base(rows.size());
    std::vector<double> mean_line(rows.size());
    std::vector<double> upper_line(rows.size());
    double log_kappa = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        base[i] = jra_impact_force(fit.reference_mass, velocities[i], reference);
        mean_line[i] = fit.regression.mean(velocities[i]);
        upper_line[i] = fit.regression.upper(velocities[i]);
        if (!(mean_line[i] > 0.0)) {
            std::ostringstream message;
            message << "the mean regression line is " << mean_line[i]
                    << " N at v = " << velocities[i]
                    << " m/s: the formula (always > 0) cannot match it "
                    << "there; use the power regression";
            throw std::invalid_argument(message.str());
        }
        log_kappa += std::log(mean_line[i] / base[i]);
    }
    const double kappa = std::exp(log_kappa / static_cast<double>(rows.size()));

    fit.lambda_identified = !options.lambda.has_value();
    if (fit.lambda_identified) {
        fit.coefficients = {seed_lambda * std::pow(kappa, 1.0 / lambda_exponent), 1.0, 1.0};
    } else {
        const double beta = kappa / std::pow(*options.lambda / seed_lambda, lambda_exponent);
        fit.coefficients = {*options.lambda, 1.0, beta};
    }

    std::vector<double> formula(rows.size());
    double log_alpha = 0.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        formula[i] = jra_impact_force(fit.reference_mass, velocities[i], fit.coefficients);
        log_alpha += std::log(upper_line[i] / formula[i]);
    }
    fit.coefficients.alpha = std::exp(log_alpha / static_cast<double>(rows.size()));
    fit.mean_mismatch = largest_mismatch(formula, mean_line);
    for (double& f : formula) f *= fit.coefficients.alpha;
    fit.upper_mismatch = largest_mismatch(formula, upper_line);
    return fit;
}

}  // namespace rockfall::risk
