// Seed 001's published numbers (Table 2 and the text's speeds at 1.4 m) and the comparison of
// simulated values with them.

#include "risk/seed001.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace rockfall::risk::seed001 {
namespace {

std::size_t angle_index(int angle_deg) {
    for (std::size_t i = 0; i < angles_deg.size(); ++i) {
        if (angles_deg[i] == angle_deg) return i;
    }
    throw std::invalid_argument("seed 001: slope angle " + std::to_string(angle_deg) +
                                " deg: the paper has 30, 45 and 60 deg");
}

std::size_t cluster_index(Cluster cluster) { return cluster == Cluster::c1 ? 0 : 1; }

// Table 2, "Numerical" rows: [shape][cluster * 3 + angle], N.
constexpr double numerical_force[4][6] = {
    {60.4, 280.3, 698.7, 66.5, 294.3, 712.8},     // tetrahedral, 0.67
    {105.2, 319.8, 723.3, 118.4, 340.8, 741.0},   // cubical, 0.80
    {145.4, 365.7, 759.2, 166.6, 380.7, 773.2},   // octahedral, 0.85
    {189.9, 425.8, 808.9, 207.9, 446.8, 825.7}};  // spherical, 1.0

// Table 2, "Physical" rows: [rock][cluster * 3 + angle], N.
constexpr double physical_force[4][6] = {{60.9, 281.6, 704.3, 63.3, 303.4, 706.5},  // yellow, 0.72
                                         {101.5, 315.6, 730.8, 114.9, 334.9, 744.9},  // green, 0.80
                                         {135.8, 356.2, 781.5, 143.0, 373.7, 795.6},  // blue, 0.85
                                         {200.3, 405.4, 821.9, 220.2, 425.3, 838.3}};  // red, 0.89

// "Effect of cluster size": measured speeds at 1.4 m of travel, [rock][cluster * 3 + angle],
// m/s (the text lists red, blue, green, yellow per cluster and angle).
constexpr double measured_speed[4][6] = {{2.6, 3.5, 4.9, 2.8, 3.5, 5.0},   // yellow
                                         {3.2, 4.0, 5.6, 3.4, 4.1, 5.7},   // green
                                         {3.5, 4.2, 5.8, 3.7, 4.5, 5.9},   // blue
                                         {3.9, 4.5, 6.4, 4.0, 4.7, 6.6}};  // red

std::size_t column(Cluster cluster, int angle_deg) {
    return cluster_index(cluster) * angles_deg.size() + angle_index(angle_deg);
}

// Whether the values rise strictly in order (all finite).
bool rising(const std::vector<double>& values) {
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!std::isfinite(values[i])) return false;
        if (i > 0 && !(values[i] > values[i - 1])) return false;
    }
    return true;
}

std::string angle_label(int angle_deg) { return std::to_string(angle_deg) + " deg"; }

std::string cluster_label(Cluster cluster) { return cluster == Cluster::c1 ? "C1" : "C2"; }

}  // namespace

std::string to_string(Cluster cluster) { return cluster == Cluster::c1 ? "c1" : "c2"; }

std::string to_string(Shape shape) {
    switch (shape) {
        case Shape::tetrahedron:
            return "tetrahedron";
        case Shape::cube:
            return "cube";
        case Shape::octahedron:
            return "octahedron";
        case Shape::sphere:
            return "sphere";
    }
    return "?";
}

std::string to_string(Marked rock) {
    switch (rock) {
        case Marked::yellow:
            return "yellow";
        case Marked::green:
            return "green";
        case Marked::blue:
            return "blue";
        case Marked::red:
            return "red";
    }
    return "?";
}

double sphericity(Shape shape) {
    constexpr double values[] = {0.67, 0.80, 0.85, 1.0};
    return values[static_cast<int>(shape)];
}

double sphericity(Marked rock) {
    constexpr double values[] = {0.72, 0.80, 0.85, 0.89};
    return values[static_cast<int>(rock)];
}

double published_force(Shape shape, Cluster cluster, int angle_deg) {
    return numerical_force[static_cast<int>(shape)][column(cluster, angle_deg)];
}

double published_force(Marked rock, Cluster cluster, int angle_deg) {
    return physical_force[static_cast<int>(rock)][column(cluster, angle_deg)];
}

double published_speed_at_1_4m(Marked rock, Cluster cluster, int angle_deg) {
    return measured_speed[static_cast<int>(rock)][column(cluster, angle_deg)];
}

SampleSummary Comparison::summary() const {
    if (simulated.empty()) return {};
    return sample_summary(simulated);
}

double Comparison::relative_error() const {
    if (simulated.empty()) return std::numeric_limits<double>::quiet_NaN();
    return (summary().mean - published) / published;
}

bool Comparison::within() const {
    const double error = relative_error();
    return std::isfinite(error) && std::abs(error) <= tolerance;
}

ForceGrid published_grid() {
    ForceGrid grid{};
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        for (std::size_t a = 0; a < angles_deg.size(); ++a) {
            for (std::size_t s = 0; s < shapes.size(); ++s)
                grid[c][a][s] = published_force(shapes[s], clusters[c], angles_deg[a]);
        }
    }
    return grid;
}

std::vector<Trend> trends(const ForceGrid& simulated) {
    const ForceGrid published = published_grid();
    std::vector<Trend> out;
    const auto add = [&out](std::string label, std::vector<double> values,
                            const std::vector<double>& reference) {
        out.push_back({std::move(label), values, rising(reference), rising(values)});
    };
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        for (std::size_t a = 0; a < angles_deg.size(); ++a) {
            add("force grows with sphericity (tetrahedron, cube, octahedron, sphere), " +
                    cluster_label(clusters[c]) + ", " + angle_label(angles_deg[a]),
                {simulated[c][a].begin(), simulated[c][a].end()},
                {published[c][a].begin(), published[c][a].end()});
        }
    }
    // The effect falls as the angle rises: listed from 60 deg down, the values rise.
    const auto effect = [](const ForceGrid& grid, std::size_t c, std::size_t a) {
        return (grid[c][a][3] - grid[c][a][0]) / grid[c][a][3];
    };
    for (std::size_t c = 0; c < clusters.size(); ++c) {
        std::vector<double> values;
        std::vector<double> reference;
        for (std::size_t a = angles_deg.size(); a-- > 0;) {
            values.push_back(effect(simulated, c, a));
            reference.push_back(effect(published, c, a));
        }
        add("sphericity effect (F_sphere - F_tetrahedron) / F_sphere shrinks as the angle grows "
            "(listed 60, 45, 30 deg), " +
                cluster_label(clusters[c]),
            values, reference);
    }
    for (std::size_t s = 0; s < shapes.size(); ++s) {
        for (std::size_t a = 0; a < angles_deg.size(); ++a) {
            add("C2 above C1, " + to_string(shapes[s]) + ", " + angle_label(angles_deg[a]),
                {simulated[0][a][s], simulated[1][a][s]}, {published[0][a][s], published[1][a][s]});
        }
    }
    return out;
}

namespace {

Comparison comparison(std::string label, std::string unit, double published, double tolerance) {
    Comparison c;
    c.label = std::move(label);
    c.unit = std::move(unit);
    c.published = published;
    c.tolerance = tolerance;
    return c;
}

// Adds a value to a comparison: one more expected, and the value when it is finite.
void add(Comparison& c, double value) {
    ++c.expected;
    if (std::isfinite(value)) c.simulated.push_back(value);
}

std::string case_label(Cluster cluster, int angle_deg) {
    return cluster_label(cluster) + ", " + angle_label(angle_deg);
}

}  // namespace

Reproduction compare(const std::vector<RunRecord>& runs) {
    Reproduction r;
    for (const Cluster cluster : clusters) {
        for (const int angle : angles_deg) {
            for (const Shape shape : shapes) {
                r.numerical_forces.push_back(comparison(
                    "peak force, " + to_string(shape) + ", " + case_label(cluster, angle), "N",
                    published_force(shape, cluster, angle), force_tolerance));
            }
            for (const Marked rock : marked_rocks) {
                const std::string which = to_string(rock) + ", " + case_label(cluster, angle);
                r.physical_forces.push_back(comparison("peak force, " + which, "N",
                                                       published_force(rock, cluster, angle),
                                                       force_tolerance));
                r.speeds.push_back(comparison("speed at 1.4 m, " + which, "m/s",
                                              published_speed_at_1_4m(rock, cluster, angle),
                                              speed_tolerance));
            }
        }
    }
    std::vector<std::uint64_t> seeds;
    for (const RunRecord& run : runs) {
        if (std::find(seeds.begin(), seeds.end(), run.seed) == seeds.end())
            seeds.push_back(run.seed);
        const std::size_t at = column(run.cluster, run.angle_deg);
        if (run.shape) {
            Comparison& c =
                r.numerical_forces[at * shapes.size() + static_cast<std::size_t>(*run.shape)];
            for (const RockRecord& rock : run.rocks) add(c, rock.sampled_peak_force);
            continue;
        }
        for (const RockRecord& rock : run.rocks) {
            for (const Marked m : marked_rocks) {
                if (rock.name != to_string(m)) continue;
                const std::size_t k = at * marked_rocks.size() + static_cast<std::size_t>(m);
                add(r.physical_forces[k], rock.sampled_peak_force);
                add(r.speeds[k], rock.speed_at_1_4m);
            }
        }
    }
    r.seeds = static_cast<int>(seeds.size());
    ForceGrid grid{};
    for (std::size_t k = 0; k < r.numerical_forces.size(); ++k) {
        const Comparison& c = r.numerical_forces[k];
        const std::size_t at = k / shapes.size();
        grid[at / angles_deg.size()][at % angles_deg.size()][k % shapes.size()] =
            c.simulated.empty() ? std::numeric_limits<double>::quiet_NaN() : c.summary().mean;
    }
    r.trends = trends(grid);
    return r;
}

}  // namespace rockfall::risk::seed001
