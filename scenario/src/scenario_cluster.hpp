#pragma once
// A cluster in scenario files: the [cluster] table with its grading, rock family, density,
// settle time, [cluster.material] and [cluster.box] (docs/clusters.md, "Clusters in scenario
// files").

#include "scenario_reader.hpp"
#include "scenario_rock_shape.hpp"
#include "scenario_schema.hpp"

#include "engine/scenario.hpp"
#include "shapes/grading.hpp"
#include "shapes/release_box.hpp"

#include <array>
#include <string_view>

namespace rockfall::scenario::detail {

inline const Fields<shapes::Grading, 6> grading_fields{{
    {"count", &shapes::Grading::count, "", closed(0, shapes::max_cluster_rocks)},
    {"total_volume", &shapes::Grading::total_volume, "m3", non_negative()},
    {"d50", &shapes::Grading::d50, "m", positive()},
    {"cu", &shapes::Grading::cu, "", closed(1.0, 20.0)},
    {"d_min", &shapes::Grading::d_min, "m", closed(0.01, 10.0)},
    {"d_max", &shapes::Grading::d_max, "m", closed(0.01, 10.0)},
}};

inline const Fields<engine::Cluster, 2> cluster_fields{{
    {"settle_time", &engine::Cluster::settle_time, "s", closed(0.01, 10.0)},
    // 0: off; check_cluster also refuses (0, 0.5).
    {"sphericity", &engine::Cluster::sphericity, "", closed(0.0, 0.95)},
}};

inline const Fields<shapes::ReleaseBox, 5> release_box_fields{{
    {"start", &shapes::ReleaseBox::start, "m", non_negative()},
    {"length", &shapes::ReleaseBox::length, "m", positive()},
    {"width", &shapes::ReleaseBox::width, "m", positive()},
    {"height", &shapes::ReleaseBox::height, "m", positive()},
    {"floor", &shapes::ReleaseBox::floor, "m", non_negative()},
}};

// A marked rock's spot in the release box (its shape keys are a [[rocks]] entry's).
inline const Fields<engine::MarkedRock, 2> marked_rock_fields{{
    {"along", &engine::MarkedRock::along, "m", non_negative()},
    {"across", &engine::MarkedRock::across, "m", any_finite()},
}};

inline constexpr std::array<EnumName<shapes::Packing>, 2> packing_names{{
    {"spheres", shapes::Packing::spheres},
    {"flat", shapes::Packing::flat},
}};

// The families a cluster's rocks may take (a custom hull has no size to draw).
inline constexpr std::array<shapes::RockKind, 3> cluster_kinds = {
    shapes::RockKind::sphere, shapes::RockKind::massive, shapes::RockKind::planar};

// Reads [cluster] from the root table, if present. A scenario with a cluster and no [[rocks]]
// has no other rocks (not the default one).
// Its [[cluster.marked]] rocks take their shapes through `shape_cache`.
void read_cluster(TableReader& root, engine::Scenario& scenario, bool has_rocks,
                  RockShapeCache& shape_cache);

// The cluster's ranges, its grading's rules and its box against the slope.
void check_cluster(Checker& c, const engine::Scenario& scenario, bool profile_ok);

}  // namespace rockfall::scenario::detail
