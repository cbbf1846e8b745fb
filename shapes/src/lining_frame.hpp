#pragma once
// Private helpers shared by the linings and the release box: a segment's surface plane, the
// check of a list of lined segments, and the rows of a hexagonal lattice.

#include "shapes/lining.hpp"
#include "shapes/polyhedron.hpp"
#include "shapes/slope.hpp"

#include <string_view>
#include <vector>

namespace rockfall::shapes::detail {

using shapes::SegmentPlane;

SegmentPlane segment_plane(const Slope& slope, int index);

// Throws std::invalid_argument unless every entry of `segments` (the field `field`, e.g.
// "sphere_layer.segments") is a distinct index of one of the slope's segments.
void check_segments(const Slope& slope, const std::vector<int>& segments, std::string_view field);

// Throws std::invalid_argument "<field> = <value> <unit>: must be in [lo, hi]" unless value is
// finite and within [lo, hi].
void check_range(std::string_view field, double value, std::string_view unit, double lo, double hi);

// Positions lo + margin + k step (k = 0, 1, ...) as many as fit in [lo, hi], with the
// leftover split equally at both ends; empty when hi < lo.
std::vector<double> centred_rows(double lo, double hi, double step);

// Row spacing of a hexagonal lattice of the given neighbour distance: spacing sqrt(3) / 2.
double hex_row_spacing(double spacing);

// Across-slope positions of the sites of lattice row `row` within |v| <= limit: j spacing on
// even rows, (j + 1/2) spacing on odd rows.
std::vector<double> hex_row_sites(int row, double spacing, double limit);

}  // namespace rockfall::shapes::detail
