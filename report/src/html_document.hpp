#pragma once
// Pieces of the HTML reports (html_report.cpp and the section writers): the document around
// the sections with its inline style sheet, sections, tables, figures and the number formats
// every section shares. Private to the report library. The markup is also well-formed XML
// (every element closed, attributes quoted, text escaped), so that tests can parse it.

#include "report/svg_plot.hpp"

#include <cstdint>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::report::html {

/// Text escaped for HTML and XML (&, <, >, ").
std::string escaped(const std::string& text);

/// The document's start: doctype, head with title, generator and the style sheet (screen and
/// print: A4, each section on a new page), the opening of the body and the report's title.
void write_head(std::ostream& out, const std::string& title, const std::string& generator);

/// The document's end: a footer naming the generator, the closing tags.
void write_tail(std::ostream& out, const std::string& footer);

/// One section of the report, written whole once its body is known.
struct Section {
    /// Anchor (id attribute, [a-z-]) and heading.
    std::string id;
    std::string title;
    /// Body: HTML made by the functions below.
    std::string body;
};

/// The list of sections with links, and the sections left out with the reason for each.
void write_contents(std::ostream& out, const std::vector<Section>& sections,
                    const std::vector<std::pair<std::string, std::string>>& left_out);

/// The section: <section id> with its heading and body.
void write_section(std::ostream& out, const Section& section);

/// A paragraph of plain text (escaped).
std::string paragraph(const std::string& text);

/// A heading inside a section, plain text.
std::string subheading(const std::string& text);

/// A table of plain-text cells (escaped); header cells name their units.
struct Table {
    /// Caption above the table (may be empty).
    std::string caption;
    std::vector<std::string> header;
    std::vector<std::vector<std::string>> rows;
};

/// The table as HTML: cells that start like a number right-aligned (not in the first column),
/// text left-aligned.
std::string table(const Table& t);

/// Label-value rows (provenance), values plain text.
std::string items(const std::vector<std::pair<std::string, std::string>>& rows);

/// Preformatted text (a scenario file, commands), escaped, with an optional CSS class
/// ("commands": kept on one page in print).
std::string preformatted(const std::string& text, const std::string& css_class = "");

/// An inline SVG figure (render_svg of the plot, its ids prefixed "figN-") numbered `number`
/// with its caption.
std::string figure(Plot plot, int number, const std::string& caption);

/// A value with 4 significant digits and its unit ("12.35 m"), "-" for NaN.
std::string value(double v, const std::string& unit);

/// A confidence as a percentage ("95").
std::string confidence_text(double confidence);

}  // namespace rockfall::report::html
