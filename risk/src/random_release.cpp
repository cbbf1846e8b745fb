#include "risk/random_release.hpp"

#include "validation.hpp"

#include "shapes/random.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

constexpr double pi = 3.14159265358979323846;

using detail::require;

}  // namespace

// One implementation for shapes and risk: shapes/random.hpp.
std::uint64_t splitmix64(std::uint64_t x) { return shapes::splitmix64(x); }

std::mt19937_64 make_generator(std::uint64_t seed) { return shapes::make_generator(seed); }

double uniform01(std::mt19937_64& generator) { return shapes::uniform01(generator); }

double uniform(std::mt19937_64& generator, double lo, double hi) {
    return lo + (hi - lo) * uniform01(generator);
}

std::size_t uniform_index(std::mt19937_64& generator, std::size_t n) {
    require(n > 0, "uniform_index needs n > 0");
    const auto index =
        static_cast<std::size_t>(std::floor(static_cast<double>(n) * uniform01(generator)));
    return index < n ? index : n - 1;
}

engine::Vec3 orientation_deg_from_uniforms(double u1, double u2, double u3) {
    return {-180.0 + 360.0 * u1, std::asin(-1.0 + 2.0 * u2) * 180.0 / pi, -180.0 + 360.0 * u3};
}

engine::Vec3 uniform_orientation_deg(std::mt19937_64& generator) {
    const double u1 = uniform01(generator);
    const double u2 = uniform01(generator);
    const double u3 = uniform01(generator);
    return orientation_deg_from_uniforms(u1, u2, u3);
}

engine::Scenario random_rock_scenario(const engine::Scenario& base, std::uint64_t seed,
                                      const RandomRockRanges& ranges) {
    require(!base.rocks.empty(), "random_rock_scenario: the base scenario has no rock to vary");
    require(!ranges.kinds.empty(), "RandomRockRanges.kinds: must not be empty");
    require(
        ranges.min_size >= 0.01 && ranges.min_size <= ranges.max_size && ranges.max_size <= 10.0,
        "RandomRockRanges sizes [" + std::to_string(ranges.min_size) + ", " +
            std::to_string(ranges.max_size) + "] m: need 0.01 <= min_size <= max_size <= 10");
    require(ranges.lateral_margin >= 0.0,
            "RandomRockRanges.lateral_margin = " + std::to_string(ranges.lateral_margin) +
                " m: must be >= 0");

    std::mt19937_64 generator = make_generator(seed);
    engine::RockRelease rock = base.rocks.front();
    rock.rock.kind = ranges.kinds[uniform_index(generator, ranges.kinds.size())];
    rock.rock.shape = nullptr;  // the drawn family replaces any mesh shape of the base rock
    rock.rock.size = uniform(generator, ranges.min_size, ranges.max_size);

    const double radius = shapes::make_rock(rock.rock.kind, rock.rock.size).bounding_radius;
    const double half_range = 0.5 * base.slope.width - radius - ranges.lateral_margin;
    require(half_range >= 0.0, "a " + std::string(shapes::to_string(rock.rock.kind)) + " of " +
                                   std::to_string(rock.rock.size) + " m with a margin of " +
                                   std::to_string(ranges.lateral_margin) +
                                   " m does not fit across the slope width of " +
                                   std::to_string(base.slope.width) + " m");
    rock.release.lateral = uniform(generator, -half_range, half_range);
    rock.release.orientation_deg = uniform_orientation_deg(generator);
    rock.release.random_orientation = false;

    engine::Scenario scenario = base;
    scenario.rocks = {rock};
    return scenario;
}

}  // namespace rockfall::risk
