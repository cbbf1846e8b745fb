#pragma once
// Numbers in messages, shared by the distribution and sampling sources.

#include <charconv>
#include <string>

namespace rockfall::risk::detail {

// Shortest text that reads back to the same double ("0.1", "2600", "-inf").
inline std::string number_text(double value) {
    char buffer[32];
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), value);
    return std::string(buffer, result.ptr);
}

}  // namespace rockfall::risk::detail
