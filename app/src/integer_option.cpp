#include "integer_option.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>
#include <system_error>

namespace rockfall::app {

CLI::Validator integer_in(std::uint64_t min, std::uint64_t max, const std::string& what) {
    const std::string range = "[" + std::to_string(min) + ", " + std::to_string(max) + "]";
    return CLI::Validator(
        [min, max, what, range](std::string& value) -> std::string {
            const std::string expected =
                ": " + what + " must be a whole number in " + range + ", written in decimal";
            const bool digits = !value.empty() && value.size() <= 20 &&
                                std::all_of(value.begin(), value.end(),
                                            [](unsigned char c) { return std::isdigit(c) != 0; });
            std::uint64_t number = 0;
            if (!digits) return value + expected;
            const auto [end, error] =
                std::from_chars(value.data(), value.data() + value.size(), number);
            if (error != std::errc() || end != value.data() + value.size() || number < min ||
                number > max)
                return value + " is out of range" + expected;
            value = std::to_string(number);
            return {};
        },
        "in " + range);
}

void check_seed_options(CLI::App& app) {
    for (CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
        if (CLI::Option* seed = command->get_option_no_throw("--seed"))
            seed->transform(integer_in(0, std::numeric_limits<std::uint64_t>::max(), "a seed"));
        check_seed_options(*command);
    }
}

}  // namespace rockfall::app
