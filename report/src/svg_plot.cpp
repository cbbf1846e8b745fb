// SVG x-y plots with nice ticks and a legend (see svg_plot.hpp).

#include "report/svg_plot.hpp"

#include "svg_detail.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rockfall::report {
namespace svg_detail {

std::string num(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", value);
    return buffer;
}

std::string escaped(const std::string& text) {
    std::string out;
    for (const char c : text) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string svg_open(double width, double height) {
    return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + num(width) + "\" height=\"" +
           num(height) + "\" viewBox=\"0 0 " + num(width) + ' ' + num(height) +
           "\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\">\n"
           "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
}

void write_axes(std::ostream& out, const Frame& f, const Plot& plot) {
    const PlotArea& a = f.area;
    char label[64];
    out << "<g stroke=\"#e3e3e3\" stroke-width=\"1\">\n";
    for (double v : f.x.values) {
        out << "<line x1=\"" << num(f.px(v)) << "\" y1=\"" << num(a.top) << "\" x2=\""
            << num(f.px(v)) << "\" y2=\"" << num(a.bottom) << "\"/>\n";
    }
    for (double v : f.y.values) {
        out << "<line x1=\"" << num(a.left) << "\" y1=\"" << num(f.py(v)) << "\" x2=\""
            << num(a.right) << "\" y2=\"" << num(f.py(v)) << "\"/>\n";
    }
    out << "</g>\n<rect x=\"" << num(a.left) << "\" y=\"" << num(a.top) << "\" width=\""
        << num(a.right - a.left) << "\" height=\"" << num(a.bottom - a.top)
        << "\" fill=\"none\" stroke=\"#333333\" stroke-width=\"1\"/>\n";
    out << "<g font-size=\"" << num(font_size) << "\" fill=\"#333333\">\n";
    for (double v : f.x.values) {
        std::snprintf(label, sizeof label, "%.*f", f.x.decimals, v);
        out << "<text x=\"" << num(f.px(v)) << "\" y=\"" << num(a.bottom + 18)
            << "\" text-anchor=\"middle\">" << label << "</text>\n";
    }
    for (double v : f.y.values) {
        std::snprintf(label, sizeof label, "%.*f", f.y.decimals, v);
        out << "<text x=\"" << num(a.left - 8) << "\" y=\"" << num(f.py(v) + 4.5)
            << "\" text-anchor=\"end\">" << label << "</text>\n";
    }
    const double mid_x = 0.5 * (a.left + a.right);
    const double mid_y = 0.5 * (a.top + a.bottom);
    out << "<text x=\"" << num(mid_x) << "\" y=\"" << num(a.bottom + 46)
        << "\" text-anchor=\"middle\" font-size=\"" << num(font_size + 1) << "\">"
        << escaped(plot.x_label) << "</text>\n";
    out << "<text x=\"" << num(a.left - 62) << "\" y=\"" << num(mid_y)
        << "\" text-anchor=\"middle\" font-size=\"" << num(font_size + 1)
        << "\" transform=\"rotate(-90 " << num(a.left - 62) << ' ' << num(mid_y) << ")\">"
        << escaped(plot.y_label) << "</text>\n";
    out << "<text x=\"" << num(mid_x) << "\" y=\"" << num(a.top - 18)
        << "\" text-anchor=\"middle\" font-size=\"" << num(font_size + 3)
        << "\" font-weight=\"bold\">" << escaped(plot.title) << "</text>\n</g>\n";
}

Ticks axis_ticks(double data_low, double data_high, std::optional<double> low,
                 std::optional<double> high) {
    Ticks ticks = nice_ticks(low.value_or(data_low), high.value_or(data_high));
    // A fixed end stays where it was asked to be, even between two ticks.
    if (low) ticks.lower = *low;
    if (high) ticks.upper = *high;
    std::erase_if(ticks.values, [&](double v) {
        const double slack = 1e-9 * ticks.step;
        return v < ticks.lower - slack || v > ticks.upper + slack;
    });
    return ticks;
}

}  // namespace svg_detail

namespace {

using svg_detail::axis_ticks;
using svg_detail::escaped;
using svg_detail::font_size;
using svg_detail::Frame;
using svg_detail::num;
using svg_detail::write_axes;

using svg_detail::margin_bottom;
using svg_detail::margin_left;
using svg_detail::margin_top;

// Layout, px: the right margin, the legend.
constexpr double margin_right = 24.0;
// Average advance of a sans-serif character at font_size, to size the legend box.
constexpr double char_width = 6.2;
constexpr double legend_sample = 30.0;
constexpr double legend_row = 20.0;
constexpr double legend_pad = 10.0;
constexpr double max_legend_width = 420.0;

// Heckbert (1990): the "nice" number nearest x (> 0), 1, 2, 5 or 10 times a power of ten.
double nice_number(double x) {
    const double power = std::pow(10.0, std::floor(std::log10(x)));
    const double f = x / power;
    return (f < 1.5 ? 1.0 : f < 3.0 ? 2.0 : f < 7.0 ? 5.0 : 10.0) * power;
}

bool has_legend(const Plot& plot) {
    return std::any_of(plot.series.begin(), plot.series.end(),
                       [](const Series& s) { return !s.label.empty(); });
}

double legend_width(const Plot& plot) {
    std::size_t longest = 0;
    for (const Series& s : plot.series) longest = std::max(longest, s.label.size());
    const double width = 3.0 * legend_pad + legend_sample + char_width * double(longest);
    return std::min(width, max_legend_width);
}

void check_series(const Series& s) {
    if (s.x.size() != s.y.size()) {
        throw std::invalid_argument("plot series \"" + s.label +
                                    "\": " + std::to_string(s.x.size()) + " x values but " +
                                    std::to_string(s.y.size()) + " y values");
    }
    for (std::size_t i = 0; i < s.x.size(); ++i) {
        if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) {
            throw std::invalid_argument("plot series \"" + s.label + "\": point " +
                                        std::to_string(i) + " is not finite");
        }
    }
}

void write_marker(std::ostream& out, Marker marker, double cx, double cy, double size,
                  const std::string& color, double opacity) {
    const std::string style = " fill=\"" + color + "\" fill-opacity=\"" + num(opacity * 0.85) +
                              "\" stroke=\"" + color + "\" stroke-opacity=\"" + num(opacity) + "\"";
    switch (marker) {
        case Marker::none:
            return;
        case Marker::circle:
            out << "<circle cx=\"" << num(cx) << "\" cy=\"" << num(cy) << "\" r=\"" << num(size)
                << '"' << style << "/>\n";
            return;
        case Marker::square:
            out << "<rect x=\"" << num(cx - size) << "\" y=\"" << num(cy - size) << "\" width=\""
                << num(2 * size) << "\" height=\"" << num(2 * size) << '"' << style << "/>\n";
            return;
        case Marker::triangle:
            out << "<polygon points=\"" << num(cx) << ',' << num(cy - 1.2 * size) << ' '
                << num(cx - 1.04 * size) << ',' << num(cy + 0.6 * size) << ' '
                << num(cx + 1.04 * size) << ',' << num(cy + 0.6 * size) << '"' << style << "/>\n";
            return;
    }
}

void write_line(std::ostream& out, const std::vector<std::pair<double, double>>& points,
                const Series& s) {
    out << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\""
        << num(s.line_width) << "\" stroke-opacity=\"" << num(s.opacity)
        << "\" stroke-linejoin=\"round\"";
    if (!s.dash.empty()) out << " stroke-dasharray=\"" << s.dash << '"';
    out << " points=\"";
    for (std::size_t i = 0; i < points.size(); ++i) {
        out << (i ? " " : "") << num(points[i].first) << ',' << num(points[i].second);
    }
    out << "\"/>\n";
}

void write_legend(std::ostream& out, const Plot& plot, const PlotArea& a) {
    std::size_t entries = 0;
    for (const Series& s : plot.series) entries += s.label.empty() ? 0 : 1;
    const double left = a.right + legend_pad * 1.5;
    const double height = legend_pad + legend_row * double(entries);
    out << "<g font-size=\"" << num(font_size - 1) << "\" fill=\"#333333\">\n<rect x=\""
        << num(left) << "\" y=\"" << num(a.top) << "\" width=\"" << num(legend_width(plot))
        << "\" height=\"" << num(height) << "\" fill=\"white\" stroke=\"#bbbbbb\"/>\n";
    double y = a.top + legend_pad + legend_row * 0.5 - 2;
    for (const Series& s : plot.series) {
        if (s.label.empty()) continue;
        const double x0 = left + legend_pad;
        if (s.line) write_line(out, {{x0, y}, {x0 + legend_sample, y}}, s);
        write_marker(out, s.marker, x0 + 0.5 * legend_sample, y, s.marker_size, s.color, s.opacity);
        out << "<text x=\"" << num(x0 + legend_sample + legend_pad) << "\" y=\"" << num(y + 4)
            << "\">" << escaped(s.label) << "</text>\n";
        y += legend_row;
    }
    out << "</g>\n";
}

}  // namespace

Ticks nice_ticks(double lower, double upper, int target) {
    if (!std::isfinite(lower) || !std::isfinite(upper) || lower > upper || target < 2) {
        throw std::invalid_argument("nice_ticks: needs finite lower <= upper and target >= 2");
    }
    if (lower == upper) {
        const double widen = lower == 0.0 ? 1.0 : 0.1 * std::abs(lower);
        lower -= widen;
        upper += widen;
    }
    Ticks t;
    t.step = nice_number((upper - lower) / double(target - 1));
    const double first = std::floor(lower / t.step + 1e-9);
    const double last = std::ceil(upper / t.step - 1e-9);
    t.lower = first * t.step;
    t.upper = last * t.step;
    for (double k = first; k <= last + 0.5; k += 1.0) {
        const double v = k * t.step;
        t.values.push_back(v == 0.0 ? 0.0 : v);  // no "-0"
    }
    t.decimals = std::max(0, static_cast<int>(-std::floor(std::log10(t.step) + 1e-9)));
    return t;
}

PlotArea plot_area(const Plot& plot) {
    const double legend = has_legend(plot) ? legend_width(plot) + 2.0 * legend_pad : 0.0;
    return {margin_left, margin_top, plot.width - margin_right - legend,
            plot.height - margin_bottom};
}

std::pair<Ticks, Ticks> plot_ticks(const Plot& plot) {
    double x_low = std::numeric_limits<double>::infinity();
    double x_high = -x_low;
    double y_low = x_low;
    double y_high = -x_low;
    for (const Series& s : plot.series) {
        check_series(s);
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            x_low = std::min(x_low, s.x[i]);
            x_high = std::max(x_high, s.x[i]);
            y_low = std::min(y_low, s.y[i]);
            y_high = std::max(y_high, s.y[i]);
        }
    }
    if (!(x_low <= x_high)) throw std::invalid_argument("plot \"" + plot.title + "\": no data");
    return {axis_ticks(x_low, x_high, plot.x_min, plot.x_max),
            axis_ticks(y_low, y_high, plot.y_min, plot.y_max)};
}

std::string render_svg(const Plot& plot) {
    const auto [x_ticks, y_ticks] = plot_ticks(plot);
    const Frame frame{plot_area(plot), x_ticks, y_ticks};
    const PlotArea& a = frame.area;
    std::ostringstream out;
    out << svg_detail::svg_open(plot.width, plot.height) << "<defs><clipPath id=\""
        << svg_detail::escaped(plot.id_prefix) << "plot-area\"><rect x=\"" << num(a.left)
        << "\" y=\"" << num(a.top) << "\" width=\"" << num(a.right - a.left) << "\" height=\""
        << num(a.bottom - a.top) << "\"/></clipPath></defs>\n";
    write_axes(out, frame, plot);
    out << "<g clip-path=\"url(#" << svg_detail::escaped(plot.id_prefix) << "plot-area)\">\n";
    for (const Series& s : plot.series) {
        std::vector<std::pair<double, double>> points;
        for (std::size_t i = 0; i < s.x.size(); ++i) {
            points.emplace_back(frame.px(s.x[i]), frame.py(s.y[i]));
        }
        if (s.line && points.size() >= 2) write_line(out, points, s);
        for (const auto& [px, py] : points) {
            write_marker(out, s.marker, px, py, s.marker_size, s.color, s.opacity);
        }
    }
    out << "</g>\n";
    if (has_legend(plot)) write_legend(out, plot, a);
    out << "</svg>\n";
    return out.str();
}

}  // namespace rockfall::report
