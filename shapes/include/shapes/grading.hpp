#pragma once
/// Grain-size distribution (grading) of a rock cluster, as in geotechnics: the percent passing
/// by mass against size, its characteristic sizes d10, d30, d50, d60 and the coefficients of
/// uniformity Cu = d60 / d10 and curvature Cc = d30^2 / (d10 d60). A size d here is a rock's
/// volume-equivalent diameter (6 V / pi)^(1/3), m; one density for the whole cluster, so mass
/// fractions are volume fractions.
///
/// Model: the mass fraction passing size d is a log-normal distribution in d truncated to
/// [d_min, d_max], ln d normal with mean mu and deviation sigma before truncation; mu and sigma
/// are fitted so that the truncated curve passes d50 at 50 % and has d60 / d10 = Cu exactly.
/// Rocks are drawn one by one from the matching number distribution: weighting a log-normal
/// number density by d^3 shifts its mean by 3 sigma^2, so ln d of a rock is normal with mean
/// mu - 3 sigma^2 and deviation sigma, truncated to the same [d_min, d_max].

#include <random>
#include <vector>

namespace rockfall::shapes {

/// A cluster's grading as a user gives it; exactly one of count and total_volume is > 0.
/// Defaults: cluster C2 of seed 001 (99 rocks, d50 53 mm, Cu 1.52, 30 to 100 mm).
struct Grading {
    /// Number of rocks, in [1, max_cluster_rocks]; 0 when total_volume is given.
    int count = 99;
    /// Solid volume of the rocks together, m3, > 0; 0 when count is given. Rocks are drawn
    /// until their volume reaches it (see cluster_sizes).
    double total_volume = 0.0;
    /// Size passed by 50 % of the mass, m, in (d_min, d_max).
    double d50 = 0.053;
    /// Coefficient of uniformity d60 / d10, > 1 and at most what [d_min, d_max] allows about
    /// d50 (the limit of a wide log-normal; reported by the error).
    double cu = 1.52;
    /// Smallest and largest rock size, m, with 1e-3 <= d_min < d_max <= 100.
    double d_min = 0.030;
    double d_max = 0.100;
};

/// Most rocks a cluster may have.
inline constexpr int max_cluster_rocks = 100'000;

/// Seed 001's cluster C1: 53 rocks, d50 51 mm, Cu 1.52, 30 to 95 mm (the paper's 0.006 m3 is
/// not used: see docs/clusters.md).
Grading seed001_c1();
/// Seed 001's cluster C2: 99 rocks, d50 53 mm, Cu 1.52, 30 to 100 mm (0.010 m3 not used).
Grading seed001_c2();

/// The fitted log-normal of a grading.
struct GradingModel {
    /// Mean and standard deviation of ln(d / 1 m) of the mass distribution before truncation.
    double mu = 0.0;
    double sigma = 0.0;
    /// Truncation, m.
    double d_min = 0.0;
    double d_max = 0.0;
};

/// Checks a grading and fits its model. Throws std::invalid_argument naming the field, its
/// value, unit and allowed range: count or total_volume (neither or both given, or out of
/// range; a total_volume needing more than max_cluster_rocks rocks), d_min, d_max, d50 outside
/// (d_min, d_max), cu <= 1 or beyond the largest the truncation allows.
GradingModel grading_model(const Grading& grading);

/// The model's fraction of the mass passing size d (m), in [0, 1]: 0 below d_min, 1 above d_max.
double mass_passing(const GradingModel& model, double d);

/// The sizes of one cluster's rocks, m, in the order drawn, each in [d_min, d_max]: one
/// uniform01 draw from `generator` per rock, mapped through the inverse of the truncated
/// number distribution (bisection to 1e-14 in ln d), so the same generator state gives the
/// same sizes. With count, that many rocks. With total_volume V, rocks are drawn until their
/// volume sum S reaches V; the rock that crosses it is kept when S - V < V - (S - its volume),
/// i.e. when keeping it leaves the total nearer to V (at least one rock). Throws as
/// grading_model.
std::vector<double> cluster_sizes(const Grading& grading, std::mt19937_64& generator);

/// The grading of a set of rocks, by mass (volume) passing.
struct GradingStats {
    /// Characteristic sizes, m.
    double d10 = 0.0;
    double d30 = 0.0;
    double d50 = 0.0;
    double d60 = 0.0;
    /// Uniformity d60 / d10 and curvature d30^2 / (d10 d60).
    double cu = 1.0;
    double cc = 1.0;
    /// Number of rocks and their solid volume pi / 6 sum d^3, m3.
    int count = 0;
    double total_volume = 0.0;
};

/// The grading of rocks of the given sizes (m, > 0, any order, at least one). Sorted
/// ascending, rock i is plotted at the mass fraction passing midway through it,
/// (C_{i-1} + C_i) / 2 with C_i the cumulative fraction up to and including it (Hazen's
/// plotting position, weighted by mass); d_p is interpolated linearly in ln d between the two
/// rocks around p, and is the smallest (largest) size below the first (beyond the last)
/// plotted point. Throws std::invalid_argument for no sizes or a size that is not finite > 0.
GradingStats grading_of(const std::vector<double>& sizes);

}  // namespace rockfall::shapes
