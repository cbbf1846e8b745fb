#pragma once
/// Building particle sets: regular lattices filling boxes, and initial stress states.

#include "mpm/math.hpp"
#include "mpm/particles.hpp"
#include "shapes/slope.hpp"

namespace rockfall::mpm {

/// Fills an oriented box with a regular lattice of points at about `spacing` m (> 0), one point
/// at the centre of each lattice cell, with density kg/m3 (> 0). The count per box axis is
/// round(edge / spacing) (at least 1) and the point volume is the box volume over the count,
/// so the total mass is exactly density times volume. In 2D the box must be rotated about
/// scene y only; its local axes 0 and 2 span the x-z plane and volumes are per metre of width.
/// Returns the number of points added.
template <int Dim>
int add_box_particles(Particles<Dim>& particles, const shapes::OrientedBox& box, double spacing,
                      double density);

/// Sets a geostatic stress on every particle below a horizontal free surface at scene height
/// `surface_z` (m): vertical stress -rho g (surface_z - z), horizontal stresses k0 times it
/// (Pa, tension positive); rho from each particle's mass and volume, g > 0 in m/s2, k0 >= 0.
template <int Dim>
void set_geostatic_stress(Particles<Dim>& particles, double surface_z, double g, double k0);

}  // namespace rockfall::mpm
