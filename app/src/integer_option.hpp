#pragma once
/// Whole-number options read by one rule: decimal digits only, in a stated range.

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace rockfall::app {

/// A CLI11 transform (for Option::transform: check() would drop the rewrite) that accepts a
/// decimal integer in [min, max] (`what` names it in the error, e.g. "a seed") and rewrites it
/// in plain decimal, so that CLI11's own conversion (strtoull with base 0, which reads "010" as
/// octal, "0x10" as hex, wraps "-1" to 2^64 - 1 and clamps an overflow) reads the number that
/// was checked.
CLI::Validator integer_in(std::uint64_t min, std::uint64_t max, const std::string& what);

/// Adds the seed rule (a decimal integer in [0, 2^64 - 1]) to the `--seed` option of every
/// subcommand of `app`, at any depth, so that no command can take a seed by another rule.
void check_seed_options(CLI::App& app);

}  // namespace rockfall::app
