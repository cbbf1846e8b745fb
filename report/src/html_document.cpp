// The HTML document and its building blocks (see html_document.hpp).

#include "html_document.hpp"

#include "report/query_table.hpp"
#include "report/text_format.hpp"
#include "svg_detail.hpp"

#include <cmath>
#include <sstream>
#include <string_view>

namespace rockfall::report::html {
namespace {

// One style sheet for screen and print. Print: A4 with margins, each section from a new page,
// no table row or figure split over two pages. No '<' or '&' in it (the document stays XML).
constexpr const char* style_sheet = R"css(
body { font-family: "DejaVu Sans", Helvetica, Arial, sans-serif; font-size: 15px;
       line-height: 1.4; color: #1a1a1a; max-width: 1000px; margin: 0 auto; padding: 0 16px; }
h1 { font-size: 26px; margin: 24px 0 4px; }
h2 { font-size: 21px; border-bottom: 2px solid #1f77b4; padding-bottom: 3px; margin-top: 36px; }
h3 { font-size: 16px; margin: 20px 0 6px; }
p.subtitle { color: #555; margin-top: 0; }
table { border-collapse: collapse; margin: 6px 0 14px; font-size: 13px; }
caption { text-align: left; font-weight: bold; padding: 4px 0; caption-side: top; }
th, td { border: 1px solid #c8c8c8; padding: 3px 7px; vertical-align: top; }
th { background: #eef3f8; text-align: left; }
td.n { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
table.items th { width: 12em; }
table.items td { white-space: normal; }
pre.commands { background: #fbfbfb; }
pre { font-family: "DejaVu Sans Mono", monospace; font-size: 11.5px; background: #f6f6f6;
      border: 1px solid #ddd; padding: 8px; white-space: pre-wrap; overflow-wrap: anywhere; }
figure { margin: 10px 0 18px; }
figure svg { width: 100%; height: auto; display: block; border: 1px solid #e3e3e3; }
figcaption { font-size: 13px; color: #333; margin-top: 4px; }
nav ul { margin: 4px 0; }
p.left-out { font-size: 13px; color: #555; }
footer { margin: 36px 0 24px; padding-top: 6px; border-top: 1px solid #ccc; font-size: 12px;
         color: #555; }
@page { size: A4; margin: 15mm 13mm 15mm 13mm; }
@media print {
    body { font-size: 10.5pt; max-width: none; padding: 0; }
    h2 { margin-top: 0; }
    section { break-before: page; }
    h2, h3, caption { break-after: avoid; }
    figure, tr, pre.commands { break-inside: avoid; }
    table { font-size: 8.5pt; }
    pre { font-size: 7.5pt; }
    a { color: inherit; text-decoration: none; }
}
)css";

}  // namespace

std::string escaped(const std::string& text) { return svg_detail::escaped(text); }

void write_head(std::ostream& out, const std::string& title, const std::string& generator) {
    out << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\"/>\n"
        << "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\"/>\n"
        << "<meta name=\"generator\" content=\"" << escaped(generator) << "\"/>\n"
        << "<title>" << escaped(title) << "</title>\n<style>" << style_sheet
        << "</style>\n</head>\n<body>\n<h1>" << escaped(title) << "</h1>\n";
}

void write_tail(std::ostream& out, const std::string& footer) {
    out << "<footer>" << escaped(footer) << "</footer>\n</body>\n</html>\n";
}

void write_contents(std::ostream& out, const std::vector<Section>& sections,
                    const std::vector<std::pair<std::string, std::string>>& left_out) {
    out << "<nav>\n<h3>Contents</h3>\n<ul>\n";
    for (const Section& s : sections) {
        out << "<li><a href=\"#" << s.id << "\">" << escaped(s.title) << "</a></li>\n";
    }
    out << "</ul>\n";
    if (!left_out.empty()) {
        out << "<p class=\"left-out\">Not in this report: ";
        for (std::size_t i = 0; i < left_out.size(); ++i) {
            out << (i == 0 ? "" : "; ") << escaped(left_out[i].first) << " ("
                << escaped(left_out[i].second) << ")";
        }
        out << ".</p>\n";
    }
    out << "</nav>\n";
}

void write_section(std::ostream& out, const Section& section) {
    out << "<section id=\"" << section.id << "\">\n<h2>" << escaped(section.title) << "</h2>\n"
        << section.body << "</section>\n";
}

std::string paragraph(const std::string& text) { return "<p>" + escaped(text) + "</p>\n"; }

std::string subheading(const std::string& text) { return "<h3>" + escaped(text) + "</h3>\n"; }

std::string table(const Table& t) {
    std::ostringstream out;
    out << "<table>\n";
    if (!t.caption.empty()) out << "<caption>" << escaped(t.caption) << "</caption>\n";
    out << "<thead><tr>";
    for (const std::string& h : t.header) out << "<th>" << escaped(h) << "</th>";
    out << "</tr></thead>\n<tbody>\n";
    for (const std::vector<std::string>& row : t.rows) {
        out << "<tr>";
        for (std::size_t c = 0; c < row.size(); ++c) {
            // Numbers right-aligned: a cell that starts like one ("12.3", "-", "4.5e+05 to").
            const bool number =
                c > 0 && !row[c].empty() &&
                std::string_view("0123456789-+.").find(row[c][0]) != std::string_view::npos;
            out << (number ? "<td class=\"n\">" : "<td>") << escaped(row[c]) << "</td>";
        }
        out << "</tr>\n";
    }
    out << "</tbody>\n</table>\n";
    return out.str();
}

std::string items(const std::vector<std::pair<std::string, std::string>>& rows) {
    std::ostringstream out;
    out << "<table class=\"items\">\n<tbody>\n";
    for (const auto& [label, text] : rows) {
        out << "<tr><th>" << escaped(label) << "</th><td>" << escaped(text) << "</td></tr>\n";
    }
    out << "</tbody>\n</table>\n";
    return out.str();
}

std::string preformatted(const std::string& text, const std::string& css_class) {
    return (css_class.empty() ? "<pre>" : "<pre class=\"" + css_class + "\">") + escaped(text) +
           "</pre>\n";
}

std::string figure(Plot plot, int number, const std::string& caption) {
    plot.id_prefix = "fig" + std::to_string(number) + "-";
    return "<figure>\n" + render_svg(plot) + "<figcaption>Figure " + std::to_string(number) + ". " +
           escaped(caption) + "</figcaption>\n</figure>\n";
}

std::string value(double v, const std::string& unit) {
    if (std::isnan(v)) return "-";
    return fmt("%.4g", v) + (unit.empty() ? "" : " " + unit);
}

std::string confidence_text(double confidence) { return percent_text(confidence); }

}  // namespace rockfall::report::html
