#pragma once
/// The figure of `rockfall fit --svg`: peak load against impact velocity with the regression
/// lines and the formula envelopes, in the manner of seed 000's Figure 7.

#include "report/impact_data.hpp"
#include "report/svg_plot.hpp"

#include "risk/envelope.hpp"
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

/// The comparison of `rockfall envelope` drawn the same way: per shape the impacts of `data`
/// scaled to the median mass of that shape's rows by the formula's m^(2/3), and the formula's
/// envelope for that shape at that mass, so that a point lies above its curve exactly when
/// its ratio (`compared`) exceeds 1; loads in kN against the velocity the formula was given.
Plot envelope_figure(const ImpactData& data, const std::vector<risk::ComparedImpact>& compared,
                     const risk::EnvelopeFormula& formula, const std::string& title);

}  // namespace rockfall::report
