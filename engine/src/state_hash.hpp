#pragma once
// Bitwise hash of the rocks' final states (Outcome::state_hash). Private to the engine.

#include "engine/outcome.hpp"

#include <cstdint>
#include <vector>

namespace rockfall::engine {

// FNV-1a over the bits of each rock's final time, position, orientation, velocity and angular
// velocity, in rock order: equal runs give equal hashes.
std::uint64_t state_hash(const std::vector<RockOutcome>& rocks);

}  // namespace rockfall::engine
