#include "risk/heap_test.hpp"

#include "validation.hpp"

#include "risk/parallel.hpp"
#include "risk/random_release.hpp"
#include "shapes/grading.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

using engine::Vec3;

constexpr double kDegree = std::numbers::pi / 180.0;

void require_count(const char* field, std::int64_t value, std::int64_t lower, std::int64_t upper,
                   const char* unit) {
    if (value >= lower && value <= upper) return;
    std::ostringstream message;
    message << field << " = " << value << (unit[0] != '\0' ? " " : "") << unit << ": must be in ["
            << lower << ", " << upper << ']';
    throw std::invalid_argument(message.str());
}

void check_material(const std::string& field, const engine::Material& m) {
    detail::require_range((field + ".friction").c_str(), m.friction, "", 0.0, 2.0, false, false);
    detail::require_range((field + ".restitution").c_str(), m.restitution, "", 0.0, 1.0, false,
                          false);
    detail::require_range((field + ".rolling_resistance").c_str(), m.rolling_resistance, "", 0.0,
                          1.0, false, false);
}

double bin_width_of(const HeapTestSpec& spec) {
    return spec.method.bin_width > 0.0 ? spec.method.bin_width : 0.5 * spec.heap.grading.d50;
}

}  // namespace

void check_heap_spec(const HeapTestSpec& spec) {
    const engine::HeapScenario& h = spec.heap;
    const engine::Funnel& f = h.funnel;
    shapes::grading_model(h.grading);
    if (h.sphericity != 0.0)
        detail::require_range("sphericity", h.sphericity, "", 0.5, 0.95, false, false);
    detail::require_range("funnel.inner_diameter", f.inner_diameter, "m", 0.02, 2.0, false, false);
    detail::require_range("funnel.height", f.height, "m", 0.05, 5.0, false, false);
    detail::require_range("funnel.wall_thickness", f.wall_thickness, "m", 1e-3, 0.05, false, false);
    require_count("funnel.facets", f.facets, 12, 256, "boxes");
    detail::require_range("funnel.lift_speed", f.lift_speed, "m/s", 1e-4, 1.0, false, false);
    detail::require_range("funnel.rim_gap", f.rim_gap, "m", 0.0, 0.01, false, false);
    // Rocks must pass under the rim only once it is lifted, and fit across the funnel.
    detail::require_range("grading.d_max", h.grading.d_max, "m", 2.0 * f.rim_gap,
                          0.5 * f.inner_diameter, true, false);
    check_material("funnel.material", f.material);
    check_material("surface", h.surface);
    check_material("rock.material", h.rock.material);
    detail::require_range("floor_size", h.floor_size, "m", 4.0 * f.inner_diameter, 20.0, false,
                          false);
    detail::require_range("time_step", h.time_step, "s", 1e-5, 1e-2, false, false);
    if (!engine::lift_step_allowed(h.lift_time_step)) {
        std::ostringstream message;
        message << "lift_time_step = " << h.lift_time_step
                << " s: must be 0 (the fill's time_step) or in [1e-05, 0.01]";
        throw std::invalid_argument(message.str());
    }
    detail::require_positive("rest_speed", h.rest_speed, "m/s");
    detail::require_positive("rest_duration", h.rest_duration, "s");
    detail::require_positive("max_fill_time", h.max_fill_time, "s");
    detail::require_positive("max_settle_time", h.max_settle_time, "s");
    require_count("solver_iterations", h.solver_iterations, 1, 100, "");
    require_count("lift_solver_iterations", h.lift_solver_iterations, 0, 100, "");
    detail::require_range("contact_slop", h.contact_slop, "g dt^2", 0.0, 100.0, false, false);
    require_count("collision_threads", h.collision_threads, 1, 1024, "");
    detail::require_positive("gravity", h.gravity, "m/s2");
    require_count("count", spec.count, 1, 1'000'000, "heaps");
    require_count("method.planes", spec.method.planes, 1, 360, "");
    require_count("method.samples_per_bin", spec.method.samples_per_bin, 1, 100, "");
    detail::require_at_least("method.bin_width", spec.method.bin_width, "m", 0.0);
    detail::require_range("method.low_fraction", spec.method.low_fraction, "", 0.0, 1.0, false,
                          true);
    detail::require_range("method.high_fraction", spec.method.high_fraction, "",
                          spec.method.low_fraction, 1.0, true, false);
}

std::uint64_t heap_seed(std::uint64_t seed, std::int64_t index) {
    return splitmix64(splitmix64(seed) + static_cast<std::uint64_t>(index));
}

HeapSurface::HeapSurface(const engine::HeapOutcome& heap) : surface_z_(heap.surface_z) {
    for (std::size_t i = 0; i < heap.rocks.size(); ++i) {
        if (!heap.on_floor[i]) continue;
        const shapes::RockGeometry& g = heap.rocks[i];
        const engine::RockState& s = heap.final_states[i];
        Rock& rock = rocks_.emplace_back();
        rock.center = s.position;
        rock.reach = g.bounding_radius;
        rock.radius = g.radius;
        if (g.radius > 0.0) continue;
        const Eigen::Matrix3d rotation = s.orientation.toRotationMatrix();
        for (const auto& t : g.hull.triangles) {
            const Vec3 a = rotation * g.hull.vertices[static_cast<std::size_t>(t[0])];
            const Vec3 b = rotation * g.hull.vertices[static_cast<std::size_t>(t[1])];
            const Vec3 c = rotation * g.hull.vertices[static_cast<std::size_t>(t[2])];
            const Vec3 n = (b - a).cross(c - a);
            if (!(n.norm() > 0.0)) continue;
            const Vec3 u = n.normalized();
            // Relative to the centre of mass: n . (p - centre) <= d.
            rock.planes.emplace_back(u.x(), u.y(), u.z(), u.dot(a));
        }
    }
}

double HeapSurface::height(double x, double y) const {
    double top = surface_z_;
    for (const Rock& rock : rocks_) {
        const double dx = x - rock.center.x();
        const double dy = y - rock.center.y();
        const double d2 = dx * dx + dy * dy;
        if (d2 >= rock.reach * rock.reach || rock.center.z() + rock.reach <= top) continue;
        if (rock.radius > 0.0) {
            top = std::max(top, rock.center.z() + std::sqrt(rock.radius * rock.radius - d2));
            continue;
        }
        // The vertical line (dx, dy, t) clipped by every face plane: n . p <= d.
        double lower = -std::numeric_limits<double>::infinity();
        double upper = std::numeric_limits<double>::infinity();
        for (const Eigen::Vector4d& p : rock.planes) {
            const double rest = p.w() - p.x() * dx - p.y() * dy;
            if (p.z() > 1e-12) {
                upper = std::min(upper, rest / p.z());
            } else if (p.z() < -1e-12) {
                lower = std::max(lower, rest / p.z());
            } else if (rest < 0.0) {
                upper = -std::numeric_limits<double>::infinity();
            }
            if (upper < lower) break;
        }
        if (upper >= lower) top = std::max(top, rock.center.z() + upper);
    }
    return top - surface_z_;
}

HeapProfile heap_profile(const HeapSurface& surface, double axis_x, double axis_y,
                         double max_radius, double azimuth_deg, double bin_width,
                         const AngleMethod& method) {
    HeapProfile profile;
    profile.azimuth_deg = azimuth_deg;
    const double cx = std::cos(azimuth_deg * kDegree);
    const double cy = std::sin(azimuth_deg * kDegree);
    const int bins = std::max(1, static_cast<int>(max_radius / bin_width));
    const int samples = method.samples_per_bin;
    for (int b = 0; b < bins; ++b) {
        double h = 0.0;
        for (int k = 0; k < samples; ++k) {
            const double r = (b + (k + 0.5) / samples) * bin_width;
            h = std::max(h, surface.height(axis_x + r * cx, axis_y + r * cy));
        }
        profile.radius.push_back((b + 0.5) * bin_width);
        profile.height.push_back(h);
    }
    const auto summit = std::max_element(profile.height.begin(), profile.height.end());
    profile.heap_height = *summit;
    const double low = method.low_fraction * profile.heap_height;
    const double high = method.high_fraction * profile.heap_height;
    std::vector<double> x, y;
    std::size_t j = static_cast<std::size_t>(summit - profile.height.begin());
    for (; j < profile.height.size() && profile.height[j] >= low; ++j) {
        if (profile.height[j] <= high) {
            x.push_back(profile.radius[j]);
            y.push_back(profile.height[j]);
        }
    }
    profile.foot_radius = j < profile.radius.size() ? profile.radius[j] : max_radius;
    profile.fitted_points = static_cast<int>(x.size());
    profile.valid = profile.heap_height > 0.0 && x.size() >= 3;
    if (profile.valid) profile.angle_deg = std::atan(-fit_line(x, y).slope) / kDegree;
    return profile;
}

HeapMeasurement measure_heap(const engine::HeapOutcome& heap, double bin_width,
                             const AngleMethod& method) {
    HeapMeasurement m;
    m.status = heap.status;
    m.rocks = static_cast<int>(heap.rocks.size());
    m.rolled_off = heap.rolled_off;
    m.fill_height = heap.fill_height;
    m.fill_time = heap.fill_time;
    m.fill_at_rest = heap.fill_at_rest;
    m.lift_time = heap.lift_time;
    m.settle_time = heap.settle_time;
    const HeapSurface surface(heap);
    // The surface's edge nearest the axis.
    const double max_radius = heap.axis_x;
    std::vector<double> angles;
    for (int p = 0; p < method.planes; ++p) {
        const double azimuth = 360.0 * p / method.planes;
        HeapProfile& profile = m.planes.emplace_back(heap_profile(
            surface, heap.axis_x, heap.axis_y, max_radius, azimuth, bin_width, method));
        if (!profile.valid) continue;
        angles.push_back(profile.angle_deg);
        m.heap_height += profile.heap_height;
        m.foot_radius += profile.foot_radius;
    }
    m.valid_planes = static_cast<int>(angles.size());
    // No plane with a flank of 3 bins: the rocks spread as a single layer (or rolled off),
    // a heap of angle 0.
    if (angles.empty()) return m;
    m.heap_height /= m.valid_planes;
    m.foot_radius /= m.valid_planes;
    m.angle_deg = mean(angles);
    m.angle_sd_deg = angles.size() >= 2 ? standard_deviation(angles) : 0.0;
    return m;
}

HeapMeasurement run_heap(const HeapTestSpec& spec, std::int64_t index) {
    const std::uint64_t seed = heap_seed(spec.seed, index);
    const engine::HeapOutcome outcome = engine::simulate_heap(spec.heap, seed);
    const std::string which = "heap " + std::to_string(index) + " (seed " + std::to_string(seed);
    if (outcome.status == engine::HeapStatus::numerical_failure) {
        throw std::runtime_error(which + "): numerical failure in the engine");
    }
    if (outcome.status == engine::HeapStatus::overflow) {
        std::ostringstream message;
        message << which << "): the settled fill is " << outcome.fill_height
                << " m high, above the funnel's height " << spec.heap.funnel.height
                << " m: fewer or smaller rocks, or a taller funnel";
        throw std::invalid_argument(message.str());
    }
    HeapMeasurement m = measure_heap(outcome, bin_width_of(spec), spec.method);
    m.index = index;
    m.seed = seed;
    return m;
}

namespace {

HeapTestResult summarize(std::vector<HeapMeasurement> heaps) {
    HeapTestResult r;
    r.heaps = std::move(heaps);
    std::vector<double> angle, plane, height, fill;
    for (const HeapMeasurement& m : r.heaps) {
        r.not_at_rest += m.status == engine::HeapStatus::at_rest ? 0 : 1;
        r.fills_not_at_rest += m.fill_at_rest ? 0 : 1;
        angle.push_back(m.angle_deg);
        height.push_back(m.heap_height);
        fill.push_back(m.fill_height);
        for (const HeapProfile& p : m.planes) {
            if (p.valid) plane.push_back(p.angle_deg);
        }
    }
    r.angle_deg = sample_summary(angle);
    r.plane_angle_deg = sample_summary(plane.empty() ? angle : plane);
    r.heap_height = sample_summary(height);
    r.fill_height = sample_summary(fill);
    return r;
}

// Heaps at several rock frictions at once (one pool for all), each a full test.
std::vector<HeapTestResult> run_tests(const HeapTestSpec& spec, const std::vector<double>& values,
                                      int threads, std::int64_t done_before, std::int64_t total,
                                      const BatchProgress& progress) {
    const auto count = static_cast<std::int64_t>(values.size()) * spec.count;
    // Fewer heaps than threads: the spare threads share each heap's collision detection.
    const auto heaps_at_once = static_cast<int>(std::min<std::int64_t>(count, threads));
    std::vector<HeapTestSpec> specs(values.size(), spec);
    for (std::size_t v = 0; v < values.size(); ++v) {
        specs[v].heap.rock.material.friction = values[v];
        specs[v].heap.collision_threads = std::max(1, threads / std::max(1, heaps_at_once));
    }
    std::vector<HeapMeasurement> heaps(static_cast<std::size_t>(count));
    run_parallel(
        count, threads,
        [&](std::int64_t i) {
            heaps[static_cast<std::size_t>(i)] =
                run_heap(specs[static_cast<std::size_t>(i / spec.count)], i % spec.count);
        },
        done_before, total, progress);
    std::vector<HeapTestResult> results;
    for (std::size_t v = 0; v < values.size(); ++v) {
        const auto first = heaps.begin() + static_cast<std::ptrdiff_t>(v) * spec.count;
        results.push_back(summarize({first, first + spec.count}));
    }
    return results;
}

}  // namespace

HeapTestResult run_heap_test(const HeapTestSpec& spec, int threads, const BatchProgress& progress) {
    check_heap_spec(spec);
    return std::move(
        run_tests(spec, {spec.heap.rock.material.friction}, threads, 0, spec.count, progress)
            .front());
}

FrictionIdentification identify_friction(const HeapTestSpec& spec, double target_deg,
                                         const FrictionOptions& options,
                                         const BatchProgress& progress) {
    check_heap_spec(spec);
    detail::require_range("target_angle", target_deg, "deg", 0.0, 90.0, true, true);
    require_count("curve_points", options.curve_points, 2, 101, "");
    detail::require_range("friction_min", options.friction_min, "", 0.0, 2.0, false, true);
    detail::require_range("friction_max", options.friction_max, "", options.friction_min, 2.0, true,
                          false);
    std::vector<double> values;
    for (int i = 0; i < options.curve_points; ++i) {
        values.push_back(options.friction_min + (options.friction_max - options.friction_min) * i /
                                                    (options.curve_points - 1));
    }
    const std::int64_t total = spec.count * (options.curve_points + options.max_iterations);
    std::int64_t done = 0;
    // Every result, keyed by the friction it was run at, to keep the heaps with the points.
    std::vector<FrictionPoint> runs;
    const SearchEvaluator evaluate = [&](const std::vector<double>& frictions) {
        const std::vector<HeapTestResult> results =
            run_tests(spec, frictions, options.threads, done, total, progress);
        done += spec.count * static_cast<std::int64_t>(frictions.size());
        std::vector<SampleSummary> out;
        for (std::size_t i = 0; i < results.size(); ++i) {
            out.push_back(results[i].angle_deg);
            runs.push_back({frictions[i], results[i]});
        }
        return out;
    };
    const UnreachableTarget unreachable = [&](double lo, double hi,
                                              const std::vector<SearchPoint>& curve) {
        std::ostringstream message;
        message << "target_angle = " << target_deg << " deg: must be in [" << lo << ", " << hi
                << "] deg, the mean angle of repose over rock friction " << options.friction_min
                << " to " << options.friction_max
                << " for these rocks (friction: mean angle, deg: " << curve_text(curve)
                << "); widen --friction-range";
        throw std::invalid_argument(message.str());
    };
    const ParameterSearch search = search_parameter(
        values, target_deg, {options.tolerance, options.max_iterations}, evaluate, unreachable);
    if (progress) progress(done, done);
    const auto run_at = [&](double friction) {
        return *std::find_if(runs.begin(), runs.end(),
                             [&](const FrictionPoint& p) { return p.friction == friction; });
    };
    FrictionIdentification id;
    id.target_deg = target_deg;
    id.identified = run_at(search.best.parameter);
    id.consistent = search.consistent;
    for (const SearchPoint& p : search.curve) id.curve.push_back(run_at(p.parameter));
    for (const SearchPoint& p : search.refinements) id.refinements.push_back(run_at(p.parameter));
    return id;
}

}  // namespace rockfall::risk
