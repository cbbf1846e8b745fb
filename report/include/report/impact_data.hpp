#pragma once
/// The wall impacts `rockfall fit` and `rockfall envelope` report on: measured rows from a CSV
/// file, or every wall hit of a sweep from its results database (the loading is the
/// program's: app/impact_source.hpp).

#include "db/wall_impacts.hpp"
#include "risk/impact_fit.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace rockfall::report {

/// Which velocity of a simulated hit the formula is given.
enum class HitVelocity {
    /// The component normal to the wall, which the formula's normal (Hertz) impact sees.
    normal,
    /// |v| at first touch, as a camera measures the velocity just before the hit.
    total,
};

/// "normal" or "total"; throws std::invalid_argument otherwise.
HitVelocity parse_hit_velocity(const std::string& name);

/// "normal" or "total".
const char* to_string(HitVelocity velocity);

/// Impact rows with, for a database, the hit each row comes from.
struct ImpactData {
    /// Rows in SI units.
    std::vector<risk::ImpactRow> rows;
    /// Whether they come from a results database.
    bool from_database = false;
    /// For a database: the hit of each row (same order); empty for a CSV file.
    std::vector<db::WallImpact> hits;
    /// For a database: hits left out because their kind has no shape class of the formula
    /// (not sphere, massive or planar) or they lack a positive velocity, force or mass.
    std::size_t skipped = 0;
    /// Rows left out as slower than the minimum velocity asked for (drop_slow).
    std::size_t slow = 0;
    /// Rows left out as a rock's second or later hit (keep_first_hits).
    std::size_t later = 0;
};

/// The impacts a report is about: the file named on the command line, its rows, the
/// velocity they carry, and the slowest kept (m/s).
struct ImpactSelection {
    std::string input;
    const ImpactData* data = nullptr;
    HitVelocity velocity = HitVelocity::normal;
    double min_velocity = 0.0;
    /// Only each rock's first hit (keep_first_hits).
    bool first_hits = false;
};

/// The rows of a results database's wall hits (db::read_wall_impacts), the formula given the
/// `velocity` of each: hits of a kind with no shape class of the formula, or without a
/// positive velocity, force or mass, are counted in `skipped`.
ImpactData database_rows(std::vector<db::WallImpact> hits, HitVelocity velocity);

/// Leaves out the rows (and their hits) slower than `min_velocity` (m/s, finite, >= 0),
/// counting them in `slow`: a rock pressed against the wall at a few cm/s loads it with its
/// weight and push, not by an impact the formula describes. Throws std::invalid_argument for
/// a bad minimum.
void drop_slow(ImpactData& data, double min_velocity);

/// Leaves out every hit but each rock's first (counted in `later`): seed 000 measured the
/// velocity just before a rock's arrival at the wall, not its rebounds, re-contacts or the
/// slow contacts of a rock rocking or sliding along the wall. Throws std::invalid_argument for
/// rows from a CSV file, which carry no hit number.
void keep_first_hits(ImpactData& data);

/// One line on where the rows come from and what was left out, for the reports:
/// "FILE (results database: N wall hits, velocity normal; left out: ...)".
std::string describe(const ImpactData& data, const std::string& input, HitVelocity velocity);

}  // namespace rockfall::report
