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
    // Column in outcomes (per rock) or wall_impacts (per hit).
    std::string_view column;
    std::string_view unit;
    bool wall;
    // How a sample's value is made of its rocks' outcomes or its hits (all of its rocks).
    std::string_view per_sample;
};

constexpr QuantityInfo quantity_table[] = {
    {Quantity::reach, "reach", "reach_m", "m", false, "MAX"},
    {Quantity::max_speed, "max_speed", "max_speed_m_s", "m/s", false, "MAX"},
    {Quantity::bounce_height, "bounce_height", "max_bounce_height_m", "m", false, "MAX"},
    {Quantity::impact_energy, "impact_energy", "energy_before_J", "J", true, "MAX"},
    {Quantity::impact_speed, "impact_speed", "impact_speed_m_s", "m/s", true, "MAX"},
    {Quantity::impulse, "impulse", "normal_impulse_N_s", "N s", true, "SUM"},
    {Quantity::peak_force, "peak_force", "peak_force_N", "N", true, "MAX"},
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
std::vector<double> quartile_edges(const ResultsDb& db, Per per) {
    sql::Statement select(db.handle(), db.path(),
                          std::string("SELECT size_m FROM ") +
                              (per == Per::rock ? "rocks" : "samples") + " WHERE size_m > 0");
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
    Classifier(const ResultsDb& db, const Grouping& grouping)
        : by_(grouping.by), per_(grouping.per) {
        if (by_ == GroupBy::size) {
            edges_ = grouping.size_edges.empty() ? quartile_edges(db, per_) : grouping.size_edges;
            validate_size_edges(edges_);
        }
        if (by_ == GroupBy::zone) {
            sql::Statement zones(db.handle(), db.path(), "SELECT zone, name FROM zones");
            while (zones.step()) zone_names_[zones.integer(0)] = zones.text(1);
        }
    }

    // SQL expression of the group column, given samples as `s` and, per rock, rocks as `r`.
    std::string column() const {
        const std::string table = rock_columns() ? "r." : "s.";
        switch (by_) {
            case GroupBy::kind:
                return table + "kind";
            case GroupBy::shape:
                return table + "shape";
            case GroupBy::size:
                return table + "size_m";
            case GroupBy::zone:
                return "s.zone";
            case GroupBy::none:
                break;
        }
        return "NULL";
    }

    // The JOIN that brings the group column's table to a table aliased `alias` (with columns
    // sample and, per rock, rock).
    std::string join(std::string_view alias) const {
        const std::string a(alias);
        if (by_ == GroupBy::none) return "";
        if (rock_columns()) {
            return " JOIN rocks r ON r.sample = " + a + ".sample AND r.rock = " + a + ".rock";
        }
        return " JOIN samples s ON s.sample = " + a + ".sample";
    }

    // Whether the group column is a rock's (kind, shape and size per rock).
    bool rock_columns() const {
        return per_ == Per::rock && by_ != GroupBy::none && by_ != GroupBy::zone;
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
    Per per_;
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

std::string_view to_string(Per per) { return per == Per::rock ? "rock" : "sample"; }

Per parse_per(std::string_view name) {
    if (name == "rock") return Per::rock;
    if (name == "sample") return Per::sample;
    throw std::invalid_argument("unknown observation '" + std::string(name) +
                                "': choose rock or sample");
}

std::vector<Group> read_groups(const ResultsDb& db, Quantity quantity, const Grouping& grouping) {
    Classifier classifier(db, grouping);
    const std::string group_column = classifier.column();
    const std::string column(column_of(quantity));
    const bool per_rock = grouping.per == Per::rock;
    // Per rock every value is one rock's (a wall quantity: the largest over its hits); per
    // sample it is made of all of the sample's rocks (info().per_sample).
    const std::string aggregate = per_rock ? "MAX" : std::string(info(quantity).per_sample);
    const std::string by_observation = per_rock ? ".sample, w.rock" : ".sample";
    std::vector<Group> groups;
    // Each row: the group column, the observations the row stands for (column 1), and
    // optionally a value (column 2).
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
    const std::string count = grouping.by == GroupBy::none ? ", COUNT(*)" : ", 1";
    if (needs_wall_hit(quantity)) {
        // Observations per group from the rocks or samples table alone (every sample is
        // written with its rocks' outcomes): one aggregate row without grouping, else one row
        // per observation.
        if (!per_rock) {
            read("SELECT " + group_column + count + " FROM samples s", false);
        } else if (grouping.by == GroupBy::zone) {
            read("SELECT s.zone, 1 FROM rocks o JOIN samples s ON s.sample = o.sample", false);
        } else {
            read("SELECT " + group_column + count + " FROM rocks r", false);
        }
        read("SELECT " + group_column + ", 0, " + aggregate + "(w." + column +
                 ") FROM wall_impacts w" + classifier.join("w") + " GROUP BY w" + by_observation,
             true);
    } else if (per_rock) {
        read("SELECT " + group_column + ", 1, o." + column + " FROM outcomes o" +
                 classifier.join("o"),
             true);
    } else {
        read("SELECT " + group_column + ", 1, " + aggregate + "(o." + column + ") FROM outcomes o" +
                 classifier.join("o") + " GROUP BY o.sample",
             true);
    }
    std::vector<Group> ordered;
    for (const std::size_t index : classifier.output_order()) {
        if (index >= groups.size() || groups[index].samples == 0) continue;
        Group& group = groups[index];
        group.id = classifier.id(index);
        std::sort(group.values.begin(), group.values.end());
        ordered.push_back(std::move(group));
    }
    if (ordered.empty() && grouping.by == GroupBy::size && !per_rock) {
        sql::Statement sized(db.handle(), db.path(),
                             "SELECT COUNT(*) FROM samples WHERE size_m IS NULL");
        if (sized.step() && sized.integer(0) > 0) {
            throw std::invalid_argument(
                "--by size --per sample: the samples have no size (a cluster release's rocks "
                "each have their own); group the rocks by size with --per rock");
        }
    }
    return ordered;
}

std::vector<WorstSample> worst_samples(const ResultsDb& db, Quantity by, std::int64_t count,
                                       Per per) {
    if (count < 1) {
        throw std::invalid_argument("number of samples = " + std::to_string(count) +
                                    ": must be >= 1");
    }
    const bool per_rock = per == Per::rock;
    const std::string column(column_of(by));
    // Per rock each rock's value (a wall quantity: its largest over its hits); per sample the
    // sample's (info().per_sample over all its rocks), with rock -1.
    const std::string value =
        (per_rock ? std::string("MAX") : std::string(info(by).per_sample)) + "(" + column + ")";
    const std::string observation = per_rock ? "sample, rock" : "sample";
    const std::string rank_sql =
        "SELECT sample, " + std::string(per_rock ? "rock" : "-1") + ", " + value + " AS v FROM " +
        (needs_wall_hit(by) ? "wall_impacts" : "outcomes") + " GROUP BY " + observation +
        " HAVING v IS NOT NULL ORDER BY v DESC, " + observation + " LIMIT ?";
    sql::Statement ranked(db.handle(), db.path(), rank_sql);
    ranked.bind_int(1, count);
    sql::Statement sample(
        db.handle(), db.path(),
        per_rock ? "SELECT seed, kind, size_m, mass_kg, zone_name, reach_m, max_speed_m_s, "
                   "max_bounce_height_m, wall_hits FROM sample_results "
                   "WHERE sample = ? AND rock = ?"
                 : "SELECT s.seed, s.kind, s.size_m, s.mass_kg, z.name, MAX(o.reach_m), "
                   "MAX(o.max_speed_m_s), MAX(o.max_bounce_height_m), SUM(o.wall_hits) "
                   "FROM samples s JOIN outcomes o ON o.sample = s.sample "
                   "LEFT JOIN zones z ON z.zone = s.zone WHERE s.sample = ? GROUP BY s.sample");
    sql::Statement impacts(
        db.handle(), db.path(),
        std::string("SELECT MAX(peak_force_N), MAX(energy_before_J), ") +
            (per_rock ? "MAX" : "SUM") +
            "(normal_impulse_N_s), MAX(impact_speed_m_s) FROM wall_impacts WHERE sample = ?" +
            (per_rock ? " AND rock = ?" : ""));
    std::vector<WorstSample> worst;
    while (ranked.step()) {
        WorstSample& w = worst.emplace_back();
        w.sample = ranked.integer(0);
        w.rock = ranked.integer(1);
        sample.reset();
        sample.bind_int(1, w.sample);
        if (per_rock) sample.bind_int(2, w.rock);
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
        if (per_rock) impacts.bind_int(2, w.rock);
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
                          "SELECT sample, MAX(reach_m), SUM(wall_hits) FROM outcomes "
                          "GROUP BY sample ORDER BY sample");
    std::vector<StoredOutcome> outcomes;
    while (select.step()) {
        outcomes.push_back({select.integer(0), select.real(1), select.integer(2)});
    }
    return outcomes;
}

}  // namespace rockfall::db
