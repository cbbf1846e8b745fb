// The wall-load history figure (see load_history_figure.hpp).

#include "report/load_history_figure.hpp"

#include <filesystem>

namespace rockfall::report {
namespace {

constexpr double n_per_kn = 1.0e3;

const char* load_unit(bool per_metre) { return per_metre ? "kN/m" : "kN"; }

}  // namespace

Plot load_history_plot(const std::string& title, const risk::LoadHistory& sampled,
                       const std::string& sampled_label, const risk::LoadHistory& filtered,
                       const std::string& filtered_label, const risk::LoadHistory* measured) {
    auto series = [](const risk::LoadHistory& h, std::string label, std::string color,
                     double width) {
        Series s;
        s.label = std::move(label);
        s.color = std::move(color);
        s.line_width = width;
        s.x = h.time;
        for (const double f : h.load) {
            s.y.push_back(f / n_per_kn);
        }
        return s;
    };
    Plot plot;
    plot.title = title;
    plot.x_label = "time since release (s)";
    plot.y_label =
        std::string("wall load normal to the wall (") + load_unit(sampled.per_metre) + ")";
    plot.series.push_back(series(sampled, sampled_label, "#9e9e9e", 1.0));
    plot.series.push_back(series(filtered, filtered_label, "#1f77b4", 2.5));
    if (measured != nullptr) {
        const std::string name = std::filesystem::path(measured->source).filename().string();
        Series m = series(*measured, "measured (" + name + ")", "#d62728", 2.0);
        m.dash = "6 4";
        plot.series.push_back(std::move(m));
    }
    plot.y_min = 0.0;
    return plot;
}

}  // namespace rockfall::report
