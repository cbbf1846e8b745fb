#include "engine/simulation.hpp"

#include "cluster_release.hpp"
#include "recorders.hpp"
#include "release.hpp"
#include "state_hash.hpp"
#include "step_size.hpp"
#include "stop_rule.hpp"
#include "wall_substep.hpp"
#include "world.hpp"

#include "engine/wall_contact.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <iterator>
#include <optional>
#include <vector>

namespace rockfall::engine {
namespace {

// Where a rock is in its run: moving (the run waits for it), at rest and kept in the world as
// an obstacle until the run ends (it moves again if something pushes it), or gone (left the
// domain, failed, time limit: out of the world).
enum class Phase { moving, resting, gone };

// Everything that belongs to one rock during a run.
struct RockRun {
    RockRun(shapes::RockGeometry rock, int body_index, double rock_mass, const Vec3& rock_inertia,
            RockRecorder rock_recorder, StopRule rule)
        : geometry(std::move(rock)),
          body(body_index),
          mass(rock_mass),
          inertia(rock_inertia),
          recorder(std::move(rock_recorder)),
          stop_rule(std::move(rule)) {}

    shapes::RockGeometry geometry;
    int body = -1;
    double mass = 0.0;
    Vec3 inertia = Vec3::Zero();
    std::optional<WallContactLaw> law;  // only when the scenario has a reaction wall
    LoadCell load_cell;
    RockRecorder recorder;
    StopRule stop_rule;
    Phase phase = Phase::moving;
    // State after the last step (before the next one) and its gap above the surface.
    BodyState body_state;
    RockState state;
    double gap = 0.0;
    // Wall contact of the coming step: the approach and force (whole-world stepping), or its
    // sub-steps (per-rock stepping) when the rock may touch the wall within the step.
    WallApproach approach;
    std::optional<WallForce> wall_force;
    std::optional<WallSubsteps> substeps;
    WallContactTrack track;
    // Whether Bullet's rigid contact holds the rock against the wall (a resting contact) rather
    // than the compliant law (an impact).
    bool rigid_wall = false;
    // Found deeper in the wall than half its size: it went through the contact.
    bool inside_wall = false;
};

// Step size of the coming step and whether the near-wall refinement chose it.
struct StepChoice {
    double dt = 0.0;
    bool fine = false;
};

// One run: builds the world and steps it, phase by phase, until every rock has stopped.
class Run {
  public:
    Run(const Scenario& scenario, std::uint64_t seed, const RunOptions& options);
    Outcome execute();

  private:
    WallRock wall_rock(RockRun& rock) {
        return {rock.geometry, rock.mass, rock.inertia, *rock.law, rock.track, rigid_resting_};
    }
    void wall_contacts();
    void substep_wall_contacts();
    StepChoice step_size() const;
    void record(double dt);
    void stop(std::size_t index, StopReason reason);
    void settle(std::size_t index);
    void wake(std::size_t index);
    void finalize(std::size_t index);
    void make_rigid(RockRun& rock);
    void settle_cluster(const Cluster& cluster);

    const Scenario& scenario_;
    const shapes::Slope slope_;
    // The angle bars, when the step is refined near them (numerics.bar_refinement > 1).
    std::vector<shapes::OrientedBox> bars_;
    World world_;
    std::vector<RockRun> rocks_;
    Outcome outcome_;
    double time_ = 0.0;
    // Rocks still moving: the run ends when none is.
    std::size_t moving_count_ = 0;
    // Rocks out of the world.
    std::int64_t gone_count_ = 0;
    // RunOptions::rigid_resting_wall.
    bool rigid_resting_ = true;
};

Run::Run(const Scenario& scenario, std::uint64_t seed, const RunOptions& options)
    : scenario_(scenario),
      slope_(scenario.slope),
      world_(scenario, slope_),
      rigid_resting_(options.rigid_resting_wall) {
    assert(!scenario.rocks.empty() || scenario.cluster);
    assert(options.trajectory_interval > 0.0);
    assert(options.collision_threads >= 1);
    world_.set_collision_threads(options.collision_threads);
    if (scenario.numerics.bar_refinement > 1) {
        for (const shapes::OrientedBox& box : slope_.solids()) {
            if (box.role == shapes::SurfaceRole::bar) bars_.push_back(box);
        }
    }
    Random random(seed);
    std::vector<PlacedRock> placed;
    for (const RockRelease& spec : scenario.rocks) {
        PlacedRock& rock = placed.emplace_back();
        rock.spec = spec;
        rock.geometry = spec.rock.geometry();
        rock.initial = release_state(slope_, rock.geometry, spec.release, random);
    }
    if (scenario.cluster) {
        std::vector<PlacedRock> cluster = cluster_rocks(slope_, *scenario.cluster, seed);
        std::move(cluster.begin(), cluster.end(), std::back_inserter(placed));
    }
    if (options.geometry) {
        RunGeometry geometry;
        for (const PlacedRock& rock : placed) geometry.rocks.push_back(rock.geometry);
        if (scenario.cluster)
            geometry.solids.push_back(release_box_walls(slope_, scenario.cluster->box)[1]);
        options.geometry(geometry);
    }
    std::vector<int> bodies;
    for (const PlacedRock& rock : placed) {
        bodies.push_back(world_.add_rock(rock.geometry, rock.spec.rock, rock.initial));
    }
    if (scenario.cluster) {
        settle_cluster(*scenario.cluster);
    }
    rocks_.reserve(placed.size());
    outcome_.rocks.resize(placed.size());
    for (std::size_t i = 0; i < placed.size(); ++i) {
        const RockRelease& spec = placed[i].spec;
        shapes::RockGeometry& geometry = placed[i].geometry;
        const int body = bodies[i];
        const BodyState initial = world_.state(body);
        const double rolling_radius = 0.5 * geometry.nominal_size;
        const double bounding_radius = geometry.bounding_radius;
        RockRun& rock = rocks_.emplace_back(
            std::move(geometry), body, world_.mass(body), world_.inertia(body),
            RockRecorder(scenario, slope_, static_cast<int>(i), rolling_radius, options),
            StopRule(scenario.numerics, slope_, bounding_radius));
        if (slope_.wall()) {
            rock.law.emplace(scenario.wall_contact, scenario.materials.wall, spec.rock.material,
                             rock.mass, rock.geometry);
        }
        rock.body_state = initial;
        rock.state = rock_state(initial, 0.0, rock.mass, rock.inertia);
        rock.gap = surface_gap(slope_, rock.geometry, initial);
        rock.recorder.start(rock.state, rock.gap);
        outcome_.rocks[i].size = spec.rock.size;
        outcome_.rocks[i].name = spec.name;
    }
    moving_count_ = rocks_.size();
}

// Before t = 0: the packed cluster settles in its box, closed by a gate and a back wall, at the
// coarse step; then the gate opens (the back wall stays, as the experiment's box did). Nothing
// is recorded and the clock starts at the opening.
void Run::settle_cluster(const Cluster& cluster) {
    const std::array<shapes::OrientedBox, 2> walls = release_box_walls(slope_, cluster.box);
    const int gate = world_.add_static_box(walls[0], scenario_.materials.side_walls);
    world_.add_static_box(walls[1], scenario_.materials.side_walls);
    const double dt = scenario_.numerics.time_step;
    const auto steps = static_cast<long>(std::ceil(cluster.settle_time / dt));
    for (long k = 0; k < steps; ++k) {
        world_.step(dt);
    }
    world_.remove_static_box(gate);
}

Outcome Run::execute() {
    while (moving_count_ > 0) {
        wall_contacts();
        const StepChoice step = step_size();
        // Phase 3: the physics step.
        world_.step(step.dt);
        time_ += step.dt;
        ++(step.fine ? outcome_.fine_steps : outcome_.coarse_steps);
        outcome_.body_steps += static_cast<std::int64_t>(rocks_.size()) - gone_count_;
        record(step.dt);
    }
    for (std::size_t i = 0; i < rocks_.size(); ++i) {
        if (rocks_[i].phase == Phase::resting) {
            finalize(i);
        }
    }
    outcome_.simulated_time = time_;
    outcome_.state_hash = state_hash(outcome_.rocks);
    return std::move(outcome_);
}

// Phase 1: the compliant wall contact of each rock that may touch the wall, applied as an
// external force for the coming step (Bullet clears forces after each step). A slow touch, or
// a contact that outlasts an impact, becomes a resting contact that Bullet holds rigidly.
void Run::wall_contacts() {
    if (scenario_.numerics.wall_stepping == WallStepping::per_rock) {
        substep_wall_contacts();
        return;
    }
    const std::optional<shapes::OrientedBox>& wall = slope_.wall();
    for (RockRun& rock : rocks_) {
        rock.wall_force.reset();
        if (rock.phase == Phase::gone || !wall || rock.rigid_wall) {
            continue;
        }
        const BodyState& s = rock.body_state;
        rock.approach = wall_approach(*wall, rock.geometry, s, scenario_.numerics.time_step);
        if (rock.approach.gap > 0.0 && !rock.track.touching) {
            continue;
        }
        const WallContactAt at =
            wall_contact_at(*wall, wall_rock(rock), s, time_,
                            scenario_.wall_contact.steps_per_contact, scenario_.numerics.time_step);
        if (at.kind == WallContactAt::Kind::inside) {
            rock.inside_wall = true;
        } else if (at.kind == WallContactAt::Kind::resting) {
            make_rigid(rock);
        } else if (at.kind == WallContactAt::Kind::force) {
            rock.wall_force = at.force;
            world_.apply_force(rock.body, at.force.force, at.force.point);
        }
    }
}

// Phase 1 with per-rock stepping: each rock that may touch the wall within the coming step
// has its wall contact sub-stepped on its own, at the contact's fine step; the rigid-body step
// applies the resulting impulse as a constant force and torque (its momentum change is the
// load cell's impulse), and the pose correction after the step (record) puts the rock where
// the sub-steps did. Everything else stays at the coarse step.
void Run::substep_wall_contacts() {
    const std::optional<shapes::OrientedBox>& wall = slope_.wall();
    const double dt = scenario_.numerics.time_step;
    const Vec3 gravity(0.0, 0.0, -scenario_.gravity);
    for (RockRun& rock : rocks_) {
        rock.substeps.reset();
        rock.wall_force.reset();
        if (rock.phase == Phase::gone || !wall || rock.rigid_wall) {
            continue;
        }
        const BodyState& s = rock.body_state;
        if (!rock.track.touching && !rock.load_cell.in_contact()) {
            const WallApproach approach = wall_approach(*wall, rock.geometry, s, dt);
            // Within reach of the wall during the step, with a reserve for what gravity adds.
            if (approach.gap > approach.closing_speed * dt + scenario_.gravity * dt * dt + 1e-4) {
                continue;
            }
        }
        WallSubsteps& substeps = rock.substeps.emplace(
            substep_wall(*wall, wall_rock(rock), s, time_, dt, gravity,
                         scenario_.wall_contact.steps_per_contact, rock.load_cell));
        outcome_.fine_steps += substeps.substeps;
        if (substeps.end == WallContactAt::Kind::free) {
            // It did not touch the wall: nothing to apply or correct.
            rock.substeps.reset();
            continue;
        }
        if (substeps.end == WallContactAt::Kind::inside) {
            rock.inside_wall = true;
        } else if (substeps.end == WallContactAt::Kind::resting) {
            make_rigid(rock);
        }
        world_.apply_impulse_over_step(rock.body, substeps.impulse, substeps.angular_impulse, dt);
    }
}

void Run::make_rigid(RockRun& rock) {
    rock.rigid_wall = true;
    world_.set_rigid_wall_contact(rock.body, true);
}

// Phase 2: the coarse step, or the shortest step a rock near the wall needs: the contact's fine
// step while an impact lasts, shrinking approach steps before. Resting contacts, and rocks
// too slow to make an impact, take the coarse step. With numerics.bar_refinement, the coarse
// step is divided while a rock approaching an angle bar at 1 m/s or more may reach it within
// two coarse steps (may_reach).
StepChoice Run::step_size() const {
    const double coarse = scenario_.numerics.time_step;
    double dt = coarse;
    if (!bars_.empty() && std::any_of(rocks_.begin(), rocks_.end(), [&](const RockRun& rock) {
            return rock.phase == Phase::moving &&
                   may_reach(bars_, rock.geometry, rock.body_state, coarse, scenario_.gravity);
        })) {
        dt = coarse / scenario_.numerics.bar_refinement;
    }
    if (scenario_.numerics.wall_stepping == WallStepping::per_rock) {
        return {dt, dt < coarse};
    }
    const int steps_per_contact = scenario_.wall_contact.steps_per_contact;
    for (const RockRun& rock : rocks_) {
        if (rock.phase == Phase::gone || !rock.law || rock.rigid_wall) {
            continue;
        }
        if (rock.track.touching || rock.load_cell.in_contact()) {
            dt = std::min(dt, rock.track.step);
        } else if (rock.approach.closing_speed >= kRestingContactSpeed) {
            dt = std::min(dt, approach_step(*rock.law, rock.approach, steps_per_contact, coarse));
        }
    }
    return {dt, dt < coarse};
}

// The wall force a resting contact applied during the last step, as the load cell reads a
// compliant one: the constraint impulse over the step. Empty once Bullet holds no contact
// point, which ends the resting contact.
std::optional<WallForce> resting_wall_force(const RigidWallContact& contact, double dt) {
    if (!contact.touching || contact.normal_impulse <= 0.0) {
        return std::nullopt;
    }
    WallForce force;
    force.force = contact.impulse / dt;
    force.point = contact.point;
    force.normal = contact.normal_impulse / dt;
    force.normal_direction = contact.normal;
    force.tangential = (force.force - force.normal * force.normal_direction).norm();
    return force;
}

// Phase 4 (after the physics step): load cells, recorders and stop rules.
void Run::record(double dt) {
    const bool any_rigid = std::any_of(rocks_.begin(), rocks_.end(), [](const RockRun& rock) {
        return rock.phase != Phase::gone && rock.rigid_wall;
    });
    const std::vector<RigidWallContact> rigid =
        any_rigid ? world_.rigid_wall_contacts() : std::vector<RigidWallContact>();
    for (std::size_t i = 0; i < rocks_.size(); ++i) {
        RockRun& rock = rocks_[i];
        if (rock.phase == Phase::gone) {
            continue;
        }
        if (rock.substeps) {
            world_.shift_pose(rock.body, rock.substeps->position_shift,
                              rock.substeps->rotation_shift);
        }
        const BodyState body = world_.state(rock.body);
        const RockState after = rock_state(body, time_, rock.mass, rock.inertia);
        const double gap = surface_gap(slope_, rock.geometry, body);
        bool holding = false;
        if (rock.rigid_wall) {
            const RigidWallContact& contact = rigid[static_cast<std::size_t>(rock.body)];
            rock.wall_force = resting_wall_force(contact, dt);
            holding = contact.touching;
            if (!contact.touching) {
                rock.rigid_wall = false;
                rock.track.touching = false;
                world_.set_rigid_wall_contact(rock.body, false);
            }
        }
        // Sub-steps fed the load cell themselves, unless a resting contact took over.
        const bool recorded = rock.substeps && !rock.rigid_wall;
        if (!recorded && (rock.wall_force || rock.load_cell.in_contact())) {
            rock.load_cell.record(dt, rock.wall_force, rock.state, after, holding);
        }
        rock.recorder.after_step(rock.state, rock.gap, after, gap);
        rock.body_state = body;
        rock.state = after;
        rock.gap = gap;
        const std::optional<StopReason> reason =
            rock.inside_wall ? StopReason::numerical_failure : rock.stop_rule.check(after, dt);
        if (!reason) {
            if (rock.phase == Phase::resting) {
                wake(i);
            }
        } else if (*reason != StopReason::at_rest) {
            stop(i, *reason);
        } else if (rock.phase == Phase::moving) {
            settle(i);
        }
    }
}

// A moving rock comes to rest: its outcome says so, and it stays in the world.
void Run::settle(std::size_t index) {
    RockRun& rock = rocks_[index];
    rock.phase = Phase::resting;
    outcome_.rocks[index].stop = StopReason::at_rest;
    outcome_.rocks[index].stop_time = time_;
    world_.allow_sleep(rock.body, true, scenario_.numerics.rest_speed,
                       rock.geometry.bounding_radius);
    --moving_count_;
}

// A rock at rest is moving again (pushed or undermined): the run waits for it once more.
void Run::wake(std::size_t index) {
    RockRun& rock = rocks_[index];
    rock.phase = Phase::moving;
    world_.allow_sleep(rock.body, false, 0.0, 0.0);
    ++moving_count_;
}

// The end of a rock's record: open wall hits close, reach and maxima are written.
void Run::finalize(std::size_t index) {
    RockRun& rock = rocks_[index];
    RockOutcome& outcome = outcome_.rocks[index];
    outcome.final_state = rock.state;
    rock.load_cell.finish(rock.state);
    outcome.wall_hits = rock.load_cell.hits();
    rock.recorder.finish(rock.state, outcome);
}

// A moving rock leaves the run: out of the domain, failed or out of time.
void Run::stop(std::size_t index, StopReason reason) {
    RockRun& rock = rocks_[index];
    RockOutcome& outcome = outcome_.rocks[index];
    outcome.stop = reason;
    outcome.stop_time = time_;
    finalize(index);
    world_.remove_rock(rock.body);
    if (rock.phase == Phase::moving) {
        --moving_count_;
    }
    rock.phase = Phase::gone;
    ++gone_count_;
}

}  // namespace

Outcome simulate(const Scenario& scenario, std::uint64_t seed, const RunOptions& options) {
    Run run(scenario, seed, options);
    return run.execute();
}

}  // namespace rockfall::engine
