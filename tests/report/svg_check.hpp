#pragma once
// Parse-level checks of an SVG document for the figure tests: well-formed XML as far as the
// writers use it (one root element, every start tag closed in order, quoted attributes, no
// raw '<' or '&' in text), and counts of substrings.

#include <cstddef>
#include <string>
#include <vector>

namespace rockfall::test {

/// An empty string when `svg` is well-formed, otherwise what is wrong and where (offset).
inline std::string xml_problem(const std::string& svg) {
    std::vector<std::string> open;
    std::size_t roots = 0;
    std::size_t i = 0;
    auto at = [&](std::size_t k) { return " at offset " + std::to_string(k); };
    while (i < svg.size()) {
        if (svg[i] == '&') {
            const std::size_t end = svg.find(';', i);
            if (end == std::string::npos || end - i > 8) return "bare '&'" + at(i);
            i = end + 1;
            continue;
        }
        if (svg[i] != '<') {
            ++i;
            continue;
        }
        const std::size_t end = svg.find('>', i);
        if (end == std::string::npos) return "unterminated tag" + at(i);
        std::string tag = svg.substr(i + 1, end - i - 1);
        i = end + 1;
        if (tag.empty()) return "empty tag" + at(end);
        if (tag[0] == '?' || tag[0] == '!') continue;
        if (tag[0] == '/') {
            const std::string name = tag.substr(1);
            if (open.empty() || open.back() != name) {
                return "</" + name + "> closes " +
                       (open.empty() ? "nothing" : "<" + open.back() + ">") + at(end);
            }
            open.pop_back();
            continue;
        }
        const bool self_closing = tag.back() == '/';
        if (self_closing) tag.pop_back();
        const std::size_t name_end = tag.find_first_of(" \n\t");
        const std::string name = tag.substr(0, name_end);
        // Attributes: name="value" pairs, quotes balanced.
        std::size_t quotes = 0;
        for (const char c : tag) quotes += c == '"' ? 1 : 0;
        if (quotes % 2 != 0) return "unbalanced quotes in <" + name + ">" + at(end);
        if (tag.find('<') != std::string::npos) return "'<' inside <" + name + ">" + at(end);
        if (open.empty()) ++roots;
        if (!self_closing) open.push_back(name);
    }
    if (!open.empty()) return "<" + open.back() + "> is never closed";
    if (roots != 1) return std::to_string(roots) + " root elements";
    return {};
}

/// How often `what` occurs in `text`.
inline std::size_t occurrences(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (auto k = text.find(what); k != std::string::npos; k = text.find(what, k + 1)) ++n;
    return n;
}

}  // namespace rockfall::test
