#pragma once
// Numbers in messages and labels: the shortest text that reads back as the same double
// ("0.2", "100", "1e-05"), never std::to_string's fixed six decimals.

#include <charconv>
#include <string>

namespace rockfall::db {

inline std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    return std::string(buffer, result.ptr);
}

}  // namespace rockfall::db
