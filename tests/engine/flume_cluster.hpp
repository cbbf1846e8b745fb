#pragma once
// Seed 001's flume at 45 deg with the wall 0.5 m past the toe and a cluster of blocky rocks of
// C2's grading in the default release box at the top: the cluster tests' scenario.

#include "engine/simulation.hpp"
#include "shapes/grading.hpp"

namespace rockfall::engine::test {

inline Scenario flume_cluster(int count) {
    Scenario scenario;
    scenario.slope.segments = {{1.82, 45.0}, {1.82, 0.0}};
    scenario.slope.width = 0.6;
    scenario.slope.thickness = 0.1;
    scenario.slope.bars.enabled = false;
    scenario.slope.bars.segments.clear();
    scenario.slope.side_walls.height = 0.3;
    scenario.slope.side_walls.thickness = 0.01;
    scenario.slope.wall.distance_from_toe = 0.5;
    scenario.slope.wall.height = 0.3;
    scenario.slope.wall.thickness = 0.2;
    const Material rock_material{0.4, 0.3, 0.02};
    scenario.materials.slope = rock_material;
    scenario.stations = {0.0};
    scenario.rocks.clear();
    Cluster cluster;
    cluster.grading = shapes::seed001_c2();
    cluster.grading.count = count;
    cluster.rock.kind = shapes::RockKind::massive;
    cluster.rock.density = 2620.0;
    cluster.rock.material = rock_material;
    scenario.cluster = cluster;
    scenario.numerics.max_time = 10.0;
    return scenario;
}

}  // namespace rockfall::engine::test
