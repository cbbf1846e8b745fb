// The verification scenes (see verification_scenes.hpp).

#include "engine/verification_scenes.hpp"

#include "engine/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace rockfall::engine::scenes {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

Vec3 downslope(double angle_deg) {
    return {std::cos(radians(angle_deg)), 0.0, -std::sin(radians(angle_deg))};
}

Vec3 upward_normal(double angle_deg) {
    return {std::sin(radians(angle_deg)), 0.0, std::cos(radians(angle_deg))};
}

Scenario plane_scenario(double angle_deg, shapes::RockKind kind, const Material& material,
                        double time_step) {
    Scenario scenario;
    scenario.slope.segments = {{40.0, angle_deg}};
    scenario.slope.bars.enabled = false;
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.enabled = false;
    scenario.materials.slope = material;
    scenario.rocks.front().rock.kind = kind;
    scenario.rocks.front().rock.size = 0.2;
    scenario.rocks.front().rock.material = material;
    scenario.rocks.front().release.distance = 5.0;
    scenario.stations = {};
    scenario.numerics.time_step = time_step;
    scenario.gravity = gravity;
    return scenario;
}

std::vector<RockState> trajectory(const Scenario& scenario, double interval) {
    std::vector<RockState> states;
    RunOptions options;
    options.trajectory_interval = interval;
    options.trajectory = [&](int, const RockState& state) { states.push_back(state); };
    simulate(scenario, 1, options);
    return states;
}

const RockState& state_at(const std::vector<RockState>& states, double t) {
    return *std::min_element(states.begin(), states.end(),
                             [t](const RockState& a, const RockState& b) {
                                 return std::abs(a.time - t) < std::abs(b.time - t);
                             });
}

double mean_acceleration(const std::vector<RockState>& states, const Vec3& direction, double t0,
                         double t1) {
    const RockState& a = state_at(states, t0);
    const RockState& b = state_at(states, t1);
    return (b.velocity - a.velocity).dot(direction) / (b.time - a.time);
}

Scenario wall_scenario(const WallContact& contact, double restitution, double size, double speed,
                       double density) {
    constexpr double gap = 0.8;  // m
    Scenario scenario;
    scenario.name = "wall hit";
    scenario.slope.segments = {{4.0, 0.0}};
    scenario.slope.bars.enabled = false;
    scenario.slope.bars.segments.clear();
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.distance_from_toe = 3.0;
    // No friction anywhere, so the sphere slides without spin and the wall's friction is idle.
    scenario.materials.slope = Material{0.0, 0.3, 0.0};
    scenario.materials.wall = Material{0.0, restitution, 0.0};
    scenario.wall_contact = contact;
    RockRelease rock;
    rock.rock.kind = shapes::RockKind::sphere;
    rock.rock.size = size;
    rock.rock.density = density;
    rock.rock.material = Material{0.0, restitution, 0.0};
    rock.release.distance = 3.0 - 0.5 * size - gap;
    rock.release.velocity = Vec3(speed, 0.0, 0.0);
    scenario.rocks = {rock};
    scenario.stations = {1.0};
    scenario.numerics.max_time = gap / speed + 0.2;
    return scenario;
}

Bounce first_bounce(double angle_deg, shapes::RockKind kind, double restitution, double time_step,
                    double height) {
    Scenario scenario = plane_scenario(angle_deg, kind, {0.5, restitution, 0.0}, time_step);
    scenario.rocks.front().release.height = height;
    scenario.numerics.max_time = 1.5;
    Bounce bounce;
    bounce.states = trajectory(scenario, 1e-6);
    const std::vector<RockState>& states = bounce.states;
    const Vec3 n = upward_normal(angle_deg);
    // The release puts the lowest point `height` above the surface: contact is at this normal
    // coordinate of the centre.
    const double touching = states.front().position.dot(n) - height;
    std::size_t k = 1;
    while (k < states.size() &&
           !(states[k - 1].velocity.dot(n) < 0.0 && states[k].velocity.dot(n) > 0.0)) {
        ++k;
    }
    if (k >= states.size()) throw std::runtime_error("first_bounce: the rock never rebounded");
    bounce.velocity_ratio = states[k].velocity.dot(n) / -states[k - 1].velocity.dot(n);
    double apex = states[k].position.dot(n);
    for (std::size_t j = k; j < states.size() && states[j].velocity.dot(n) >= 0.0; ++j) {
        apex = std::max(apex, states[j].position.dot(n));
    }
    bounce.rebound_height = apex - touching;
    return bounce;
}

}  // namespace rockfall::engine::scenes
