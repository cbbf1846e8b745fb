// The [sweep] table written out in full, for results databases: read back by read_sweep.

#include "sweep_reader.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace rockfall::scenario::detail {
namespace {

std::string distribution_text(const risk::Distribution& d) {
    using Family = risk::Distribution::Family;
    switch (d.family) {
        case Family::fixed:
            return format_number(d.value);
        case Family::uniform:
            return "{ uniform = [" + format_number(d.min) + ", " + format_number(d.max) + "] }";
        case Family::triangular:
            return "{ triangular = [" + format_number(d.min) + ", " + format_number(d.mode) + ", " +
                   format_number(d.max) + "] }";
        case Family::normal:
        case Family::lognormal: {
            std::string text = "{ " + risk::to_string(d.family) +
                               " = { mean = " + format_number(d.mean) +
                               ", sd = " + format_number(d.sd) + " }";
            // Infinite bounds are the defaults: no truncation on that side.
            if (std::isfinite(d.min)) text += ", min = " + format_number(d.min);
            if (std::isfinite(d.max)) text += ", max = " + format_number(d.max);
            return text + " }";
        }
    }
    return {};
}

std::string kind_text(const risk::SweepSpec& spec) {
    std::vector<std::string> names;
    std::vector<double> weights = spec.kind_weights;
    for (const shapes::RockKind kind : spec.kinds) {
        names.push_back(toml_string(shapes::to_string(kind)));
    }
    for (const auto& entry : spec.entries) names.push_back(toml_string(entry->name));
    weights.insert(weights.end(), spec.entry_weights.begin(), spec.entry_weights.end());
    if (spec.generated_weight > 0.0) {
        names.push_back(toml_string("generated"));
        weights.push_back(spec.generated_weight);
    }
    if (names.size() == 1) return names.front();
    std::string choice;
    std::string weight_list;
    for (std::size_t i = 0; i < names.size(); ++i) choice += (i == 0 ? "" : ", ") + names[i];
    for (std::size_t i = 0; i < weights.size(); ++i) {
        weight_list += (i == 0 ? "" : ", ") + format_number(weights[i]);
    }
    return "{ choice = [" + choice + "], weights = [" + weight_list + "] }";
}

// A named shape with its hull, so that the text stands alone (no catalogue to look for), as
// format_scenario writes mesh rocks. The vertices are written in full precision: read back,
// they give the same hull, though Qhull may list its vertices in another order (a sweep runs
// on the spec read back from this text for that reason).
std::string shape_text(const shapes::CustomShape& shape) {
    std::string points;
    for (const shapes::Vec3& v : shape.hull.vertices) {
        points += "\n    " + format_vector(engine::Vec3(v)) + ",";
    }
    return "\n[[sweep.rock.shapes]]\nname = " + toml_string(shape.name) + "\nvertices = [" +
           points + "\n]\n";
}

template <class S, std::size_t N>
void write_distributions(std::ostream& out, const S& object,
                         const std::array<DistributionKey<S>, N>& keys) {
    for (const auto& [key, member, unit] : keys) {
        out << key << " = " << distribution_text(object.*member) << "\n";
    }
}

}  // namespace

std::string format_cluster_sweep(const risk::SweepSpec& spec) {
    if (spec.seed > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max())) {
        throw std::invalid_argument("sweep.seed = " + std::to_string(spec.seed) +
                                    ": a scenario file holds seeds in [0, 2^63 - 1] only");
    }
    std::ostringstream out;
    out << "[sweep]\n";
    for (const auto& [name, value] : sweep_method_names) {
        if (value == spec.method) out << "method = " << toml_string(name) << "\n";
    }
    out << "samples = " << spec.samples << "\n";
    out << "seed = " << spec.seed << "\n";
    return out.str();
}

std::string format_sweep(const risk::SweepSpec& spec) {
    std::ostringstream out;
    out << format_cluster_sweep(spec);
    out << "random_orientation = " << (spec.random_orientation ? "true" : "false") << "\n";
    out << "lateral_margin = " << format_number(spec.lateral_margin) << "\n";
    out << "\n[sweep.rock]\n";
    out << "kind = " << kind_text(spec) << "\n";
    if (spec.sphericity) {
        out << "sphericity = " << distribution_text(*spec.sphericity) << "\n";
    }
    write_distributions(out, spec, sweep_rock_keys);
    for (const auto& entry : spec.entries) out << shape_text(*entry);
    out << "\n[sweep.rock.material]\n";
    write_distributions(out, spec, sweep_material_keys);
    out << "\n[sweep.release]\n";
    write_distributions(out, spec, sweep_release_keys);
    for (const risk::ReleaseZone& zone : spec.zones) {
        out << "\n[[sweep.release.zones]]\n";
        out << "name = " << toml_string(zone.name) << "\n";
        out << "weight = " << format_number(zone.weight) << "\n";
        write_distributions(out, zone, sweep_zone_keys);
    }
    return out.str();
}

}  // namespace rockfall::scenario::detail
