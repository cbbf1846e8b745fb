// Exceedance curves as a figure (see curve_figure.hpp).

#include "report/curve_figure.hpp"

#include <array>
#include <cstddef>

namespace rockfall::report {
namespace {

// Tableau 10 colours: distinct in print and for the common colour-vision deficiencies.
constexpr std::array<const char*, 10> palette{"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728",
                                              "#9467bd", "#8c564b", "#e377c2", "#7f7f7f",
                                              "#bcbd22", "#17becf"};

}  // namespace

Plot curve_figure(const db::ExceedanceCurve& curve, const std::string& title) {
    const std::string name(db::to_string(curve.quantity));
    const std::string unit(db::unit_of(curve.quantity));
    Plot plot;
    plot.title = title;
    plot.x_label = curve.quantity == db::Quantity::reach ? "reach past the toe x (m)"
                                                         : name + " x (" + unit + ")";
    plot.y_label = "probability that " + name + " >= x";
    plot.y_min = 0.0;
    plot.y_max = 1.0;
    const std::string band = std::to_string(static_cast<int>(curve.confidence * 100.0 + 0.5)) +
                             " % " + std::string(db::display_name(curve.method));
    for (std::size_t g = 0; g < curve.groups.size(); ++g) {
        const db::CurveGroup& group = curve.groups[g];
        const char* color = palette[g % palette.size()];
        Series line;
        line.label = group.id.label + " (" + std::to_string(group.trials) + " trials)";
        line.color = color;
        line.line_width = 2.0;
        Series lower;
        lower.label = g == 0 ? band : "";
        lower.color = color;
        lower.line_width = 0.8;
        lower.dash = "4 3";
        Series upper = lower;
        upper.label.clear();
        for (const db::CurvePoint& p : group.points) {
            line.x.push_back(p.threshold);
            line.y.push_back(p.probability);
            lower.x.push_back(p.threshold);
            lower.y.push_back(p.interval.lower);
            upper.x.push_back(p.threshold);
            upper.y.push_back(p.interval.upper);
        }
        plot.series.push_back(std::move(lower));
        plot.series.push_back(std::move(upper));
        plot.series.push_back(std::move(line));
    }
    return plot;
}

}  // namespace rockfall::report
