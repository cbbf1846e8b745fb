#pragma once
// Input checks shared by the risk sources: one message format naming field, value, unit and
// allowed range, so every formula reports bad input the same way.

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::risk::detail {

/// Throws std::invalid_argument with `message` unless `condition` holds.
inline void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument(message);
}

/// Throws std::invalid_argument "FIELD = VALUE UNIT: must be finite and > 0" unless value is.
inline void require_positive(const char* field, double value, const char* unit) {
    if (std::isfinite(value) && value > 0.0) return;
    std::ostringstream message;
    message << field << " = " << value << ' ' << unit << ": must be finite and > 0";
    throw std::invalid_argument(message.str());
}

/// Throws std::invalid_argument "FIELD = VALUE UNIT: must be finite and >= LOWER" unless it is.
inline void require_at_least(const char* field, double value, const char* unit, double lower) {
    if (std::isfinite(value) && value >= lower) return;
    std::ostringstream message;
    message << field << " = " << value << ' ' << unit << ": must be finite and >= " << lower;
    throw std::invalid_argument(message.str());
}

/// Throws std::invalid_argument "FIELD = VALUE UNIT: must be in [LOWER, UPPER]" (or the open
/// bounds) unless value lies in the range.
inline void require_range(const char* field, double value, const char* unit, double lower,
                          double upper, bool open_lower, bool open_upper) {
    const bool above = open_lower ? value > lower : value >= lower;
    const bool below = open_upper ? value < upper : value <= upper;
    if (std::isfinite(value) && above && below) return;
    std::ostringstream message;
    message << field << " = " << value << ' ' << unit << ": must be in " << (open_lower ? '(' : '[')
            << lower << ", " << upper << (open_upper ? ')' : ']');
    throw std::invalid_argument(message.str());
}

}  // namespace rockfall::risk::detail
