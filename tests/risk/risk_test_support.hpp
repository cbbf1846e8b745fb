#pragma once
// Helpers shared by the risk tests: distributions written as in a sweep file, and the problems
// risk::find_problems reports for a spec.

#include "risk/distribution.hpp"
#include "risk/sampling.hpp"

#include <limits>
#include <string>
#include <vector>

namespace rockfall::test {

inline constexpr double infinity = std::numeric_limits<double>::infinity();

// Uniform in [min, max].
inline risk::Distribution uniform(double min, double max) {
    risk::Distribution d;
    d.family = risk::Distribution::Family::uniform;
    d.min = min;
    d.max = max;
    return d;
}

// Normal of mean and sd, truncated to [min, max] (untruncated by default).
inline risk::Distribution normal(double mean, double sd, double min = -infinity,
                                 double max = infinity) {
    risk::Distribution d;
    d.family = risk::Distribution::Family::normal;
    d.mean = mean;
    d.sd = sd;
    d.min = min;
    d.max = max;
    return d;
}

// The keys of every problem of `spec` against `base`, in the order they are reported.
inline std::vector<std::string> problem_keys(const risk::SweepSpec& spec,
                                             const engine::Scenario& base) {
    std::vector<std::string> keys;
    for (const risk::SweepProblem& problem : risk::find_problems(spec, base)) {
        keys.push_back(problem.key);
    }
    return keys;
}

// Every problem of `spec` against `base` as "key = message" lines.
inline std::string problem_text(const risk::SweepSpec& spec, const engine::Scenario& base) {
    std::string text;
    for (const risk::SweepProblem& problem : risk::find_problems(spec, base)) {
        text += problem.key + " = " + problem.message + "\n";
    }
    return text;
}

}  // namespace rockfall::test
