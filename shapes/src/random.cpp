#include "shapes/random.hpp"

namespace rockfall::shapes {

std::uint64_t splitmix64(std::uint64_t x) {
    // The constants of the SplitMix64 output function (Steele et al. 2014): the golden-ratio
    // increment, then two multiply-xorshift rounds.
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}

std::mt19937_64 make_generator(std::uint64_t seed) { return std::mt19937_64(splitmix64(seed)); }

double uniform01(std::mt19937_64& generator) {
    constexpr double two_to_minus_53 = 1.0 / 9007199254740992.0;
    return static_cast<double>(generator() >> 11) * two_to_minus_53;
}

}  // namespace rockfall::shapes
