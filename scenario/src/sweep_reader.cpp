// Reading the [sweep] table: key names and types only; sweep_validation.cpp checks the values.

#include "sweep_reader.hpp"

#include <limits>
#include <optional>
#include <utility>

namespace rockfall::scenario::detail {
namespace {

constexpr std::array<std::string_view, 4> family_keys = {"uniform", "normal", "lognormal",
                                                         "triangular"};

// What a distribution-valued key accepts, for type errors.
std::string distribution_forms(std::string_view unit) {
    return std::string("must be a number") + (unit.empty() ? "" : " (" + std::string(unit) + ")") +
           " or a distribution: { uniform = [min, max] }, { normal = { mean = ..., sd = ... }, "
           "min = ..., max = ... }, { lognormal = { mean = ..., sd = ... }, min = ..., max = ... } "
           "or { triangular = [min, mode, max] }";
}

// An array of exactly N numbers, or nothing.
template <std::size_t N>
std::optional<std::array<double, N>> numbers(const toml::node& node) {
    const auto* array = node.as_array();
    if (array == nullptr || array->size() != N) return std::nullopt;
    std::array<double, N> values{};
    for (std::size_t i = 0; i < N; ++i) {
        const std::optional<double> value = number_of(*array->get(i));
        if (!value) return std::nullopt;
        values[i] = *value;
    }
    return values;
}

// { mean = ..., sd = ... } of a normal or lognormal, both required.
void read_moments(TableReader& parent, std::string_view family, const toml::node& node,
                  std::string_view unit, risk::Distribution& d) {
    Context& context = parent.context();
    const std::string path = parent.path(family);
    const auto* table = node.as_table();
    if (table == nullptr) {
        context.report(node, path,
                       describe(node) + ": must be a table { mean = ..., sd = ... } (" +
                           std::string(unit.empty() ? "dimensionless" : unit) + ")");
        return;
    }
    TableReader r(*table, path, context);
    for (const std::string_view key : {std::string_view("mean"), std::string_view("sd")}) {
        if (!table->contains(key)) {
            context.report(node, path,
                           describe(node) + ": must give " + std::string(key) + " (the " +
                               (key == "mean" ? "mean" : "standard deviation") +
                               " of the value itself, before any truncation)");
        }
    }
    read(r, "mean", d.mean, unit, any_finite());
    read(r, "sd", d.sd, unit, positive());
    r.finish();
}

// A 64-bit integer key; `min` is the smallest value TOML may give.
void read_integer(TableReader& r, std::string_view key, std::int64_t& out, std::int64_t min) {
    const toml::node* node = r.get(key);
    if (node == nullptr) return;
    const auto* value = node->as_integer();
    if (value == nullptr || value->get() < min) {
        r.context().report(*node, r.path(key),
                           describe(*node) + ": must be an integer in [" + std::to_string(min) +
                               ", " + std::to_string(std::numeric_limits<std::int64_t>::max()) +
                               "]");
        return;
    }
    out = value->get();
}

void read_release(TableReader& r, risk::SweepSpec& spec) {
    for (const auto& [key, member, unit] : sweep_release_keys) {
        read_distribution(r, key, spec.*member, unit);
    }
    // Zones start at the base rock's release point (sweep_defaults' single zone).
    const risk::ReleaseZone start = spec.zones.empty() ? risk::ReleaseZone{} : spec.zones.front();
    with_table_array(r, "zones", spec.zones, [&](TableReader& z, risk::ReleaseZone& zone) {
        zone = start;
        read(z, "name", zone.name);
        read(z, "weight", zone.weight, "", positive());
        for (const auto& [key, member, unit] : sweep_zone_keys) {
            read_distribution(z, key, zone.*member, unit);
        }
    });
}

}  // namespace

void read_distribution(TableReader& parent, std::string_view key, risk::Distribution& out,
                       std::string_view unit) {
    const toml::node* node = parent.get(key);
    if (node == nullptr) return;
    Context& context = parent.context();
    const std::string path = parent.path(key);
    if (const std::optional<double> value = number_of(*node)) {
        out = risk::fixed(*value);
        return;
    }
    const auto* table = node->as_table();
    if (table == nullptr) {
        context.report(*node, path, describe(*node) + ": " + distribution_forms(unit));
        return;
    }
    const std::size_t problems_before = context.problems.size();
    TableReader r(*table, path, context);
    risk::Distribution d;
    std::vector<std::string> named;
    for (const std::string_view family : family_keys) {
        const toml::node* parameters = r.get(family);
        if (parameters == nullptr) continue;
        named.emplace_back(family);
        const std::string family_path = r.path(family);
        if (family == "uniform" || family == "triangular") {
            const bool uniform = family == "uniform";
            // [min, max] of a uniform as [min, mode, max] with an unused mode.
            std::optional<std::array<double, 3>> bounds = numbers<3>(*parameters);
            if (uniform) {
                const std::optional<std::array<double, 2>> ends = numbers<2>(*parameters);
                bounds.reset();
                if (ends) bounds = std::array<double, 3>{(*ends)[0], 0.0, (*ends)[1]};
            }
            if (!bounds) {
                context.report(
                    *parameters, family_path,
                    describe(*parameters) + ": must be " +
                        (uniform ? "[min, max], two numbers" : "[min, mode, max], three numbers") +
                        (unit.empty() ? "" : " (" + std::string(unit) + ")"));
                continue;
            }
            d.family = uniform ? risk::Distribution::Family::uniform
                               : risk::Distribution::Family::triangular;
            d.min = (*bounds)[0];
            d.mode = (*bounds)[1];
            d.max = (*bounds)[2];
        } else {
            d.family = family == "normal" ? risk::Distribution::Family::normal
                                          : risk::Distribution::Family::lognormal;
            read_moments(r, family, *parameters, unit, d);
        }
    }
    const bool truncatable = d.family == risk::Distribution::Family::normal ||
                             d.family == risk::Distribution::Family::lognormal;
    for (const std::string_view bound : {std::string_view("min"), std::string_view("max")}) {
        const toml::node* bound_node = table->get(bound);
        if (bound_node != nullptr && named.size() == 1 && !truncatable) {
            r.get(bound);
            context.report(*bound_node, r.path(bound),
                           describe(*bound_node) + ": truncates a normal or lognormal only; a " +
                               named.front() + " distribution gives its bounds in its array");
            continue;
        }
        read(r, bound, bound == "min" ? d.min : d.max, unit, any_finite());
    }
    if (named.empty()) {
        context.report(*node, path,
                       describe(*node) + ": names no distribution: " + distribution_forms(unit));
    } else if (named.size() > 1) {
        context.report(*node, path,
                       describe(*node) + ": names " + std::to_string(named.size()) +
                           " distributions (" + named[0] + ", " + named[1] +
                           (named.size() > 2 ? ", ..." : "") + "): give one");
    }
    r.finish();
    if (context.problems.size() == problems_before) out = d;
}

namespace {

// method, samples and seed: what every sweep has.
void read_sweep_header(TableReader& r, risk::SweepSpec& spec) {
    std::array<std::string_view, sweep_method_names.size()> methods;
    for (std::size_t i = 0; i < methods.size(); ++i) methods[i] = sweep_method_names[i].name;
    if (const auto index = read_choice(r, "method", methods)) {
        spec.method = sweep_method_names[*index].value;
    }
    read_integer(r, "samples", spec.samples, 1);
    std::int64_t seed = static_cast<std::int64_t>(spec.seed);
    read_integer(r, "seed", seed, 0);
    spec.seed = static_cast<std::uint64_t>(seed);
}

// A cluster scenario's samples are whole releases: every key but the header's is refused.
void refuse_for_cluster(TableReader& r, const toml::table& table, Context& context) {
    for (const auto& [key, value] : table) {
        const std::string_view name = key.str();
        if (name == "method" || name == "samples" || name == "seed") continue;
        r.get(name);
        context.report(value, r.path(name),
                       "cannot be swept over a cluster: each sample of a scenario with "
                       "[cluster] is one whole release, its rocks' sizes and orientations drawn "
                       "from the [cluster] table by the sample's seed, and its [[rocks]] kept "
                       "as written; a [sweep] table there sets only method, samples and seed");
    }
    r.finish();
}

}  // namespace

void read_sweep(const toml::node& node, risk::SweepSpec& spec, Context& context, bool cluster) {
    const auto* table = node.as_table();
    if (table == nullptr) {
        context.report(node, "sweep", describe(node) + ": must be a table ([sweep])");
        return;
    }
    TableReader r(*table, "sweep", context);
    read_sweep_header(r, spec);
    if (cluster) {
        refuse_for_cluster(r, *table, context);
        return;
    }
    read(r, "random_orientation", spec.random_orientation, "", {});
    read(r, "lateral_margin", spec.lateral_margin, "m", non_negative());
    with_table(r, "rock", [&](TableReader& rock) {
        read_sweep_shapes(rock, spec);
        for (const auto& [key, member, unit] : sweep_rock_keys) {
            read_distribution(rock, key, spec.*member, unit);
        }
        with_table(rock, "material", [&](TableReader& material) {
            for (const auto& [key, member, unit] : sweep_material_keys) {
                read_distribution(material, key, spec.*member, unit);
            }
        });
    });
    with_table(r, "release", [&](TableReader& release) { read_release(release, spec); });
    r.finish();
}

}  // namespace rockfall::scenario::detail
