#pragma once
/// What `rockfall envelope` prints: every wall impact against the design formula for its
/// rock's mass, shape and impact velocity; the ratio's distribution for all impacts and per
/// shape, the share above the envelope with its interval, and the worst impacts with the
/// sample, hit and seed that reproduce them. Loads in kN in the text, N in the JSON.

#include "report/impact_data.hpp"

#include "risk/envelope.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace rockfall::report {

/// One comparison, as computed by risk::compare_with_formula.
struct EnvelopeView {
    ImpactSelection impacts;
    /// The formula and the comparison of every row with it.
    risk::EnvelopeFormula formula;
    std::vector<risk::ComparedImpact> compared;
    /// Confidence of the intervals, in (0, 1).
    double confidence = 0.95;
    /// Indices into `compared` of the worst impacts, worst first (risk::worst_impacts).
    std::vector<std::size_t> worst;
};

/// The readable summary: sources, formula per shape, statistics, worst-impact table.
void print_envelope_text(std::ostream& out, const EnvelopeView& view);

/// The same as one JSON document.
nlohmann::json envelope_json(const EnvelopeView& view);

}  // namespace rockfall::report
