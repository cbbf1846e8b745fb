#pragma once
// Rough linings in scenario files: [slope.lining.spheres], [slope.lining.bumps] and
// [slope.lining.sheet] (docs/clusters.md, "Linings"), each with its shape keys and the
// `segments` it lies on.

#include "scenario_reader.hpp"
#include "scenario_schema.hpp"

#include "engine/scenario.hpp"
#include "shapes/lining.hpp"
#include "shapes/slope.hpp"

#include <string>
#include <vector>

namespace rockfall::scenario::detail {

inline const Fields<shapes::SphereLayer, 2> sphere_layer_fields{{
    {"radius", &shapes::SphereLayer::radius, "m", closed(1e-3, 0.5)},
    {"spacing", &shapes::SphereLayer::spacing, "m", positive()},
}};

inline const Fields<shapes::Bumps, 3> bump_fields{{
    {"height", &shapes::Bumps::height, "m", closed(1e-3, 0.5)},
    {"base_diameter", &shapes::Bumps::base_diameter, "m", closed(2e-3, 1.0)},
    {"spacing", &shapes::Bumps::spacing, "m", positive()},
}};

inline const Fields<shapes::PerforatedSheet, 4> sheet_fields{{
    {"thickness", &shapes::PerforatedSheet::thickness, "m", closed(1e-4, 0.05)},
    {"hole_diameter", &shapes::PerforatedSheet::hole_diameter, "m", closed(5e-4, 0.5)},
    {"hole_spacing", &shapes::PerforatedSheet::hole_spacing, "m", positive()},
    {"hole_sides", &shapes::PerforatedSheet::hole_sides, "", closed(8, 64)},
}};

// Reads a list of segment indices (integers) at `key`.
void read_segment_list(TableReader& reader, std::string_view key, std::vector<int>& out);

// Reads [slope.lining] from the [slope] table being read, if present.
void read_lining(TableReader& slope_reader, shapes::SlopeSpec& slope);

// The lining's ranges, and the rules the geometry itself checks (spacing against size,
// segments of the profile, the number of spheres), at the lining's keys.
void check_lining(Checker& c, const shapes::SlopeSpec& slope, bool profile_ok);

}  // namespace rockfall::scenario::detail
