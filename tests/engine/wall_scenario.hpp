#pragma once
// A pure normal wall impact through the whole engine, for the wall tests: the library's
// verification scene (engine/verification_scenes.hpp) under the tests' name.

#include "engine/verification_scenes.hpp"

namespace rockfall::engine::test {

using scenes::wall_scenario;

}  // namespace rockfall::engine::test
