#pragma once
/// The seed reproductions as people read them: each published value beside the simulated mean
/// with its spread and interval, the relative error, the target and the verdict; the paper's
/// trends; as text tables or JSON.

#include "risk/seed001.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace rockfall::report {

/// How a reproduction was run, for its heading.
struct ReproductionInfo {
    /// The case files' folder.
    std::string source;
    /// First seed and number of seeds.
    std::uint64_t first_seed = 1;
    int seeds = 0;
    /// The pressure cells' sample interval, s (the cases' own, or the override).
    double sample_interval = 0.0;
    /// Runs, their summed CPU time and the wall-clock time of the whole reproduction, s.
    std::size_t runs = 0;
    double cpu_time = 0.0;
    double wall_time = 0.0;
    int threads = 1;
};

/// Seed 001's Table 2 (numerical and physical rows), the speeds at 1.4 m and the trends, as
/// text tables with units; a closing count of cells within their targets.
void print_seed001(std::ostream& out, const risk::seed001::Reproduction& reproduction,
                   const ReproductionInfo& info);

/// The same as one JSON document: keys numerical_forces, physical_forces, speeds (each a list
/// of {label, unit, published, mean, standard_deviation, interval_95, count, expected,
/// relative_error, tolerance, within}), trends ({label, values, holds, published_holds}),
/// within (counts per table) and the run information.
nlohmann::json seed001_json(const risk::seed001::Reproduction& reproduction,
                            const ReproductionInfo& info);

}  // namespace rockfall::report
