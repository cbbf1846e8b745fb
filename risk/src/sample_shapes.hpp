#pragma once
// The rock shapes of a sweep: the checks of its shape choices and target sphericities, and
// one sample's shape (a family, the base rock's, an entry, or a generated rock).

#include "risk/sampling.hpp"

#include <cstdint>
#include <vector>

namespace rockfall::risk::detail {

// Appends the problems of the spec's shape inputs (kinds, entries, generated rocks, their
// weights, the sphericity's support) under the key sweep.rock.kind or sweep.rock.sphericity;
// returns true when there are none. The sphericity's own parameters are find_problems'.
bool check_shapes(std::vector<SweepProblem>& problems, const SweepSpec& spec,
                  const engine::Scenario& base);

// Fills s.kind, shape, target_sphericity, shape_seed and custom_shape of a validated spec
// from the sample's shape and sphericity coordinates and the first seed of its generator
// chain.
void draw_shape(const SweepSpec& spec, const engine::Scenario& base, double u_shape,
                double u_sphericity, std::uint64_t first_shape_seed, SampleInputs& s);

}  // namespace rockfall::risk::detail
