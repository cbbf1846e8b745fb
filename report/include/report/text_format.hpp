#pragma once
/// Number formatting for the program's readable reports.

#include <cstdio>
#include <string>

namespace rockfall::report {

/// `value` formatted with a printf format for one double, e.g. fmt("%.2f m/s", v).
inline std::string fmt(const char* format, double value) {
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, format, value);
    return buffer;
}

}  // namespace rockfall::report
