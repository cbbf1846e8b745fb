#pragma once
// What every fuzz target shares: the refusals a reader may give for bad input, and a scratch
// folder for readers that take a path.

#include "scenario/scenario_file.hpp"

#include "shapes/polyhedron.hpp"

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rockfall::fuzz {

/// The bytes as text (readers take any bytes, also NUL and invalid UTF-8).
inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// Runs `read`; a clear refusal of bad input (ScenarioError, GeometryError, and
/// std::invalid_argument, which CsvError and the value checks derive from) is the expected
/// outcome. Any other exception is what the program would print as a failure (exit 1) for a
/// bad file, so the target aborts, and libFuzzer keeps the input as a finding.
template <typename Read>
void expect_clear_refusal(Read&& read) {
    try {
        read();
    } catch (const scenario::ScenarioError&) {
    } catch (const shapes::GeometryError&) {
    } catch (const std::invalid_argument&) {
    } catch (const std::exception& e) {
        std::fprintf(stderr, "fuzz: an unexpected exception for bad input: %s\n", e.what());
        std::abort();
    }
}

/// Aborts with `what` when `ok` is false: an invariant a reader's result must keep.
inline void require(bool ok, const char* what) {
    if (ok) return;
    std::fprintf(stderr, "fuzz: %s\n", what);
    std::abort();
}

/// A folder of this process's own for readers that take a path (in memory when /dev/shm
/// exists), removed at exit.
const std::filesystem::path& scratch_folder();

/// Writes the bytes to `name` in scratch_folder() and returns its path.
std::filesystem::path write_scratch(const std::string& name, std::string_view bytes);

}  // namespace rockfall::fuzz
