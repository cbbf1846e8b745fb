#pragma once
// Helpers shared by the scenario-file tests: which problem a ScenarioError reports, and where.

#include "scenario/scenario_file.hpp"

#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <string>

namespace rockfall::test {

// 1-based line of the first line of `file` containing `needle`.
inline int line_of(const std::filesystem::path& file, const std::string& needle) {
    std::ifstream in(file);
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
        if (line.find(needle) != std::string::npos) return number;
    }
    FAIL("'" << needle << "' not in " << file);
    return 0;
}

// The ScenarioError that `load(file)` throws; fails the test when it throws none.
template <typename Loader>
scenario::ScenarioError load_error(Loader load, const std::filesystem::path& file) {
    try {
        load(file);
    } catch (const scenario::ScenarioError& error) {
        return error;
    }
    FAIL("loading " << file << " did not throw");
    throw;
}

// The ScenarioError that `parse(text)` throws; fails the test when it throws none.
template <typename Parser>
scenario::ScenarioError parse_error(Parser parse, const std::string& text) {
    try {
        parse(text);
    } catch (const scenario::ScenarioError& error) {
        return error;
    }
    FAIL("parsing did not throw:\n" << text);
    throw;
}

// The problem reported for `key`; fails the test when there is none.
inline scenario::ScenarioProblem problem_for(const scenario::ScenarioError& error,
                                             const std::string& key) {
    for (const scenario::ScenarioProblem& problem : error.problems()) {
        if (problem.key == key) return problem;
    }
    FAIL("no problem for key '" << key << "' in:\n" << error.what());
    throw;
}

}  // namespace rockfall::test
