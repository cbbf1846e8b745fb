// The text and JSON of `rockfall fit` (see fit_report.hpp).

#include "report/fit_report.hpp"

#include "report/text_format.hpp"

#include "risk/formulas.hpp"

namespace rockfall::report {
namespace {

constexpr double kilo = 1.0e3;

std::string too_few_text(const risk::Identification& id) {
    std::string text;
    for (const auto& [shape, n] : id.too_few) {
        text += (text.empty() ? "" : ", ") + std::string(risk::to_string(shape)) + ' ' +
                std::to_string(n);
    }
    return text;
}

// How each lambda source is said in the text, and its JSON key.
struct LambdaWords {
    const char* text;
    const char* key;
};

LambdaWords lambda_words(risk::LambdaSource source) {
    switch (source) {
        case risk::LambdaSource::given:
            return {"given (--lambda); beta identified on the mean line", "given"};
        case risk::LambdaSource::spheres:
            return {"identified on this file's spheres; beta identified on the mean line",
                    "spheres"};
        case risk::LambdaSource::identified:
            break;
    }
    return {"identified on the mean line (beta = 1)", "identified"};
}

std::string line_text(const risk::ImpactRegression& r) {
    if (r.form == risk::RegressionForm::power) {
        return fmt("P = %.4g", r.a / kilo) + fmt(" v^%.4g kN", r.b) +
               fmt(" (v in m/s); R^2 = %.3f on ln P", r.r_squared) +
               fmt("; sigma = %.3g (of ln P)", r.sigma);
    }
    return fmt("P = %.4g", r.a / kilo) + fmt(" + %.4g v kN", r.b / kilo) +
           fmt(" (v in m/s); R^2 = %.3f", r.r_squared) + fmt("; sigma = %.4g kN", r.sigma / kilo);
}

}  // namespace

void print_fit_text(std::ostream& out, const FitView& view) {
    const risk::Identification& id = view.identification;
    out << "impacts: " << describe(*view.impacts.data, view.impacts.input, view.impacts.velocity)
        << '\n'
        << "regression: " << view.regression
        << (view.regression == "power"
                ? ", P = a v^b by least squares on ln P; sigma is the residual sd of ln P"
                : ", P = a + b v by least squares; sigma is the residual sd of P")
        << '\n';
    for (const risk::ShapeFit& result : view.identification.fits) {
        const risk::ImpactFit& f = result.fit;
        const risk::ImpactCoefficients& c = f.coefficients;
        const risk::ImpactCoefficients preset = risk::seed_coefficients(result.shape);
        out << '\n'
            << risk::to_string(result.shape) << ": " << f.count << " rows\n"
            << "  valid for: impact velocity " << fmt("%.4g", f.velocity_min) << " .. "
            << fmt("%.4g m/s", f.velocity_max) << ", mass " << fmt("%.4g", f.mass_min) << " .. "
            << fmt("%.4g kg", f.mass_max) << fmt(" (regression at %.4g kg)", f.reference_mass)
            << '\n'
            << "  mean line: " << line_text(f.regression) << '\n'
            << "  lambda = " << fmt("%.4g Pa", c.lambda) << fmt(" (%.4g MN/m2), ", c.lambda / 1e6)
            << lambda_words(result.lambda_source).text << '\n'
            << "  beta = " << fmt("%.3g", c.beta) << '\n'
            << "  alpha = " << fmt("%.3g", c.alpha) << ", identified on the mean + 1 sigma line\n"
            << "  formula vs lines at the data: mean within "
            << fmt("%.1f %%", 100.0 * f.mean_mismatch) << ", mean + 1 sigma within "
            << fmt("%.1f %%", 100.0 * f.upper_mismatch) << '\n'
            << "  seed 000 preset: lambda " << fmt("%.4g Pa", preset.lambda) << ", alpha "
            << fmt("%.3g", preset.alpha) << ", beta " << fmt("%.3g", preset.beta) << '\n';
    }
    if (!id.too_few.empty()) {
        out << "\nnot fitted, fewer than " << risk::kMinFitRows << " rows: " << too_few_text(id)
            << '\n';
    }
    if (view.svg) out << "\nfigure written to " << *view.svg << '\n';
}

nlohmann::json fit_json(const FitView& view) {
    const ImpactData& data = *view.impacts.data;
    const risk::Identification& id = view.identification;
    nlohmann::json fits = nlohmann::json::array();
    for (const risk::ShapeFit& result : view.identification.fits) {
        const risk::ImpactFit& f = result.fit;
        const risk::ImpactCoefficients preset = risk::seed_coefficients(result.shape);
        const bool power = f.regression.form == risk::RegressionForm::power;
        fits.push_back(
            {{"shape", std::string(risk::to_string(result.shape))},
             {"rows", f.count},
             {"velocity_min_m_s", f.velocity_min},
             {"velocity_max_m_s", f.velocity_max},
             {"mass_min_kg", f.mass_min},
             {"mass_max_kg", f.mass_max},
             {"reference_mass_kg", f.reference_mass},
             {"regression",
              {{"form", std::string(risk::to_string(f.regression.form))},
               {"a", f.regression.a},
               {"a_unit", power ? "N (s/m)^b" : "N"},
               {"b", f.regression.b},
               {"b_unit", power ? "1" : "N s/m"},
               {"sigma", f.regression.sigma},
               {"sigma_unit", power ? "1 (of ln P)" : "N"},
               {"r_squared", f.regression.r_squared}}},
             {"lambda_Pa", f.coefficients.lambda},
             {"lambda_source", lambda_words(result.lambda_source).key},
             {"alpha", f.coefficients.alpha},
             {"beta", f.coefficients.beta},
             {"mean_mismatch", f.mean_mismatch},
             {"upper_mismatch", f.upper_mismatch},
             {"seed_preset",
              {{"lambda_Pa", preset.lambda}, {"alpha", preset.alpha}, {"beta", preset.beta}}}});
    }
    nlohmann::json not_fitted = nlohmann::json::object();
    for (const auto& [shape, n] : id.too_few) not_fitted[std::string(risk::to_string(shape))] = n;
    return {{"input", view.impacts.input},
            {"source", data.from_database ? "database" : "csv"},
            {"rows", data.rows.size()},
            {"skipped", data.skipped},
            {"slow", data.slow},
            {"min_velocity_m_s", view.impacts.min_velocity},
            {"later_hits", data.later},
            {"first_hits_only", view.impacts.first_hits},
            {"not_fitted", not_fitted},
            {"velocity", data.from_database ? nlohmann::json(to_string(view.impacts.velocity))
                                            : nlohmann::json(nullptr)},
            {"regression", view.regression},
            {"fits", fits},
            {"svg", view.svg ? nlohmann::json(*view.svg) : nlohmann::json(nullptr)}};
}

}  // namespace rockfall::report
