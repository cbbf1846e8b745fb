// Peak load against impact velocity with regression lines and envelopes (see fit_figure.hpp).

#include "report/fit_figure.hpp"

#include "report/text_format.hpp"

#include "risk/statistics.hpp"

#include <algorithm>
#include <cmath>

namespace rockfall::report {
namespace {

constexpr double n_per_kn = 1.0e3;
// Points per drawn curve: smooth at figure size.
constexpr int curve_points = 80;

struct ShapeStyle {
    const char* color;
    Marker marker;
};

ShapeStyle style_of(risk::ImpactShape shape) {
    switch (shape) {
        case risk::ImpactShape::sphere:
            return {"#1f77b4", Marker::circle};
        case risk::ImpactShape::massive:
            return {"#d62728", Marker::square};
        case risk::ImpactShape::planar:
            return {"#2ca02c", Marker::triangle};
    }
    return {"#555555", Marker::circle};
}

// Line styles shared by every shape (colour tells the shape): the legend explains each once.
struct LineStyle {
    const char* meaning;
    const char* dash;
    double width;
    double opacity;
};

constexpr LineStyle envelope_style{"identified formula \u03b1 \u03b2 P(\u03bb)", "", 4.0, 0.35};
constexpr LineStyle preset_style{"seed 000 preset for the shape", "2 3", 1.2, 1.0};
constexpr LineStyle mean_style{"mean regression", "", 1.5, 1.0};
constexpr LineStyle upper_style{"mean + 1\u03c3 regression", "7 4", 1.5, 1.0};
constexpr LineStyle formula_style{"formula at the median mass", "", 2.0, 1.0};

Series styled(const LineStyle& style, const char* color) {
    Series s;
    s.color = color;
    s.dash = style.dash;
    s.line_width = style.width;
    s.opacity = style.opacity;
    return s;
}

// A legend-only entry for a line style, in grey.
Series key(const LineStyle& style) {
    Series s = styled(style, "#555555");
    s.label = style.meaning;
    return s;
}

// The style's curve of a load (N) over [from, to] m/s, drawn in kN.
template <typename F>
Series curve(const LineStyle& style, const char* color, double from, double to, F&& load) {
    Series s = styled(style, color);
    for (int i = 0; i <= curve_points; ++i) {
        const double v = from + (to - from) * i / curve_points;
        s.x.push_back(v);
        s.y.push_back(load(v) / n_per_kn);
    }
    return s;
}

// Loads scaled to the reference mass by the formula's m^(2/3), as the regression saw them.
double scaled_load(const risk::ImpactRow& row, double reference_mass) {
    return row.peak_force * std::pow(reference_mass / row.mass, 2.0 / 3.0);
}

// The shape's points, labelled with the shape and its identified coefficients.
Series data_of(const ShapeFit& f, const ShapeStyle& style, bool scaled) {
    const risk::ImpactFit& fit = f.fit;
    const risk::ImpactCoefficients& c = fit.coefficients;
    Series data;
    data.label = std::string(risk::to_string(f.shape)) + " (n = " + std::to_string(f.rows.size()) +
                 (scaled ? fmt(", at %.3g kg", fit.reference_mass) : "") +
                 fmt("): \u03b1 %.2f", c.alpha) + fmt(", \u03b2 %.2f", c.beta) +
                 fmt(", \u03bb %.0f MN/m\u00b2", c.lambda / 1.0e6);
    data.color = style.color;
    data.line = false;
    data.marker = style.marker;
    for (const risk::ImpactRow& row : f.rows) {
        data.x.push_back(row.velocity);
        data.y.push_back(scaled_load(row, fit.reference_mass) / n_per_kn);
    }
    return data;
}

}  // namespace

Plot fit_figure(const std::vector<ShapeFit>& fits, const std::string& title) {
    Plot plot;
    plot.title = title;
    plot.width = 1080.0;  // room for the legend beside a plot area about as wide as high
    plot.x_label = "impact velocity (m/s)";
    plot.x_min = 0.0;
    plot.y_min = 0.0;
    double v_max = 0.0;
    bool scaled = false;
    for (const ShapeFit& f : fits) {
        v_max = std::max(v_max, f.fit.velocity_max);
        scaled = scaled || f.fit.mass_min != f.fit.mass_max;
    }
    plot.x_max = nice_ticks(0.0, v_max).upper;
    plot.y_label = scaled ? "peak load at the reference mass (kN)" : "peak load (kN)";
    // Formula curves start just off zero, where H and so P vanish.
    const double v_from = 0.02 * *plot.x_max;

    double y_top = 0.0;
    for (const ShapeFit& f : fits) {
        const ShapeStyle style = style_of(f.shape);
        const risk::ImpactFit& fit = f.fit;
        const risk::ImpactCoefficients preset = risk::seed_coefficients(f.shape);
        plot.series.push_back(curve(envelope_style, style.color, v_from, *plot.x_max,
                                    [&](double v) { return fit.envelope(v); }));
        plot.series.push_back(curve(preset_style, style.color, v_from, *plot.x_max, [&](double v) {
            return risk::jra_impact_force(fit.reference_mass, v, preset);
        }));
        plot.series.push_back(curve(mean_style, style.color, fit.velocity_min, fit.velocity_max,
                                    [&](double v) { return fit.regression.mean(v); }));
        plot.series.push_back(curve(upper_style, style.color, fit.velocity_min, fit.velocity_max,
                                    [&](double v) { return fit.regression.upper(v); }));
        plot.series.push_back(data_of(f, style, scaled));
        for (const Series* s : {&plot.series.back(), &plot.series[plot.series.size() - 2]}) {
            y_top = std::max(y_top, *std::max_element(s->y.begin(), s->y.end()));
        }
    }
    for (const LineStyle* style : {&mean_style, &upper_style, &envelope_style, &preset_style}) {
        plot.series.push_back(key(*style));
    }
    // The envelopes run to the axis end and may dwarf the data: the axis shows the data and
    // the regression band with room above, and clips the envelopes.
    plot.y_max = nice_ticks(0.0, 1.3 * y_top).upper;
    return plot;
}

Plot envelope_figure(const ImpactData& data, const std::vector<risk::ComparedImpact>& compared,
                     const risk::EnvelopeFormula& formula, const std::string& title) {
    Plot plot;
    plot.title = title;
    plot.width = 1080.0;
    plot.x_label = "impact velocity (m/s)";
    plot.y_label = "peak load at the shape's median mass (kN)";
    plot.x_min = 0.0;
    plot.y_min = 0.0;
    double v_max = 0.0;
    for (const risk::ImpactRow& row : data.rows) v_max = std::max(v_max, row.velocity);
    plot.x_max = nice_ticks(0.0, v_max).upper;
    const double v_from = 0.02 * *plot.x_max;
    double y_top = 0.0;
    for (const risk::ImpactShape shape : risk::all_impact_shapes) {
        std::vector<double> masses;
        std::size_t above = 0;
        for (const risk::ComparedImpact& c : compared) {
            if (data.rows[c.row].shape != shape) continue;
            masses.push_back(data.rows[c.row].mass);
            above += c.ratio > 1.0 ? 1 : 0;
        }
        if (masses.empty()) continue;
        const double reference = risk::median(masses);
        const ShapeStyle style = style_of(shape);
        const risk::ImpactCoefficients c = risk::envelope_coefficients(formula, shape);
        plot.series.push_back(curve(formula_style, style.color, v_from, *plot.x_max, [&](double v) {
            return risk::jra_impact_force(reference, v, c);
        }));
        Series points;
        points.label = std::string(risk::to_string(shape)) +
                       " (n = " + std::to_string(masses.size()) + fmt(", at %.3g kg", reference) +
                       "): " + std::to_string(above) + " above";
        points.color = style.color;
        points.line = false;
        points.marker = style.marker;
        points.marker_size = 3.0;
        points.opacity = 0.7;
        for (const risk::ComparedImpact& ci : compared) {
            const risk::ImpactRow& row = data.rows[ci.row];
            if (row.shape != shape) continue;
            points.x.push_back(row.velocity);
            points.y.push_back(scaled_load(row, reference) / n_per_kn);
        }
        y_top = std::max(y_top, *std::max_element(points.y.begin(), points.y.end()));
        plot.series.push_back(std::move(points));
    }
    plot.series.push_back(key(formula_style));
    // As in fit_figure: the data with room above; the curves are clipped.
    plot.y_max = nice_ticks(0.0, 1.3 * y_top).upper;
    return plot;
}

}  // namespace rockfall::report
