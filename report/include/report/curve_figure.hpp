#pragma once
/// The figure of `rockfall query DB curve --svg`: exceedance curves P(Q >= x) against x, one
/// line per group with its confidence band as thin dashed lines of the same colour.

#include "report/svg_plot.hpp"

#include "db/queries.hpp"

#include <string>

namespace rockfall::report {

/// The plot: x in the quantity's unit, probability on [0, 1]; the legend names the groups
/// ("all" when not broken down) and the interval.
Plot curve_figure(const db::ExceedanceCurve& curve, const std::string& title);

}  // namespace rockfall::report
