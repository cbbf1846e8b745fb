#pragma once
/// What `rockfall fit` prints: per shape the rows, the range the fit is valid for, the
/// regression lines, lambda (and where it came from), beta and alpha, how closely the formula
/// follows the lines, and seed 000's preset beside them. Loads in kN in the text, N in the
/// JSON.

#include "report/impact_data.hpp"

#include "risk/impact_identification.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace rockfall::report {

/// One identification, as computed by risk::identify_shapes.
struct FitView {
    ImpactSelection impacts;
    /// "power" or "linear".
    std::string regression = "power";
    risk::Identification identification;
    /// Where the figure was written, if it was.
    std::optional<std::string> svg;
};

/// The readable summary.
void print_fit_text(std::ostream& out, const FitView& view);

/// The same as one JSON document.
nlohmann::json fit_json(const FitView& view);

}  // namespace rockfall::report
