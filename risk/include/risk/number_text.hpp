#pragma once
/// Numbers in messages and labels, shared by risk, db and the program's reports: the shortest
/// text that reads back as the same double ("0.1", "2600", "1e-05", "-inf"), never
/// std::to_string's fixed six decimals.

#include <charconv>
#include <string>

namespace rockfall::risk {

/// Shortest decimal text of `value` that reads back to the same double (any value, NaN too).
inline std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace rockfall::risk
