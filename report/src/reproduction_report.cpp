// The seed reproductions as text tables and JSON.

#include "report/reproduction_report.hpp"

#include "report/text_format.hpp"

#include <cmath>
#include <cstdio>
#include <vector>

namespace rockfall::report {
namespace {

namespace seed001 = risk::seed001;

// Values within the target, of those with values, of all.
struct Counts {
    int within = 0;
    int with_values = 0;
    int total = 0;
};

Counts count(const std::vector<seed001::Comparison>& table) {
    Counts c;
    for (const seed001::Comparison& row : table) {
        ++c.total;
        if (!row.simulated.empty()) ++c.with_values;
        if (row.within()) ++c.within;
    }
    return c;
}

void print_table(std::ostream& out, const std::string& title,
                 const std::vector<seed001::Comparison>& table) {
    if (table.empty()) return;
    const seed001::Comparison& first = table.front();
    const std::string unit = first.unit;
    out << title << " (" << unit << "; mean over the values, +- sample standard deviation, "
        << "95 % t interval of the mean; n = values / runs x rocks that should give one; target "
        << fmt("%.0f %%", first.tolerance * 100.0) << "):\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-44s %9s %9s %8s %19s %7s %8s  %s\n", "case", "published",
                  "simulated", "+- sd", "95 % interval", "n", "error", "verdict");
    out << line;
    for (const seed001::Comparison& row : table) {
        if (row.simulated.empty()) {
            std::snprintf(line, sizeof line, "  %-44s %9.2f %9s %8s %19s %3d/%-3d %8s  %s\n",
                          row.label.c_str(), row.published, "-", "-", "-", 0, row.expected, "-",
                          "no value");
            out << line;
            continue;
        }
        const risk::SampleSummary s = row.summary();
        const std::string interval = "[" + fmt("%.2f", s.mean_interval.lower) + ", " +
                                     fmt("%.2f", s.mean_interval.upper) + "]";
        std::snprintf(line, sizeof line, "  %-44s %9.2f %9.2f %8.2f %19s %3lld/%-3d %+7.0f%%  %s\n",
                      row.label.c_str(), row.published, s.mean, s.standard_deviation,
                      interval.c_str(), static_cast<long long>(s.count), row.expected,
                      row.relative_error() * 100.0, row.within() ? "within" : "miss");
        out << line;
    }
    const Counts c = count(table);
    out << "  " << c.within << " of " << c.total << " within "
        << fmt("%.0f %%", first.tolerance * 100.0) << '\n';
}

std::string values_text(const std::vector<double>& values) {
    std::string text;
    for (std::size_t i = 0; i < values.size(); ++i)
        text += (i ? ", " : "") + (std::isfinite(values[i]) ? fmt("%.3g", values[i]) : "-");
    return text;
}

nlohmann::json number(double value) {
    return std::isfinite(value) ? nlohmann::json(value) : nlohmann::json();
}

nlohmann::json table_json(const std::vector<seed001::Comparison>& table) {
    nlohmann::json rows = nlohmann::json::array();
    for (const seed001::Comparison& row : table) {
        const risk::SampleSummary s = row.summary();
        const bool any = !row.simulated.empty();
        rows.push_back(
            {{"label", row.label},
             {"unit", row.unit},
             {"published", row.published},
             {"mean", any ? number(s.mean) : nlohmann::json()},
             {"standard_deviation", any ? number(s.standard_deviation) : nlohmann::json()},
             {"interval_95", any ? nlohmann::json{s.mean_interval.lower, s.mean_interval.upper}
                                 : nlohmann::json()},
             {"count", s.count},
             {"expected", row.expected},
             {"relative_error", number(row.relative_error())},
             {"tolerance", row.tolerance},
             {"within", row.within()}});
    }
    return rows;
}

nlohmann::json counts_json(const std::vector<seed001::Comparison>& table) {
    const Counts c = count(table);
    return {{"within", c.within}, {"with_values", c.with_values}, {"total", c.total}};
}

}  // namespace

void print_seed001(std::ostream& out, const seed001::Reproduction& reproduction,
                   const ReproductionInfo& info) {
    out << "seed 001 reproduction: " << info.source << ", " << info.seeds << " seed"
        << (info.seeds == 1 ? "" : "s") << " from " << info.first_seed
        << ", pressure cells sampled every " << fmt("%.3g ms", info.sample_interval * 1e3) << "\n";
    print_table(out,
                "Table 2, numerical rows: the marked rocks' peak wall force as the pressure cells "
                "read it, every rock of the cluster of the row's shape, 4 marked rocks a run",
                reproduction.numerical_forces);
    print_table(out,
                "Table 2, physical rows: the painted rocks' peak wall force as the pressure cells "
                "read it, blocky cluster",
                reproduction.physical_forces);
    print_table(out, "The painted rocks' speeds at 1.4 m of travel (measured in the paper)",
                reproduction.speeds);
    if (!reproduction.trends.empty()) {
        out << "The paper's trends on the numerical rows' means:\n";
        for (const seed001::Trend& t : reproduction.trends) {
            out << "  " << (t.holds ? "holds " : "fails ")
                << "(Table 2: " << (t.published_holds ? "holds" : "fails") << ")  " << t.label
                << ": " << values_text(t.values) << '\n';
        }
    }
    out << info.runs << " runs, " << fmt("%.0f s", info.cpu_time) << " CPU, "
        << fmt("%.0f s", info.wall_time) << " on " << info.threads << " thread"
        << (info.threads == 1 ? "" : "s") << '\n';
}

nlohmann::json seed001_json(const seed001::Reproduction& reproduction,
                            const ReproductionInfo& info) {
    nlohmann::json trends = nlohmann::json::array();
    for (const seed001::Trend& t : reproduction.trends) {
        nlohmann::json values = nlohmann::json::array();
        for (const double v : t.values) values.push_back(number(v));
        trends.push_back({{"label", t.label},
                          {"values", values},
                          {"holds", t.holds},
                          {"published_holds", t.published_holds}});
    }
    return {{"source", info.source},
            {"first_seed", info.first_seed},
            {"seeds", info.seeds},
            {"sample_interval_s", info.sample_interval},
            {"runs", info.runs},
            {"cpu_time_s", info.cpu_time},
            {"wall_time_s", info.wall_time},
            {"threads", info.threads},
            {"numerical_forces", table_json(reproduction.numerical_forces)},
            {"physical_forces", table_json(reproduction.physical_forces)},
            {"speeds", table_json(reproduction.speeds)},
            {"trends", trends},
            {"within",
             {{"numerical_forces", counts_json(reproduction.numerical_forces)},
              {"physical_forces", counts_json(reproduction.physical_forces)},
              {"speeds", counts_json(reproduction.speeds)}}}};
}

}  // namespace rockfall::report
