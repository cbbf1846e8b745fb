#pragma once
// A pure normal wall impact through the whole engine, for the wall tests: a sphere slides
// without friction along a flat 4 m run-out into the reaction wall, whose face is 3 m from the
// run-out's start; the sphere's front starts 0.8 m upslope of it.

#include "engine/scenario.hpp"

namespace rockfall::engine::test {

// No friction anywhere, so the sphere slides without spin and the wall's friction is idle;
// `restitution` is both the wall's and the rock's. The run ends 0.2 s after the sphere would
// reach the wall.
inline Scenario wall_scenario(const WallContact& contact, double restitution, double size,
                              double speed, double density) {
    constexpr double gap = 0.8;  // m
    Scenario scenario;
    scenario.name = "wall hit";
    scenario.slope.segments = {{4.0, 0.0}};
    scenario.slope.bars.enabled = false;
    scenario.slope.bars.segments.clear();
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.distance_from_toe = 3.0;
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

}  // namespace rockfall::engine::test
