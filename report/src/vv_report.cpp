// The verification and validation report (see vv_report.hpp): HTML, JSON and the text
// summary. The page itself (head, style sheet, sections, figures) is html_document.hpp's.

#include "report/vv_report.hpp"

#include "html_document.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

namespace rockfall::report {
namespace {

// Verdict colours: readable in print and for red-green colour blindness (with the word).
constexpr const char* pass_style = "color: #1a6e2e; font-weight: bold";
constexpr const char* miss_style = "color: #b00020; font-weight: bold";

std::string tolerance_text(const VvCheck& c) {
    return "± " +
           (c.relative ? fmt("%.3g %%", 100.0 * c.tolerance) : html::value(c.tolerance, c.unit));
}

std::string error_text(const VvCheck& c) {
    const double e = c.error();
    if (std::isnan(e)) return "-";
    return c.relative ? fmt("%+.3g %%", 100.0 * e)
                      : fmt("%+.3g", e) + (c.unit.empty() ? "" : " " + c.unit);
}

std::string verdict_text(const VvCheck& c) { return c.pass() ? "PASS" : "MISS"; }

struct Counts {
    int passed = 0;
    int missed = 0;
};

Counts count(const std::vector<VvTable>& tables) {
    Counts n;
    for (const VvTable& t : tables) {
        for (const VvCheck& c : t.checks) ++(c.pass() ? n.passed : n.missed);
    }
    return n;
}

std::string counts_text(const Counts& n) {
    return std::to_string(n.passed + n.missed) + " checks: " + std::to_string(n.passed) +
           " PASS, " + std::to_string(n.missed) + " MISS";
}

std::string number_cell(const std::string& text) {
    return "<td class=\"n\">" + html::escaped(text) + "</td>";
}

// A table of checks: one row per check with the id the tests look up.
std::string checks_table(const VvTable& table) {
    bool notes = false;
    for (const VvCheck& c : table.checks) notes = notes || !c.note.empty();
    std::ostringstream out;
    // Full width: the tables of a section line up (the shared style sheet sizes tables to fit).
    out << "<table class=\"checks\" style=\"width: 100%\">\n";
    if (!table.caption.empty())
        out << "<caption>" << html::escaped(table.caption) << "</caption>\n";
    out << "<thead><tr><th>check (reference's source)</th><th>reference</th><th>simulated</th>"
        << "<th>tolerance</th><th>error</th><th>verdict</th>" << (notes ? "<th>note</th>" : "")
        << "</tr></thead>\n<tbody>\n";
    for (const VvCheck& c : table.checks) {
        out << "<tr id=\"check-" << c.id << "\"><td>" << html::escaped(c.label);
        if (!c.source.empty()) {
            out << "<br/><span style=\"color: #555; font-size: 90%\">" << html::escaped(c.source)
                << "</span>";
        }
        out << "</td>" << number_cell(html::value(c.reference, c.unit))
            << number_cell(html::value(c.simulated, c.unit)) << number_cell(tolerance_text(c))
            << number_cell(error_text(c)) << "<td class=\"verdict\" style=\""
            << (c.pass() ? pass_style : miss_style) << "\">" << verdict_text(c) << "</td>";
        if (notes) out << "<td>" << html::escaped(c.note) << "</td>";
        out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n";
    return out.str();
}

html::Section summary_section(const VvReport& r) {
    std::vector<std::pair<std::string, std::string>> items = {
        {"tool", "rockfall " + r.version},
        {"build", r.build},
        {"run", r.quick ? "quick (--quick: seed 001's physical rows over one seed, no heap test)"
                        : "full (every check and seed reproduction at its documented size)"}};
    for (const auto& setting : r.settings) items.push_back(setting);
    items.emplace_back("runtimes",
                       "not in this file, so that the same build and options give the same "
                       "bytes; `rockfall validate` prints them on standard output");
    html::Table table{"Verdicts by section", {"section", "checks", "PASS", "MISS"}, {}};
    Counts total;
    for (const VvSection& s : r.sections) {
        const Counts n = count(s.tables);
        total.passed += n.passed;
        total.missed += n.missed;
        table.rows.push_back({s.title, std::to_string(n.passed + n.missed),
                              std::to_string(n.passed), std::to_string(n.missed)});
    }
    table.rows.push_back({"all", std::to_string(total.passed + total.missed),
                          std::to_string(total.passed), std::to_string(total.missed)});
    std::string body = html::items(items);
    body += html::paragraph(
        "Each check sets the value this binary computes now, in-process, beside a reference: an "
        "analytic solution or a published measurement. PASS: the difference is within the "
        "tolerance stated with the check; MISS: it is not, or the run gave no value. Misses are "
        "results and are reported as they are; no parameter was tuned to these references "
        "unless the section says so.");
    body += html::table(table);
    return {"summary", "Summary: " + counts_text(total), body};
}

}  // namespace

double VvCheck::error() const {
    if (std::isnan(simulated)) return std::numeric_limits<double>::quiet_NaN();
    return relative ? (simulated - reference) / std::abs(reference) : simulated - reference;
}

bool VvCheck::pass() const {
    const double e = error();
    return std::isfinite(e) && std::abs(e) <= tolerance;
}

VvCheck make_check(std::string id, std::string label, std::string unit, double reference,
                   std::string source, double simulated, double tolerance, bool relative) {
    VvCheck c;
    c.id = std::move(id);
    c.label = std::move(label);
    c.unit = std::move(unit);
    c.reference = reference;
    c.source = std::move(source);
    c.simulated = simulated;
    c.tolerance = tolerance;
    c.relative = relative;
    return c;
}

Series point_series(std::string label, std::string color, Marker marker) {
    Series s;
    s.label = std::move(label);
    s.color = std::move(color);
    s.line = marker == Marker::none;
    s.marker = marker;
    return s;
}

Series line_series(std::string label, std::string color, std::vector<double> x,
                   std::vector<double> y) {
    Series s = point_series(std::move(label), std::move(color), Marker::none);
    s.x = std::move(x);
    s.y = std::move(y);
    return s;
}

Plot vv_plot(std::string title, std::string x_label, std::string y_label,
             std::vector<Series> series, bool from_zero) {
    Plot plot;
    plot.title = std::move(title);
    plot.x_label = std::move(x_label);
    plot.y_label = std::move(y_label);
    plot.series = std::move(series);
    plot.height = 480.0;
    if (from_zero) plot.x_min = plot.y_min = 0.0;
    return plot;
}

VvSection vv_section(std::string id, std::string title, std::vector<std::string> notes) {
    VvSection s;
    s.id = std::move(id);
    s.title = std::move(title);
    s.notes = std::move(notes);
    return s;
}

std::vector<const VvCheck*> all_checks(const VvReport& report) {
    std::vector<const VvCheck*> checks;
    for (const VvSection& s : report.sections) {
        for (const VvTable& t : s.tables) {
            for (const VvCheck& c : t.checks) checks.push_back(&c);
        }
    }
    return checks;
}

void write_vv_html(std::ostream& out, const VvReport& r) {
    const std::string tool = "rockfall " + r.version + " (" + r.build + ")";
    html::write_head(out, "Verification and validation report: rockfall " + r.version, tool);
    out << "<p class=\"subtitle\">" << html::escaped(tool) << ", "
        << (r.quick ? "quick run" : "full run") << "</p>\n";
    std::vector<html::Section> sections = {summary_section(r)};
    int figures = 0;
    for (const VvSection& s : r.sections) {
        std::string body;
        for (const std::string& note : s.notes) body += html::paragraph(note);
        for (const VvTable& t : s.tables) body += checks_table(t);
        for (const VvTextTable& t : s.text_tables)
            body += html::table({t.caption, t.header, t.rows});
        for (const VvFigure& f : s.figures) body += html::figure(f.plot, ++figures, f.caption);
        sections.push_back({s.id, s.title + " (" + counts_text(count(s.tables)) + ")", body});
    }
    html::write_contents(out, sections, r.left_out);
    for (const html::Section& s : sections) html::write_section(out, s);
    html::write_tail(out, "Written by " + tool +
                              "; every simulated value was computed by this binary for this "
                              "report.");
}

nlohmann::json vv_json(const VvReport& r) {
    const auto number = [](double v) {
        return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json();
    };
    nlohmann::json checks = nlohmann::json::array();
    int passed = 0;
    for (const VvSection& s : r.sections) {
        for (const VvTable& t : s.tables) {
            for (const VvCheck& c : t.checks) {
                passed += c.pass() ? 1 : 0;
                checks.push_back({{"id", c.id},
                                  {"section", s.id},
                                  {"label", c.label},
                                  {"unit", c.unit},
                                  {"reference", number(c.reference)},
                                  {"source", c.source},
                                  {"simulated", number(c.simulated)},
                                  {"tolerance", c.tolerance},
                                  {"relative", c.relative},
                                  {"error", number(c.error())},
                                  {"verdict", verdict_text(c)}});
            }
        }
    }
    return {{"version", r.version}, {"build", r.build},
            {"quick", r.quick},     {"checks", checks},
            {"passed", passed},     {"missed", static_cast<int>(checks.size()) - passed}};
}

void print_vv_summary(std::ostream& out, const VvReport& r) {
    out << "rockfall " << r.version << " (" << r.build << "), "
        << (r.quick ? "quick run" : "full run") << '\n';
    Counts total;
    char line[512];
    for (const VvSection& s : r.sections) {
        const Counts n = count(s.tables);
        total.passed += n.passed;
        total.missed += n.missed;
        out << '\n' << s.title << " (" << counts_text(n) << "):\n";
        if (!s.text.empty()) {
            out << s.text;
            continue;
        }
        for (const VvTable& t : s.tables) {
            for (const VvCheck& c : t.checks) {
                std::snprintf(line, sizeof line, "  %-58s %13s %13s %11s %9s  %s\n",
                              c.label.c_str(), html::value(c.reference, c.unit).c_str(),
                              html::value(c.simulated, c.unit).c_str(), tolerance_text(c).c_str(),
                              error_text(c).c_str(), verdict_text(c).c_str());
                out << line;
            }
        }
    }
    out << '\n' << counts_text(total) << '\n';
}

}  // namespace rockfall::report
