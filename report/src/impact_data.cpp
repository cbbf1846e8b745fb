// The impacts of a fit or envelope report (see impact_data.hpp).

#include "report/impact_data.hpp"

#include <cmath>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rockfall::report {
namespace {

bool positive(double x) { return std::isfinite(x) && x > 0.0; }

// Keeps the rows (and their hits) for which keep(i) holds, counting the others in `dropped`.
template <typename Keep>
void keep_rows(ImpactData& data, std::size_t ImpactData::*dropped, Keep keep) {
    std::vector<risk::ImpactRow> rows;
    std::vector<db::WallImpact> hits;
    for (std::size_t i = 0; i < data.rows.size(); ++i) {
        if (!keep(i)) {
            ++(data.*dropped);
            continue;
        }
        rows.push_back(data.rows[i]);
        if (data.from_database) hits.push_back(std::move(data.hits[i]));
    }
    data.rows = std::move(rows);
    data.hits = std::move(hits);
}

}  // namespace

HitVelocity parse_hit_velocity(const std::string& name) {
    if (name == "normal") return HitVelocity::normal;
    if (name == "total") return HitVelocity::total;
    throw std::invalid_argument("--velocity = \"" + name + "\": must be normal or total");
}

const char* to_string(HitVelocity velocity) {
    return velocity == HitVelocity::normal ? "normal" : "total";
}

ImpactData database_rows(std::vector<db::WallImpact> hits, HitVelocity velocity) {
    ImpactData data;
    data.from_database = true;
    for (db::WallImpact& hit : hits) {
        risk::ImpactRow row;
        row.velocity = velocity == HitVelocity::normal ? hit.normal_speed : hit.impact_speed;
        row.peak_force = hit.peak_force;
        row.mass = hit.mass;
        const std::optional<risk::ImpactShape> shape = risk::find_impact_shape(hit.kind);
        if (!shape || !positive(row.velocity) || !positive(row.peak_force) || !positive(row.mass)) {
            ++data.skipped;
            continue;
        }
        row.shape = *shape;
        data.rows.push_back(row);
        data.hits.push_back(std::move(hit));
    }
    return data;
}

void drop_slow(ImpactData& data, double min_velocity) {
    if (!(std::isfinite(min_velocity) && min_velocity >= 0.0)) {
        throw std::invalid_argument("--min-velocity = " + std::to_string(min_velocity) +
                                    " m/s: must be finite and >= 0");
    }
    keep_rows(data, &ImpactData::slow,
              [&](std::size_t i) { return data.rows[i].velocity >= min_velocity; });
}

void keep_first_hits(ImpactData& data) {
    if (!data.from_database) {
        throw std::invalid_argument(
            "--first-hits applies to a results database (its hits are numbered per rock), not "
            "to a CSV file of impacts");
    }
    keep_rows(data, &ImpactData::later, [&](std::size_t i) { return data.hits[i].hit == 1; });
}

std::string describe(const ImpactData& data, const std::string& input, HitVelocity velocity) {
    std::string left_out;
    if (data.skipped > 0) {
        left_out += std::to_string(data.skipped) +
                    " of a kind without a shape class or without a positive velocity, load or "
                    "mass";
    }
    if (data.slow > 0) {
        left_out += (left_out.empty() ? "" : ", ") + std::to_string(data.slow) +
                    " slower than --min-velocity";
    }
    if (data.later > 0) {
        left_out += (left_out.empty() ? "" : ", ") + std::to_string(data.later) +
                    " second or later hits of a rock (--first-hits)";
    }
    const std::string n = std::to_string(data.rows.size());
    return input +
           (data.from_database
                ? " (results database: " + n + " wall hits, velocity " + to_string(velocity)
                : " (" + n + " rows") +
           (left_out.empty() ? "" : "; left out: " + left_out) + ")";
}

}  // namespace rockfall::report
