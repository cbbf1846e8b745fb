#pragma once
// A pure normal wall impact through the whole engine, for the wall tests: the library's
// verification scene (engine/verification_scenes.hpp) under the tests' name, and its first hit.

#include "engine/outcome.hpp"
#include "engine/verification_scenes.hpp"

#include <catch2/catch.hpp>

namespace rockfall::engine::test {

using scenes::wall_scenario;

// The first wall hit of a one-rock run; fails the test when there is none.
inline const WallHit& first_hit(const Outcome& outcome) {
    REQUIRE(outcome.rocks.size() == 1);
    REQUIRE(!outcome.rocks[0].wall_hits.empty());
    return outcome.rocks[0].wall_hits.front();
}

}  // namespace rockfall::engine::test
