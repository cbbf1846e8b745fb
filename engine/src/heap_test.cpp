// The funnel (heap) test's physics (see engine/heap_test.hpp): fill, lift, settle.

#include "engine/heap_test.hpp"

#include "cluster_release.hpp"
#include "recorders.hpp"
#include "world.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <numbers>

namespace rockfall::engine {
namespace {

// The packing column's height, m: high enough for any fill the funnel can hold as bounding
// spheres of the angular rocks (a tetrahedron's is 8 times its volume).
constexpr double kPackingHeight = 50.0;
// The rim must clear the highest rock by this before the funnel leaves the world, m.
constexpr double kRimClearance = 1e-3;

// The engine scenario the world is built from: one horizontal segment of the surface
// material, centred on the funnel's axis at x = floor_size / 2, y = 0, with the sheet as a
// lining; no bars, side walls or wall.
Scenario world_scenario(const HeapScenario& heap) {
    Scenario scenario;
    scenario.name = "heap test";
    scenario.slope.segments = {{heap.floor_size, 0.0}};
    scenario.slope.width = heap.floor_size;
    scenario.slope.bars.enabled = false;
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.enabled = false;
    if (heap.sheet) {
        shapes::Lining lining;
        lining.sheet = *heap.sheet;
        lining.sheet->segments = {0};
        scenario.slope.lining = std::make_shared<const shapes::Lining>(lining);
    }
    scenario.materials.slope = heap.surface;
    scenario.rocks.clear();
    scenario.stations = {};
    scenario.numerics.time_step = heap.time_step;
    scenario.numerics.solver_iterations = heap.solver_iterations;
    scenario.numerics.contact_slop = heap.contact_slop;
    scenario.gravity = heap.gravity;
    Cluster cluster;
    cluster.grading = heap.grading;
    cluster.rock = heap.rock;
    cluster.sphericity = heap.sphericity;
    // The square inscribed in the funnel's circle, standing on the surface (or the sheet).
    const double side = heap.funnel.inner_diameter / std::numbers::sqrt2;
    cluster.box.start = 0.5 * (heap.floor_size - side);
    cluster.box.length = side;
    cluster.box.width = side;
    cluster.box.height = kPackingHeight;
    cluster.box.floor = heap.sheet ? heap.sheet->thickness : 0.0;
    scenario.cluster = cluster;
    return scenario;
}

// The funnel's wall boxes in its own frame (origin on the axis at the rim, z up).
std::vector<shapes::OrientedBox> funnel_boxes(const Funnel& funnel, double height) {
    const double inner = 0.5 * funnel.inner_diameter;
    const double t = funnel.wall_thickness;
    const int n = funnel.facets;
    // Each facet's inner face is tangent to the circle; its half width reaches the outer
    // corners of its neighbours, so that no gap opens between facets.
    const double half_width = (inner + t) * std::tan(std::numbers::pi / n);
    std::vector<shapes::OrientedBox> boxes;
    for (int k = 0; k < n; ++k) {
        const double phi = 2.0 * std::numbers::pi * k / n;
        shapes::OrientedBox box;
        box.rotation = Eigen::AngleAxisd(phi, Vec3::UnitZ()).toRotationMatrix();
        box.center = Vec3((inner + 0.5 * t) * std::cos(phi), (inner + 0.5 * t) * std::sin(phi),
                          0.5 * height);
        box.half_extents = Vec3(0.5 * t, half_width, 0.5 * height);
        box.role = shapes::SurfaceRole::side_wall;
        boxes.push_back(box);
    }
    return boxes;
}

bool finite(const BodyState& s) {
    return s.position.allFinite() && s.velocity.allFinite() && s.angular_velocity.allFinite();
}

// One heap test, phase by phase.
class HeapRun {
  public:
    HeapRun(const HeapScenario& heap, std::uint64_t seed, const HeapStepSink& sink)
        : heap_(heap),
          scenario_(world_scenario(heap)),
          slope_(scenario_.slope),
          world_(scenario_, slope_),
          sink_(sink) {
        world_.set_collision_threads(heap.collision_threads);
        outcome_.axis_x = 0.5 * heap.floor_size;
        outcome_.surface_z = heap.sheet ? heap.sheet->thickness : 0.0;
        std::vector<PlacedRock> placed = cluster_rocks(slope_, *scenario_.cluster, seed);
        double top = outcome_.surface_z;
        for (PlacedRock& rock : placed) {
            bodies_.push_back(world_.add_rock(rock.geometry, rock.spec.rock, rock.initial));
            top = std::max(top, rock.initial.position.z() + rock.geometry.bounding_radius);
            outcome_.rocks.push_back(std::move(rock.geometry));
        }
        const std::size_t n = bodies_.size();
        outcome_.final_states.resize(n);
        outcome_.on_floor.assign(n, true);
        rim_z_ = outcome_.surface_z + heap.funnel.rim_gap;
        const double tube = std::max(heap.funnel.height, top - rim_z_ + 0.05);
        funnel_ = world_.add_kinematic_boxes(funnel_boxes(heap.funnel, tube), heap.funnel.material,
                                             Vec3(outcome_.axis_x, 0.0, rim_z_));
    }

    HeapOutcome execute() {
        // Phase 1: the packed rocks fall into the funnel and settle there (a fill still
        // moving at max_fill_time is lifted all the same, and reported so).
        outcome_.fill_at_rest = settle(outcome_.fill_time, heap_.max_fill_time, heap_.time_step);
        if (!outcome_.fill_at_rest && failed()) return finish();
        double fill_top = outcome_.surface_z;
        for (std::size_t i = 0; i < bodies_.size(); ++i) fill_top = std::max(fill_top, top_of(i));
        outcome_.fill_height = fill_top - outcome_.surface_z;
        if (outcome_.fill_height > heap_.funnel.height) {
            outcome_.status = HeapStatus::overflow;
            return finish();
        }
        // Phase 2: the lift, until the rim clears every rock still inside its circle.
        const double dt = effective_lift_step(heap_);
        world_.set_solver_iterations(effective_lift_iterations(heap_));
        while (true) {
            const double rise = heap_.funnel.lift_speed * (outcome_.lift_time + dt);
            world_.move_kinematic(funnel_, Vec3(outcome_.axis_x, 0.0, rim_z_ + rise));
            if (!step(dt)) return finish();
            outcome_.lift_time += dt;
            if (rim_z_ + rise > highest_inside() + kRimClearance) break;
        }
        world_.remove_kinematic(funnel_);
        // Phase 3: the heap settles.
        if (!settle(outcome_.settle_time, heap_.max_settle_time, dt) && !failed())
            outcome_.status = HeapStatus::time_limit;
        return finish();
    }

  private:
    bool failed() const { return outcome_.status == HeapStatus::numerical_failure; }

    // The top of rock i, m.
    double top_of(std::size_t i) const {
        return rock_top(outcome_.rocks[i],
                        rock_state(world_.state(bodies_[i]), 0.0, 0.0, Vec3::Zero()));
    }

    // The highest top of the rocks that reach into the funnel's circle, m.
    double highest_inside() const {
        const double radius = 0.5 * heap_.funnel.inner_diameter + heap_.funnel.wall_thickness;
        double top = -std::numeric_limits<double>::infinity();
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            if (!outcome_.on_floor[i]) continue;
            const Vec3 p = world_.state(bodies_[i]).position;
            const double r = std::hypot(p.x() - outcome_.axis_x, p.y() - outcome_.axis_y);
            if (r - outcome_.rocks[i].bounding_radius < radius) top = std::max(top, top_of(i));
        }
        return top;
    }

    // One step of dt (s), then the rocks that left the surface are taken out. False on a
    // failure.
    bool step(double dt) {
        world_.step(dt);
        time_ += dt;
        ++outcome_.steps;
        const double half = 0.5 * heap_.floor_size;
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            if (!outcome_.on_floor[i]) continue;
            ++outcome_.body_steps;
            const BodyState s = world_.state(bodies_[i]);
            if (!finite(s)) {
                outcome_.status = HeapStatus::numerical_failure;
                return false;
            }
            if (std::abs(s.position.x() - outcome_.axis_x) > half ||
                std::abs(s.position.y()) > half || s.position.z() < -half) {
                outcome_.on_floor[i] = false;
                ++outcome_.rolled_off;
                outcome_.final_states[i] = state_of(i);
                world_.remove_rock(bodies_[i]);
            }
        }
        if (sink_) sink_(time_);
        return true;
    }

    // Steps of dt (s) until every rock on the surface has been slower than rest_speed for
    // rest_duration (true), or `limit` (s) or a failure (false); `elapsed` gets the time.
    bool settle(double& elapsed, double limit, double dt) {
        double quiet = 0.0;
        elapsed = 0.0;
        while (quiet < heap_.rest_duration) {
            if (elapsed >= limit || !step(dt)) return false;
            elapsed += dt;
            // The mass-weighted root mean square speed, sqrt(2 E_translation / M): single
            // rocks of a pile tip or shift now and then long after the bulk is still.
            double energy = 0.0, mass = 0.0;
            for (std::size_t i = 0; i < bodies_.size(); ++i) {
                if (!outcome_.on_floor[i]) continue;
                const double m = world_.mass(bodies_[i]);
                energy += m * world_.state(bodies_[i]).velocity.squaredNorm();
                mass += m;
            }
            const double rms = mass > 0.0 ? std::sqrt(energy / mass) : 0.0;
            quiet = rms < heap_.rest_speed ? quiet + dt : 0.0;
        }
        return true;
    }

    RockState state_of(std::size_t i) const {
        return rock_state(world_.state(bodies_[i]), time_, world_.mass(bodies_[i]),
                          world_.inertia(bodies_[i]));
    }

    HeapOutcome finish() {
        for (std::size_t i = 0; i < bodies_.size(); ++i) {
            if (outcome_.on_floor[i]) outcome_.final_states[i] = state_of(i);
        }
        return std::move(outcome_);
    }

    const HeapScenario& heap_;
    const Scenario scenario_;
    const shapes::Slope slope_;
    World world_;
    const HeapStepSink& sink_;
    std::vector<int> bodies_;
    int funnel_ = -1;
    double rim_z_ = 0.0;
    double time_ = 0.0;
    HeapOutcome outcome_;
};

}  // namespace

const char* to_string(HeapStatus status) {
    switch (status) {
        case HeapStatus::at_rest:
            return "at_rest";
        case HeapStatus::time_limit:
            return "time_limit";
        case HeapStatus::overflow:
            return "overflow";
        case HeapStatus::numerical_failure:
            break;
    }
    return "numerical_failure";
}

double effective_lift_step(const HeapScenario& heap) {
    return heap.lift_time_step > 0.0 ? heap.lift_time_step : heap.time_step;
}

int effective_lift_iterations(const HeapScenario& heap) {
    return heap.lift_solver_iterations > 0 ? heap.lift_solver_iterations : heap.solver_iterations;
}

bool lift_step_allowed(double lift_time_step) {
    return lift_time_step == 0.0 || (lift_time_step >= 1e-5 && lift_time_step <= 1e-2);
}

double rock_top(const shapes::RockGeometry& geometry, const RockState& state) {
    if (geometry.radius > 0.0) return state.position.z() + geometry.radius;
    const Eigen::Matrix3d rotation = state.orientation.toRotationMatrix();
    double top = -std::numeric_limits<double>::infinity();
    for (const Vec3& v : geometry.hull.vertices) top = std::max(top, (rotation * v).z());
    return state.position.z() + top;
}

HeapOutcome simulate_heap(const HeapScenario& scenario, std::uint64_t seed,
                          const HeapStepSink& step) {
    HeapRun run(scenario, seed, step);
    return run.execute();
}

}  // namespace rockfall::engine
