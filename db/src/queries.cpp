// Reading values, groups and the worst samples; the statistics on them are in query_tables.cpp.

#include "db/queries.hpp"

#include "sqlite.hpp"

#include "risk/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace rockfall::db {

using risk::number_text;

namespace {

struct QuantityInfo {
    Quantity quantity;
    std::string_view name;
    // Column in outcomes (per sample) or wall_impacts (per hit, maximum per sample).
    std::string_view column;
    std::string_view unit;
    bool wall;
};

constexpr QuantityInfo quantity_table[] = {
    {Quantity::reach, "reach", "reach_m", "m", false},
    {Quantity::max_speed, "max_speed", "max_speed_m_s", "m/s", false},
    {Quantity::bounce_height, "bounce_height", "max_bounce_height_m", "m", false},
    {Quantity::impact_energy, "impact_energy", "energy_before_J", "J", true},
    {Quantity::impact_speed, "impact_speed", "impact_speed_m_s", "m/s", true},
    {Quantity::impulse, "impulse", "normal_impulse_N_s", "N s", true},
    {Quantity::peak_force, "peak_force", "peak_force_N", "N", true},
};

const QuantityInfo& info(Quantity quantity) {
    for (const QuantityInfo& entry : quantity_table) {
        if (entry.quantity == quantity) return entry;
    }
    throw std::logic_error("quantity missing from quantity_table");
}

constexpr std::pair<GroupBy, std::string_view> group_names[] = {{GroupBy::none, "none"},
                                                                {GroupBy::kind, "kind"},
                                                                {GroupBy::size, "size"},
                                                                {GroupBy::zone, "zone"},
                                                                {GroupBy::shape, "shape"}};

double round_to_significant(double value, int digits) {
    const double scale = std::pow(10.0, digits - 1 - std::floor(std::log10(std::abs(value))));
    return std::round(value * scale) / scale;
}

// The default size classes: edges at the quartiles of the stored sizes, rounded so that the
// labels read well.
std::vector<double> quartile_edges(const ResultsDb& db) {
    sql::Statement select(db.handle(), db.path(), "SELECT size_m FROM samples WHERE size_m > 0");
    std::vector<double> sizes;
    while (select.step()) sizes.push_back(select.real(0));
    std::vector<double> edges;
    if (sizes.empty()) return edges;
    for (const double p : {0.25, 0.5, 0.75}) {
        // The order statistic nearest the quartile (type 1, Hyndman and Fan 1996) is plenty
        // for a class edge rounded to two digits, and nth_element finds it without sorting.
        const auto rank =
            static_cast<std::ptrdiff_t>(std::ceil(p * static_cast<double>(sizes.size())) - 1.0);
        std::nth_element(sizes.begin(), sizes.begin() + rank, sizes.end());
        const double edge = round_to_significant(sizes[static_cast<std::size_t>(rank)], 2);
        if (edge > 0.0 && (edges.empty() || edge > edges.back())) edges.push_back(edge);
    }
    return edges;
}

// Maps each row's group column to a group index and names the groups.
class Classifier {
  public:
    Classifier(const ResultsDb& db, const Grouping& grouping) : by_(grouping.by) {
        if (by_ == GroupBy::size) {
            edges_ = grouping.size_edges.empty() ? quartile_edges(db) : grouping.size_edges;
            validate_size_edges(edges_);
        }
        if (by_ == GroupBy::zone) {
            sql::Statement zones(db.handle(), db.path(), "SELECT zone, name FROM zones");
            while (zones.step()) zone_names_[zones.integer(0)] = zones.text(1);
        }
    }

    // SQL expression of the group column, given samples as `s`.
    std::string_view column() const {
        switch (by_) {
            case GroupBy::kind:
                return "s.kind";
            case GroupBy::shape:
                return "s.shape";
            case GroupBy::size:
                return "s.size_m";
            case GroupBy::zone:
                return "s.zone";
            case GroupBy::none:
                break;
        }
        return "NULL";
    }

    // The JOIN that brings samples `s` to a table aliased `alias`.
    std::string join(std::string_view alias) const {
        if (by_ == GroupBy::none) return "";
        return " JOIN samples s ON s.sample = " + std::string(alias) + ".sample";
    }

    // Group index of the row's column `column`; keys_.size() for a row that fits no group.
    std::size_t index(const sql::Statement& row, int column) {
        switch (by_) {
            case GroupBy::none:
                return key(0);
            case GroupBy::kind:
            case GroupBy::shape:
                return kind_index(row.text_view(column));
            case GroupBy::zone:
                return key(row.integer(column));
            case GroupBy::size:
                break;
        }
        const double size = row.real(column);
        if (std::isnan(size)) return keys_.size();
        const auto edge = std::upper_bound(edges_.begin(), edges_.end(), size);
        return key(edge - edges_.begin());
    }

    // Group index -> its position in the output (kinds alphabetical, zones and size classes
    // ascending).
    std::vector<std::size_t> output_order() const {
        std::vector<std::size_t> order(keys_.size());
        for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
        std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return by_ == GroupBy::kind || by_ == GroupBy::shape ? kinds_[a] < kinds_[b]
                                                                 : keys_[a] < keys_[b];
        });
        return order;
    }

    GroupId id(std::size_t index) const {
        GroupId id;
        switch (by_) {
            case GroupBy::none:
                id.label = "all";
                break;
            case GroupBy::kind:
            case GroupBy::shape:
                id.label = kinds_[index];
                break;
            case GroupBy::zone: {
                const auto name = zone_names_.find(keys_[index]);
                id.label = name != zone_names_.end() ? name->second
                                                     : "zone " + std::to_string(keys_[index]);
                break;
            }
            case GroupBy::size: {
                const auto k = static_cast<std::size_t>(keys_[index]);
                id.size_min = k == 0 ? 0.0 : edges_[k - 1];
                id.size_max =
                    k < edges_.size() ? edges_[k] : std::numeric_limits<double>::infinity();
                id.label = "[" + number_text(id.size_min) + ", " +
                           (k < edges_.size() ? number_text(id.size_max) : "inf") + ")";
                break;
            }
        }
        return id;
    }

    std::size_t size() const { return keys_.size(); }

  private:
    std::size_t key(std::int64_t value) {
        // Few groups (kinds, zones, size classes): a linear search, trying the last hit first,
        // is faster than a map for a million rows.
        if (last_ < keys_.size() && keys_[last_] == value) return last_;
        for (last_ = 0; last_ < keys_.size(); ++last_) {
            if (keys_[last_] == value) return last_;
        }
        keys_.push_back(value);
        return last_;
    }

    std::size_t kind_index(std::string_view kind) {
        if (last_ < kinds_.size() && kinds_[last_] == kind) return last_;
        for (last_ = 0; last_ < kinds_.size(); ++last_) {
            if (kinds_[last_] == kind) return last_;
        }
        kinds_.emplace_back(kind);
        keys_.push_back(static_cast<std::int64_t>(last_));
        return last_;
    }

    GroupBy by_;
    std::vector<double> edges_;
    std::map<std::int64_t, std::string> zone_names_;
    std::vector<std::int64_t> keys_;
    std::vector<std::string> kinds_;
    std::size_t last_ = 0;
};

template <class Row>
void grow(std::vector<Row>& rows, std::size_t index) {
    if (index >= rows.size()) rows.resize(index + 1);
}

}  // namespace

std::string_view to_string(Quantity quantity) { return info(quantity).name; }

Quantity parse_quantity(std::string_view name) {
    std::string names;
    for (const QuantityInfo& entry : quantity_table) {
        if (entry.name == name) return entry.quantity;
        names += (names.empty() ? "" : ", ") + std::string(entry.name);
    }
    throw std::invalid_argument("unknown quantity '" + std::string(name) + "': choose " + names);
}

std::string_view column_of(Quantity quantity) { return info(quantity).column; }

std::string_view unit_of(Quantity quantity) { return info(quantity).unit; }

bool needs_wall_hit(Quantity quantity) { return info(quantity).wall; }

std::string_view to_string(GroupBy by) {
    for (const auto& [value, name] : group_names) {
        if (value == by) return name;
    }
    throw std::logic_error("grouping missing from group_names");
}

GroupBy parse_group_by(std::string_view name) {
    for (const auto& [value, known] : group_names) {
        if (known == name) return value;
    }
    throw std::invalid_argument("unknown grouping '" + std::string(name) +
                                "': choose kind, shape, size or zone");
}

void validate_size_edges(const std::vector<double>& edges) {
    for (std::size_t i = 0; i < edges.size(); ++i) {
        const std::string where = "size class edge " + number_text(edges[i]) + " m";
        if (!std::isfinite(edges[i]) || edges[i] <= 0.0) {
            throw std::invalid_argument(where + ": must be finite and > 0");
        }
        if (i > 0 && edges[i] <= edges[i - 1]) {
            throw std::invalid_argument(where + ": edges must be strictly ascending (follows " +
                                        number_text(edges[i - 1]) + " m)");
        }
    }
}

std::vector<Group> read_groups(const ResultsDb& db, Quantity quantity, const Grouping& grouping) {
    Classifier classifier(db, grouping);
    const std::string group_column(classifier.column());
    const std::string column(column_of(quantity));
    std::vector<Group> groups;
    // Each row: the group column, the samples the row stands for (column 1), and optionally
    // a value (column 2).
    const auto read = [&](const std::string& sql, bool has_value) {
        sql::Statement select(db.handle(), db.path(), sql);
        while (select.step()) {
            const std::size_t index = classifier.index(select, 0);
            if (index == classifier.size()) continue;
            grow(groups, index);
            groups[index].samples += select.integer(1);
            if (has_value && !select.is_null(2)) groups[index].values.push_back(select.real(2));
        }
    };
    const std::string from_outcomes = " FROM outcomes o" + classifier.join("o");
    if (needs_wall_hit(quantity)) {
        // Samples per group from the samples table alone (every sample is written with its
        // outcome): one aggregate row without grouping, else one row per sample.
        read("SELECT " + group_column + (grouping.by == GroupBy::none ? ", COUNT(*)" : ", 1") +
                 " FROM samples s",
             false);
        read("SELECT " + group_column + ", 0, MAX(w." + column + ") FROM wall_impacts w" +
                 classifier.join("w") + " GROUP BY w.sample",
             true);
    } else {
        read("SELECT " + group_column + ", 1, o." + column + from_outcomes, true);
    }
    std::vector<Group> ordered;
    for (const std::size_t index : classifier.output_order()) {
        if (index >= groups.size() || groups[index].samples == 0) continue;
        Group& group = groups[index];
        group.id = classifier.id(index);
        std::sort(group.values.begin(), group.values.end());
        ordered.push_back(std::move(group));
    }
    return ordered;
}

std::vector<WorstSample> worst_samples(const ResultsDb& db, Quantity by, std::int64_t count) {
    if (count < 1) {
        throw std::invalid_argument("number of samples = " + std::to_string(count) +
                                    ": must be >= 1");
    }
    const std::string column(column_of(by));
    const std::string rank_sql =
        needs_wall_hit(by)
            ? "SELECT sample, MAX(" + column + ") AS v FROM wall_impacts GROUP BY sample " +
                  "HAVING v IS NOT NULL ORDER BY v DESC, sample LIMIT ?"
            : "SELECT sample FROM outcomes WHERE " + column + " IS NOT NULL ORDER BY " + column +
                  " DESC, sample LIMIT ?";
    sql::Statement ranked(db.handle(), db.path(), rank_sql);
    ranked.bind_int(1, count);
    sql::Statement sample(db.handle(), db.path(),
                          "SELECT seed, kind, size_m, mass_kg, zone_name, reach_m, max_speed_m_s, "
                          "max_bounce_height_m, wall_hits FROM sample_results WHERE sample = ?");
    sql::Statement impacts(db.handle(), db.path(),
                           "SELECT MAX(peak_force_N), MAX(energy_before_J), "
                           "MAX(normal_impulse_N_s), MAX(impact_speed_m_s) FROM wall_impacts "
                           "WHERE sample = ?");
    std::vector<WorstSample> worst;
    while (ranked.step()) {
        WorstSample& w = worst.emplace_back();
        w.sample = ranked.integer(0);
        sample.reset();
        sample.bind_int(1, w.sample);
        if (!sample.step()) {
            throw DatabaseError(db.path().string() + ": sample " + std::to_string(w.sample) +
                                    " has wall impacts but no inputs or outcome: the file is "
                                    "damaged",
                                DatabaseError::Kind::bad_file);
        }
        w.seed = sql::from_stored(sample.integer(0));
        w.kind = sample.text(1);
        w.size = sample.real(2);
        w.mass = sample.real(3);
        w.zone = sample.text(4);
        w.reach = sample.real(5);
        w.max_speed = sample.real(6);
        w.bounce_height = sample.real(7);
        w.wall_hits = sample.integer(8);
        impacts.reset();
        impacts.bind_int(1, w.sample);
        impacts.step();
        w.peak_force = impacts.real(0);
        w.impact_energy = impacts.real(1);
        w.impulse = impacts.real(2);
        w.impact_speed = impacts.real(3);
    }
    return worst;
}

std::vector<StoredOutcome> stored_outcomes(const ResultsDb& db) {
    sql::Statement select(db.handle(), db.path(),
                          "SELECT sample, reach_m, wall_hits FROM outcomes ORDER BY sample");
    std::vector<StoredOutcome> outcomes;
    while (select.step()) {
        outcomes.push_back({select.integer(0), select.real(1), select.integer(2)});
    }
    return outcomes;
}

}  // namespace rockfall::db
