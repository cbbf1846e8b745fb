#pragma once
// A small funnel (heap) test for the engine's tests: `rocks` blocky rocks (massive) of 8-20 mm
// (d50 12 mm) in a 60 mm funnel on a 0.5 m floor, lifted at 50 mm/s; a few seconds of CPU.

#include "engine/heap_test.hpp"
#include "shapes/rocks.hpp"

namespace rockfall::engine::test {

inline HeapScenario small_heap(int rocks) {
    HeapScenario heap;
    heap.rock.kind = shapes::RockKind::massive;
    heap.grading.count = rocks;
    heap.grading.d50 = 0.012;
    heap.grading.d_min = 0.008;
    heap.grading.d_max = 0.020;
    heap.funnel.inner_diameter = 0.06;
    heap.funnel.lift_speed = 0.05;
    heap.floor_size = 0.5;
    return heap;
}

}  // namespace rockfall::engine::test
