#pragma once
/// Every wall impact of a sweep, one row per hit with what identifies and replays its sample:
/// the input of the design-formula comparisons (`rockfall fit DB`, `rockfall envelope DB`).
/// Reads the view impact_results: every hit of every rock, each with its own rock's kind, size
/// and mass.

#include "db/results_db.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace rockfall::db {

/// One wall hit.
struct WallImpact {
    /// Sample index, rock index (0-based), hit number within the rock (1-based) and the
    /// sample's engine seed.
    std::int64_t sample = 0;
    std::int64_t rock = 0;
    std::int64_t hit = 0;
    std::uint64_t seed = 0;
    /// Shape kind name as stored ("sphere", "massive", "planar", ...).
    std::string kind;
    /// Nominal size (m) and mass (kg) of the rock.
    double size = 0.0;
    double mass = 0.0;
    /// Speed at first touch, |v before| (m/s), and its component normal to the wall (m/s).
    double impact_speed = 0.0;
    double normal_speed = 0.0;
    /// Peak normal force on the wall, N, and the kinetic energy at first touch, J.
    double peak_force = 0.0;
    double energy_before = 0.0;
};

/// All wall hits, ordered by sample, rock and hit. NULL values read as NaN. Throws DatabaseError
/// for a damaged file.
std::vector<WallImpact> read_wall_impacts(const ResultsDb& db);

}  // namespace rockfall::db
