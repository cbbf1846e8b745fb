#pragma once
/// The wall-load history figure of a soil flow, with a measured record when given.

#include "report/svg_plot.hpp"

#include "risk/load_history.hpp"

#include <string>

namespace rockfall::report {

/// The figure: the simulated load as sampled (thin grey), filtered (thick) and, when given,
/// the measured record (dashed red, labelled with its file name), in kN (kN/m) against time in
/// s, titled `title`; the labels name the sampling and the filter in the legend.
Plot load_history_plot(const std::string& title, const risk::LoadHistory& sampled,
                       const std::string& sampled_label, const risk::LoadHistory& filtered,
                       const std::string& filtered_label, const risk::LoadHistory* measured);

}  // namespace rockfall::report
