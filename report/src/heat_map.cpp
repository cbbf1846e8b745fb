// SVG heat maps with a colour bar (see heat_map.hpp).

#include "report/heat_map.hpp"

#include "svg_detail.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace rockfall::report {
namespace {

using svg_detail::escaped;
using svg_detail::font_size;
using svg_detail::num;

// Viridis: every 17th of the 256 entries of matplotlib's _viridis_data (entries 0, 17, ...,
// 255), from the original mpl-colormaps colormaps.py by Nathaniel J. Smith, Stefan van der Walt
// and Eric Firing (CC0, https://github.com/BIDS/colormap); linear interpolation between them
// differs from the full table by less than 1/255.
constexpr std::array<std::array<double, 3>, 16> viridis_anchors{{
    {0.267004, 0.004874, 0.329415},
    {0.282656, 0.100196, 0.422160},
    {0.277134, 0.185228, 0.489898},
    {0.253935, 0.265254, 0.529983},
    {0.221989, 0.339161, 0.548752},
    {0.190631, 0.407061, 0.556089},
    {0.163625, 0.471133, 0.558148},
    {0.139147, 0.533812, 0.555298},
    {0.120565, 0.596422, 0.543611},
    {0.134692, 0.658636, 0.517649},
    {0.208030, 0.718701, 0.472873},
    {0.327796, 0.773980, 0.406640},
    {0.477504, 0.821444, 0.318195},
    {0.647257, 0.858400, 0.209861},
    {0.824940, 0.884720, 0.106217},
    {0.993248, 0.906157, 0.143936},
}};

using svg_detail::margin_bottom;
using svg_detail::margin_left;
using svg_detail::margin_top;

// Layout, px: the colour bar right of the map; the legend rows below the x label.
constexpr double bar_gap = 30.0;
constexpr double bar_width = 22.0;
constexpr double legend_row = 22.0;
constexpr double swatch = 14.0;
// Average advance of a sans-serif character at the tick-label font size.
constexpr double char_width = 7.0;
constexpr const char* empty_colour = "#e6e6e6";
constexpr const char* flag_colour = "#d62728";

void check(const HeatMap& map) {
    if (map.columns < 1 || map.rows < 1) {
        throw std::invalid_argument("heat map \"" + map.title +
                                    "\": " + std::to_string(map.columns) + " x " +
                                    std::to_string(map.rows) + " cells: needs at least 1 x 1");
    }
    const auto cells = static_cast<std::size_t>(map.columns) * static_cast<std::size_t>(map.rows);
    if (map.values.size() != cells || (!map.flagged.empty() && map.flagged.size() != cells)) {
        throw std::invalid_argument("heat map \"" + map.title +
                                    "\": " + std::to_string(map.values.size()) + " values and " +
                                    std::to_string(map.flagged.size()) + " flags for " +
                                    std::to_string(cells) + " cells");
    }
    if (!(map.x_min < map.x_max) || !(map.y_min < map.y_max)) {
        throw std::invalid_argument("heat map \"" + map.title + "\": empty extent");
    }
    for (const double v : map.values) {
        if (std::isinf(v)) {
            throw std::invalid_argument("heat map \"" + map.title + "\": an infinite value");
        }
    }
}

std::string tick_label(double value, int decimals) {
    char label[64];
    std::snprintf(label, sizeof label, "%.*f", decimals, value);
    return label;
}

// One legend entry: its swatch (SVG drawn with its top-left corner at the origin) and text.
struct LegendEntry {
    std::string text;
    std::string swatch;
};

// Top-left corners of the entries, in rows from (left, top) wrapped before `right`.
std::vector<std::pair<double, double>> legend_layout(const std::vector<LegendEntry>& entries,
                                                     double left, double top, double right) {
    std::vector<std::pair<double, double>> at;
    double x = left;
    double y = top;
    for (const LegendEntry& e : entries) {
        const double width = swatch + 8.0 + char_width * 0.95 * double(e.text.size()) + 24.0;
        if (x > left && x + width > right) {
            x = left;
            y += legend_row;
        }
        at.emplace_back(x, y);
        x += width;
    }
    return at;
}

void write_legend(std::ostream& out, const std::vector<LegendEntry>& entries,
                  const std::vector<std::pair<double, double>>& at) {
    out << "<g font-size=\"" << num(font_size - 1) << "\" fill=\"#333333\">\n";
    for (std::size_t i = 0; i < entries.size(); ++i) {
        const auto [x, y] = at[i];
        out << "<g transform=\"translate(" << num(x) << ' ' << num(y) << ")\">" << entries[i].swatch
            << "</g>\n<text x=\"" << num(x + swatch + 8.0) << "\" y=\"" << num(y + swatch - 2.0)
            << "\">" << escaped(entries[i].text) << "</text>\n";
    }
    out << "</g>\n";
}

}  // namespace

std::array<double, 3> viridis(double f) {
    const double t = std::clamp(std::isnan(f) ? 0.0 : f, 0.0, 1.0) * 15.0;
    const auto k = std::min<std::size_t>(14, static_cast<std::size_t>(t));
    const double w = t - static_cast<double>(k);
    std::array<double, 3> rgb{};
    for (std::size_t c = 0; c < 3; ++c) {
        rgb[c] = (1.0 - w) * viridis_anchors[k][c] + w * viridis_anchors[k + 1][c];
    }
    return rgb;
}

std::string viridis_hex(double f) {
    const std::array<double, 3> rgb = viridis(f);
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", static_cast<int>(std::lround(rgb[0] * 255)),
                  static_cast<int>(std::lround(rgb[1] * 255)),
                  static_cast<int>(std::lround(rgb[2] * 255)));
    return hex;
}

Ticks heat_map_scale(const HeatMap& map) {
    double top = 0.0;
    for (const double v : map.values) {
        if (std::isfinite(v)) top = std::max(top, v);
    }
    if (top == 0.0 && !map.value_max) top = 1.0;
    return svg_detail::axis_ticks(0.0, top, 0.0, map.value_max);
}

std::string render_heat_map_svg(const HeatMap& map) {
    check(map);
    const double x_span = map.x_max - map.x_min;
    const double y_span = map.y_max - map.y_min;
    const double map_width = std::max(100.0, map.map_width);
    const double map_height = std::min(1.2 * map_width, map_width * y_span / x_span);
    const PlotArea area{margin_left, margin_top, margin_left + map_width, margin_top + map_height};

    Ticks x = svg_detail::axis_ticks(map.x_min, map.x_max, map.x_min, map.x_max);
    if (map.mirror_x) std::swap(x.lower, x.upper);
    const Ticks y = svg_detail::axis_ticks(map.y_min, map.y_max, map.y_min, map.y_max);
    const svg_detail::Frame frame{area, x, y};
    const Ticks scale = heat_map_scale(map);

    std::size_t longest = 0;
    for (const double v : scale.values) {
        longest = std::max(longest, tick_label(v, scale.decimals).size());
    }
    const double bar_left = area.right + bar_gap;
    const double bar_right = bar_left + bar_width;
    const double bar_label_x = bar_right + 12.0 + char_width * double(longest) + 16.0;
    const double width = bar_label_x + 24.0;

    std::vector<LegendEntry> legend;
    const bool any_flag =
        std::find(map.flagged.begin(), map.flagged.end(), true) != map.flagged.end();
    if (!map.flagged_label.empty()) {
        legend.push_back({map.flagged_label, "<rect width=\"" + num(swatch) + "\" height=\"" +
                                                 num(swatch) +
                                                 "\" fill=\"url(#flagged)\" stroke=\"" +
                                                 flag_colour + "\" stroke-width=\"2\"/>"});
    }
    if (!map.empty_label.empty()) {
        legend.push_back({map.empty_label, "<rect width=\"" + num(swatch) + "\" height=\"" +
                                               num(swatch) + "\" fill=\"" + empty_colour +
                                               "\" stroke=\"#999999\"/>"});
    }
    const bool mark_shown =
        map.mark && *map.mark >= scale.lower && *map.mark <= scale.upper && !map.mark_label.empty();
    if (mark_shown) {
        legend.push_back({map.mark_label, "<line x1=\"0\" y1=\"" + num(swatch / 2) + "\" x2=\"" +
                                              num(swatch) + "\" y2=\"" + num(swatch / 2) +
                                              "\" stroke=\"" + flag_colour +
                                              "\" stroke-width=\"2.5\"/>"});
    }
    const double legend_top = area.bottom + margin_bottom + 2.0;
    const auto legend_at = legend_layout(legend, area.left, legend_top, width - 10.0);
    const double legend_bottom =
        legend_at.empty() ? area.bottom + margin_bottom - legend_row : legend_at.back().second;
    const double height = legend_bottom + legend_row + 8.0;

    std::ostringstream out;
    out << svg_detail::svg_open(width, height);
    out << "<defs>\n<pattern id=\"flagged\" patternUnits=\"userSpaceOnUse\" width=\"6\" "
           "height=\"6\" patternTransform=\"rotate(45)\"><rect width=\"6\" height=\"6\" "
           "fill=\"white\" fill-opacity=\"0.35\"/><line x1=\"0\" y1=\"0\" x2=\"0\" y2=\"6\" "
           "stroke=\"black\" stroke-width=\"2\"/></pattern>\n"
        << "<linearGradient id=\"colour-scale\" x1=\"0\" y1=\"1\" x2=\"0\" y2=\"0\">\n";
    for (std::size_t k = 0; k < viridis_anchors.size(); ++k) {
        const double f = double(k) / double(viridis_anchors.size() - 1);
        out << "<stop offset=\"" << num(f) << "\" stop-color=\"" << viridis_hex(f) << "\"/>\n";
    }
    out << "</linearGradient>\n</defs>\n";
    Plot labels;
    labels.title = map.title;
    labels.x_label = map.x_label;
    labels.y_label = map.y_label;
    svg_detail::write_axes(out, frame, labels);

    // Cells, then the flagged ones on top so that their outline is not covered.
    const double cell_x = x_span / map.columns;
    const double cell_y = y_span / map.rows;
    auto cell_rect = [&](int column, int row) {
        const double x0 = frame.px(map.x_min + cell_x * column);
        const double x1 = frame.px(map.x_min + cell_x * (column + 1));
        const double y0 = frame.py(map.y_min + cell_y * (row + 1));
        const double y1 = frame.py(map.y_min + cell_y * row);
        return "<rect x=\"" + num(std::min(x0, x1)) + "\" y=\"" + num(y0) + "\" width=\"" +
               num(std::abs(x1 - x0)) + "\" height=\"" + num(y1 - y0) + "\"";
    };
    out << "<g stroke=\"white\" stroke-width=\"0.5\">\n";
    for (int row = 0; row < map.rows; ++row) {
        for (int column = 0; column < map.columns; ++column) {
            const double v = map.values[static_cast<std::size_t>(row * map.columns + column)];
            const std::string fill =
                std::isnan(v) ? empty_colour
                              : viridis_hex((v - scale.lower) / (scale.upper - scale.lower));
            out << cell_rect(column, row) << " fill=\"" << fill << "\"/>\n";
        }
    }
    out << "</g>\n<g fill=\"url(#flagged)\" stroke=\"" << flag_colour << "\" stroke-width=\"2\">\n";
    for (std::size_t i = 0; any_flag && i < map.flagged.size(); ++i) {
        if (!map.flagged[i]) continue;
        const int column = static_cast<int>(i) % map.columns;
        const int row = static_cast<int>(i) / map.columns;
        out << cell_rect(column, row) << " class=\"flagged\"/>\n";
    }
    out << "</g>\n<rect x=\"" << num(area.left) << "\" y=\"" << num(area.top) << "\" width=\""
        << num(area.right - area.left) << "\" height=\"" << num(area.bottom - area.top)
        << "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";

    // The colour bar: the gradient, its ticks and labels, the mark and the label.
    auto bar_y = [&](double v) {
        return area.bottom - (v - scale.lower) / (scale.upper - scale.lower) * map_height;
    };
    out << "<rect x=\"" << num(bar_left) << "\" y=\"" << num(area.top) << "\" width=\""
        << num(bar_width) << "\" height=\"" << num(map_height)
        << "\" fill=\"url(#colour-scale)\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
    out << "<g font-size=\"" << num(font_size) << "\" fill=\"#333333\" stroke=\"none\">\n";
    for (const double v : scale.values) {
        out << "<line x1=\"" << num(bar_right) << "\" y1=\"" << num(bar_y(v)) << "\" x2=\""
            << num(bar_right + 5) << "\" y2=\"" << num(bar_y(v))
            << "\" stroke=\"#333333\"/>\n<text x=\"" << num(bar_right + 8) << "\" y=\""
            << num(bar_y(v) + 4.5) << "\" class=\"colour-bar-tick\">"
            << tick_label(v, scale.decimals) << "</text>\n";
    }
    const double mid_y = 0.5 * (area.top + area.bottom);
    out << "<text x=\"" << num(bar_label_x) << "\" y=\"" << num(mid_y)
        << "\" text-anchor=\"middle\" font-size=\"" << num(font_size + 1)
        << "\" transform=\"rotate(-90 " << num(bar_label_x) << ' ' << num(mid_y)
        << ")\" class=\"colour-bar-label\">" << escaped(map.value_label) << "</text>\n</g>\n";
    if (mark_shown) {
        out << "<line x1=\"" << num(bar_left - 4) << "\" y1=\"" << num(bar_y(*map.mark))
            << "\" x2=\"" << num(bar_right + 4) << "\" y2=\"" << num(bar_y(*map.mark))
            << "\" stroke=\"" << flag_colour << "\" stroke-width=\"2.5\"/>\n";
    }
    write_legend(out, legend, legend_at);
    out << "</svg>\n";
    return out.str();
}

}  // namespace rockfall::report
