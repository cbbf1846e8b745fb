#pragma once
/// What `rockfall formula NAME` prints: one impact design formula evaluated, every input
/// echoed in SI (and in the handbook's kN, t, kJ where it gives them), the result and the
/// range the formula was made for, as "label: text" lines and as one JSON object with the
/// units in the key names.

#include "risk/design_values.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::report {

/// The inputs of one evaluation, as given (SI units); which ones a formula needs is checked
/// when it is evaluated, and a missing one throws std::invalid_argument naming its option.
struct FormulaInputs {
    /// jra, seed, labiouse, astra or uni.
    std::string name;
    /// Rock mass, kg; for uni the design block's.
    double mass = 0.0;
    /// Impact velocity, m/s, or the equivalent fall height H = v^2 / 2g, m.
    std::optional<double> velocity;
    std::optional<double> height;
    /// jra and seed: load scatter factor, shape factor, Lame constant of the hit material (Pa),
    /// and seed's shape preset (sphere, massive or planar).
    std::optional<double> alpha;
    std::optional<double> beta;
    std::optional<double> lambda;
    std::optional<std::string> shape;
    /// labiouse and astra: rock radius (m) or density (kg/m3), cushion modulus M_E (Pa), and
    /// astra's cushion thickness (m) and friction angle (deg).
    std::optional<double> radius;
    std::optional<double> density;
    std::optional<double> modulus;
    std::optional<double> thickness;
    std::optional<double> friction_angle;
    /// uni: percentile (%) in (0, 100) and partial factors.
    double percentile = 95.0;
    risk::PartialFactors factors;
};

/// The evaluated formula.
struct FormulaReport {
    /// "label: text" lines in the order they are printed.
    std::vector<std::pair<std::string, std::string>> lines;
    /// The same values as JSON fields.
    nlohmann::json json = nlohmann::json::object();

    void add(std::string label, std::string text, const nlohmann::json& fields);
};

/// Evaluates jra, seed, labiouse or astra; throws std::invalid_argument for a missing or
/// conflicting input.
FormulaReport evaluate_formula(const FormulaInputs& inputs);

/// Evaluates uni on a sample; throws std::invalid_argument for a bad percentile.
FormulaReport evaluate_design_values(const FormulaInputs& inputs, const risk::DesignSample& sample);

/// The readable lines, one "label: text" a line.
void print_formula_report(std::ostream& out, const FormulaReport& report);

}  // namespace rockfall::report
