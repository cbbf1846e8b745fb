#pragma once
/// Random rocks for Monte Carlo sweeps. Every draw comes from the sample's seed alone, through
/// a generator and conversions whose output the C++ standard fixes, so a seed gives the same
/// rock on every platform and compiler.

#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"

#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace rockfall::risk {

/// What a random rock is drawn from (defaults: the shapes and sizes of seed 000).
struct RandomRockRanges {
    /// Shape families, drawn with equal probability; not empty.
    std::vector<shapes::RockKind> kinds = {shapes::RockKind::sphere, shapes::RockKind::massive,
                                           shapes::RockKind::planar};
    /// Smallest nominal (volume-equivalent) diameter, m, in [0.01, max_size].
    double min_size = 0.2;
    /// Largest nominal diameter, m, in [min_size, 10]; the size is uniform in between.
    double max_size = 0.4;
    /// Clearance between the rock's bounding sphere and each edge of the slope width, m (>= 0).
    double lateral_margin = 0.05;
};

/// SplitMix64 output function (Steele, Lea and Flood, OOPSLA 2014): a bijective 64-bit mix,
/// so that consecutive seeds give unrelated generator states.
std::uint64_t splitmix64(std::uint64_t x);

/// The generator of one sample: std::mt19937_64 seeded with splitmix64(seed). The engine's
/// output sequence is fixed by the standard; std::uniform_real_distribution and the other
/// standard distributions are not (implementation-defined), so draw with the functions below.
std::mt19937_64 make_generator(std::uint64_t seed);

/// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw: (x >> 11) * 2^-53.
double uniform01(std::mt19937_64& generator);

/// Uniform double in [lo, hi): lo + (hi - lo) * uniform01(generator); one draw.
double uniform(std::mt19937_64& generator, double lo, double hi);

/// Uniform index in [0, n), n > 0: floor(n * uniform01(generator)); one draw (bias below
/// n * 2^-53).
std::size_t uniform_index(std::mt19937_64& generator, std::size_t n);

/// The rotation of three uniforms u1, u2, u3 in [0, 1) as x-y-z Euler angles, degrees:
/// (360 u1 - 180, asin(2 u2 - 1), 360 u3 - 180). Uniform inputs give the first and last angle
/// uniform in [-180, 180) and the middle one arcsine-distributed in [-90, 90] (density
/// cos(b) / 2), which is the Haar measure for any Tait-Bryan convention with y in the middle,
/// intrinsic or extrinsic (the volume element of SO(3) is cos(b) da db dc).
engine::Vec3 orientation_deg_from_uniforms(double u1, double u2, double u3);

/// A uniformly distributed rotation (orientation_deg_from_uniforms of three uniform01 draws).
engine::Vec3 uniform_orientation_deg(std::mt19937_64& generator);

/// A copy of `base` (at least one rock) holding one rock: base.rocks[0] with four things drawn
/// from a generator seeded only by `seed` (make_generator), in this order: the kind (uniform
/// over ranges.kinds), the size (uniform in [min_size, max_size]), the lateral release position
/// (uniform in +-(width / 2 - bounding radius - lateral_margin), the bounding radius from
/// shapes::make_rock) and the orientation (uniform_orientation_deg; random_orientation is
/// cleared, so the returned scenario alone fixes the rock). Everything else is kept. Throws
/// std::invalid_argument for bad ranges, a base without rocks, or a rock that does not fit
/// across the slope.
engine::Scenario random_rock_scenario(const engine::Scenario& base, std::uint64_t seed,
                                      const RandomRockRanges& ranges = {});

}  // namespace rockfall::risk
