#pragma once
// Recorders that run after each step, outside the physics: trajectory samples, stations,
// reach and maxima of one rock. Private to the engine.

#include "world.hpp"

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "engine/simulation.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <vector>

namespace rockfall::engine {

// Gap between the rock's lowest point and the ground (the slabs' surface or the terrain mesh,
// not bars), measured along the ground's normal under that point, m; negative when it
// penetrates.
double surface_gap(const shapes::Slope& slope, const shapes::RockGeometry& rock,
                   const BodyState& state);

// A rock's state at `time` with its kinetic energies (mass kg, principal moments kg m2).
RockState rock_state(const BodyState& body, double time, double mass,
                     const Vec3& principal_inertia);

// One rock's recorders. The rock's state after each step is the state before the next one.
class RockRecorder {
  public:
    // rolling_radius: r of Cr = w r / v, m (half the nominal size).
    RockRecorder(const Scenario& scenario, const shapes::Slope& slope, int rock_index,
                 double rolling_radius, const RunOptions& options);

    // The initial state and its surface gap (m).
    void start(const RockState& state, double gap);
    // One step from `before` (with gap_before) to `after` (with gap_after).
    void after_step(const RockState& before, double gap_before, const RockState& after,
                    double gap_after);
    // Writes reach, maxima, stations and V' into `outcome` and emits the final sample.
    void finish(const RockState& final_state, RockOutcome& outcome);

  private:
    void sample(const RockState& state);
    StationCrossing crossing(double distance, const RockState& before, double gap_before,
                             const RockState& after, double gap_after) const;

    const shapes::Slope& slope_;
    int rock_index_;
    double rolling_radius_;
    const RunOptions& options_;
    double toe_x_;
    double last_sample_time_ = -1.0;
    long next_sample_ = 0;
    double reach_ = 0.0;
    double max_speed_ = 0.0;
    double max_energy_ = 0.0;
    double max_gap_ = 0.0;
    std::vector<StationCrossing> stations_;
};

}  // namespace rockfall::engine
