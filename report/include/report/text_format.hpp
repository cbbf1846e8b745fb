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

/// `value` with 6 significant digits ("%.6g"), the precision of geometry reports.
inline std::string short_number(double value) { return fmt("%.6g", value); }

/// Three components (a point, axis lengths, moments) as "x y z" with short_number.
template <class Vector>
std::string triple(const Vector& v) {
    return short_number(v[0]) + " " + short_number(v[1]) + " " + short_number(v[2]);
}

}  // namespace rockfall::report
