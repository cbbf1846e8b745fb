#pragma once
/// The figure of `rockfall fit --svg`: peak load against impact velocity with the regression
/// lines and the formula envelopes, in the manner of seed 000's Figure 7.

#include "report/svg_plot.hpp"

#include "risk/impact_identification.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace rockfall::report {

using risk::ShapeFit;

/// The plot: per shape (colour and marker by shape) the data (scaled to the reference mass
/// when the masses differ), the mean and mean + 1 sigma regression lines over the data's
/// velocity range, the identified envelope alpha beta P_JRA(lambda) and seed 000's preset for
/// the shape over the whole axis; loads in kN.
Plot fit_figure(const std::vector<ShapeFit>& fits, const std::string& title);

}  // namespace rockfall::report
