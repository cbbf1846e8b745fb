#pragma once
/// Reproducible random numbers: the same seed gives the same draws on every platform, because
/// the standard fixes std::mt19937_64's output but not that of its distributions.

#include <cstdint>
#include <random>

namespace rockfall::shapes {

/// SplitMix64 output function (Steele, Lea and Flood, OOPSLA 2014): a bijective 64-bit mix,
/// so that consecutive seeds give unrelated generator states.
std::uint64_t splitmix64(std::uint64_t x);

/// The generator of one seed: std::mt19937_64 seeded with splitmix64(seed).
std::mt19937_64 make_generator(std::uint64_t seed);

/// Uniform double in [0, 1) from the top 53 bits of one 64-bit draw: (x >> 11) * 2^-53.
double uniform01(std::mt19937_64& generator);

}  // namespace rockfall::shapes
