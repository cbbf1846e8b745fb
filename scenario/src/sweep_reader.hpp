#pragma once
// The [sweep] table of a scenario file: what a Monte Carlo or Latin hypercube sweep varies
// (risk::SweepSpec). Read like the rest of the file (types and key names while reading, every
// problem at once); ranges are checked on the filled spec, against the base scenario's own
// rules, so that specs built in code are held to the same checks.

#include "scenario/scenario_file.hpp"
#include "scenario_reader.hpp"
#include "scenario_schema.hpp"

#include "engine/scenario.hpp"
#include "risk/sampling.hpp"

#include <toml++/toml.h>

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::scenario::detail {

// One distribution-valued key of a struct S, with its unit.
template <class S>
struct DistributionKey {
    std::string_view key;
    risk::Distribution S::*member;
    std::string_view unit;
};

// [sweep.rock]
inline const std::array<DistributionKey<risk::SweepSpec>, 2> sweep_rock_keys{{
    {"size", &risk::SweepSpec::size, "m"},
    {"density", &risk::SweepSpec::density, "kg/m3"},
}};

// [sweep.rock.material]
inline const std::array<DistributionKey<risk::SweepSpec>, 3> sweep_material_keys{{
    {"friction", &risk::SweepSpec::friction, ""},
    {"restitution", &risk::SweepSpec::restitution, ""},
    {"rolling_resistance", &risk::SweepSpec::rolling_resistance, ""},
}};

// [sweep.release]
inline const std::array<DistributionKey<risk::SweepSpec>, 2> sweep_release_keys{{
    {"speed", &risk::SweepSpec::speed, "m/s"},
    {"spin", &risk::SweepSpec::spin, "rad/s"},
}};

// [[sweep.release.zones]]
inline const std::array<DistributionKey<risk::ReleaseZone>, 2> sweep_zone_keys{{
    {"distance", &risk::ReleaseZone::distance, "m"},
    {"lateral", &risk::ReleaseZone::lateral, "m"},
}};

inline constexpr std::array<EnumName<risk::SweepSpec::Method>, 2> sweep_method_names{{
    {"monte_carlo", risk::SweepSpec::Method::monte_carlo},
    {"latin_hypercube", risk::SweepSpec::Method::latin_hypercube},
}};

// The shape names a sweep may draw: the families, and "custom" for the base rock's own shape.
inline constexpr std::array<shapes::RockKind, 4> sweep_rock_kinds{
    shapes::RockKind::sphere, shapes::RockKind::massive, shapes::RockKind::planar,
    shapes::RockKind::custom};

// A distribution-valued key: a plain number (fixed) or an inline table naming one family.
// Keeps `out` unless everything in the value was read.
void read_distribution(TableReader& parent, std::string_view key, risk::Distribution& out,
                       std::string_view unit);

// The shape keys of [sweep.rock] (sweep_shapes.cpp): kind, a weighted choice of families,
// "custom" and named shapes; catalogue, a folder or TOML catalogue (relative to the file that
// writes it) whose entries kind may name; [[sweep.rock.shapes]], named hulls given as
// vertices; and sphericity, the target sphericity of generated rocks, which replaces the kind
// draw. Fills spec.kinds, kind_weights, entries, entry_weights and sphericity.
void read_sweep_shapes(TableReader& rock, risk::SweepSpec& spec);

// Fills `spec` from the [sweep] node. Start `spec` from risk::sweep_defaults(base), so that a key
// left out keeps the base rock's value. Wrong types and unknown keys go to `context`. With
// `cluster` (a scenario with [cluster], whose samples are whole releases drawn by the engine
// from the sample's seed) only method, samples and seed are read; every other key is reported,
// naming it.
void read_sweep(const toml::node& node, risk::SweepSpec& spec, Context& context,
                bool cluster = false);

// Problems of a spec against a valid base scenario: risk::find_problems, and the supports of
// size, density, the material coefficients and each zone's release distance checked with the
// scenario's own rules (find_problems on the base with that input at each end of its support).
// `sources` (may be null) places each problem in the file.
std::vector<ScenarioProblem> find_sweep_problems(const risk::SweepSpec& spec,
                                                 const engine::Scenario& base,
                                                 const SourceMap* sources);

// The spec as a complete [sweep] table, every key written out; read_sweep reads it back to an
// identical spec. Throws std::invalid_argument for a seed above 2^63 - 1 (TOML integers are
// signed 64-bit).
std::string format_sweep(const risk::SweepSpec& spec);

// The [sweep] table of a cluster scenario: method, samples and seed (read_cluster_sweep).
std::string format_cluster_sweep(const risk::SweepSpec& spec);

}  // namespace rockfall::scenario::detail
