#include "risk/drop_test.hpp"

#include "validation.hpp"

#include "engine/simulation.hpp"
#include "risk/parallel.hpp"
#include "risk/random_release.hpp"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

using engine::RockState;
using engine::Vec3;

// Extent of the drop surface, m: long and wide enough that no bounce leaves it.
constexpr double kSurfaceLength = 20.0;
constexpr double kSurfaceWidth = 20.0;
// A step is a contact step when the velocity change differs from free fall by more than this,
// m/s: far above round-off (1e-15 of a few m/s), far below any contact impulse per unit mass.
constexpr double kContactTolerance = 1e-9;

// Whether the step from a to b is not free fall (a contact pushed or rubbed the rock).
bool contact_step(const RockState& a, const RockState& b, double gravity) {
    const double dt = b.time - a.time;
    const Vec3 free = a.velocity - Vec3(0.0, 0.0, gravity * dt);
    return (b.velocity - free).norm() > kContactTolerance;
}

// Height of the rock's lowest point above its centre of mass in `state`, m (negative).
double lowest_offset(const shapes::RockGeometry& geometry, const RockState& state) {
    if (geometry.radius > 0.0) return -geometry.radius;
    const Eigen::Matrix3d rotation = state.orientation.toRotationMatrix();
    double lowest = std::numeric_limits<double>::infinity();
    for (const Vec3& v : geometry.hull.vertices) lowest = std::min(lowest, (rotation * v).z());
    return lowest;
}

// "FIELD = VALUE: must be in [LOWER, UPPER]" (open bounds with parentheses) for a pure number.
void require_number(const char* field, double value, double lower, double upper, bool open) {
    if (std::isfinite(value) &&
        (open ? value > lower && value < upper : value >= lower && value <= upper))
        return;
    std::ostringstream message;
    message << field << " = " << value << ": must be in " << (open ? '(' : '[') << lower << ", "
            << upper << (open ? ')' : ']');
    throw std::invalid_argument(message.str());
}

double kinetic_energy(const RockState& s) { return s.translational_energy + s.rotational_energy; }

// The compression part of a first contact's normal impulse `impulse` (N s, vector), from the
// states before and after it and the velocity at first touch.
double compression_impulse(const RockState& before, const RockState& free, const Vec3& v_touch,
                           const Vec3& impulse, const shapes::RockGeometry& geometry,
                           double density, double surface_z) {
    // Compression ends when the normal velocity of the impulse's point of action r is zero.
    // The contact's linear and angular momentum changes give r: dL = r x J fixes r across J,
    // the surface plane (r_z = surface - centre of mass) along it; with several touching
    // points r is their impulse-weighted centre. With the impulse growing along its final
    // direction d (per unit normal impulse), that velocity is linear in the normal impulse P:
    // u(P) = u0 + K P, K = n . (d / m + (I^-1 (r x d)) x r), so P_c = -u0 / K (m v_in for a
    // sphere).
    if (!(impulse.z() > 0.0)) return 0.0;
    const double mass = density * geometry.properties.volume;
    const Vec3 principal = density * geometry.properties.principal_moments;
    const auto inertia = [&principal](const RockState& s) -> Eigen::Matrix3d {
        const Eigen::Matrix3d rotation = s.orientation.toRotationMatrix();
        return rotation * principal.asDiagonal() * rotation.transpose();
    };
    const Vec3 d_angular =
        inertia(free) * free.angular_velocity - inertia(before) * before.angular_velocity;
    const Vec3 across = impulse.cross(d_angular) / impulse.squaredNorm();
    const double r_z = surface_z - before.position.z();
    const Vec3 r = across + ((r_z - across.z()) / impulse.z()) * impulse;
    const Vec3 d = impulse / impulse.z();
    const Eigen::Matrix3d inverse_inertia = inertia(before).inverse();
    const double k_normal = d.z() / mass + (inverse_inertia * r.cross(d)).cross(r).z();
    const double u0 = (v_touch + before.angular_velocity.cross(r)).z();
    return k_normal > 0.0 ? std::clamp(-u0 / k_normal, 0.0, impulse.z()) : 0.0;
}

}  // namespace

void check_drop_spec(const DropTestSpec& spec) {
    detail::require_positive("height", spec.height, "m");
    detail::require(spec.count >= 1,
                    "count = " + std::to_string(spec.count) + " drops: must be >= 1");
    require_number("surface.friction", spec.surface.friction, 0.0, 2.0, false);
    require_number("surface.restitution", spec.surface.restitution, 0.0, 1.0, false);
    require_number("surface.rolling_resistance", spec.surface.rolling_resistance, 0.0, 1.0, false);
    detail::require_range("time_step", spec.time_step, "s", 1e-5, 1e-2, false, false);
    detail::require_positive("gravity", spec.gravity, "m/s2");
}

std::uint64_t drop_seed(std::uint64_t seed, std::int64_t index) {
    return splitmix64(splitmix64(seed) + static_cast<std::uint64_t>(index));
}

engine::Scenario drop_scenario(const DropTestSpec& spec) {
    engine::Scenario scenario;
    scenario.name = "drop test";
    scenario.slope.segments = {{kSurfaceLength, 0.0}};
    scenario.slope.width = kSurfaceWidth;
    scenario.slope.bars.enabled = false;
    scenario.slope.side_walls.enabled = false;
    scenario.slope.wall.enabled = false;
    scenario.materials.slope = spec.surface;
    engine::RockRelease release;
    release.rock = spec.rock;
    release.release.distance = 0.5 * kSurfaceLength;
    release.release.height = spec.height;
    release.release.random_orientation = true;
    scenario.rocks = {release};
    scenario.stations = {};
    scenario.numerics.time_step = spec.time_step;
    // The fall, a rebound at most as high (restitution <= 1), and time for a tumbling contact.
    scenario.numerics.max_time = 2.0 * std::sqrt(2.0 * spec.height / spec.gravity) + 0.5;
    scenario.gravity = spec.gravity;
    return scenario;
}

DropMeasurement measure_drop(const std::vector<RockState>& states,
                             const shapes::RockGeometry& geometry, double density, double surface_z,
                             double gravity) {
    DropMeasurement m;
    m.mass = density * geometry.properties.volume;
    const std::size_t n = states.size();
    std::size_t touch = 0;
    while (touch + 1 < n && !contact_step(states[touch], states[touch + 1], gravity)) ++touch;
    if (touch + 1 >= n) throw std::runtime_error("the rock never touched the surface");

    // First touch: the free-fall parabola through the last free state back (or on) to the gap
    // zero, so the approach is the speed at the surface, not a step before or after it.
    const RockState& before = states[touch];
    const double gap = before.position.z() + lowest_offset(geometry, before) - surface_z;
    const double vz2 = before.velocity.z() * before.velocity.z() + 2.0 * gravity * gap;
    const double vz_touch = vz2 > 0.0 ? -std::sqrt(vz2) : before.velocity.z();
    const Vec3 v_touch(before.velocity.x(), before.velocity.y(), vz_touch);
    const double z_touch = before.position.z() - gap;
    m.drop_height = states.front().position.z() - z_touch;
    m.approach_speed = -vz_touch;
    m.energy_before = 0.5 * m.mass * v_touch.squaredNorm() + before.rotational_energy;

    // The bounce lasts until the first apex in free flight; every contact before it is part
    // of it (a block that lands on a corner and then on another bounces once).
    std::size_t last_contact = touch;
    std::size_t apex = 0;
    for (std::size_t k = touch + 1; k + 1 < n; ++k) {
        if (contact_step(states[k], states[k + 1], gravity)) {
            last_contact = k;
            continue;
        }
        if (states[k].velocity.z() > 0.0 && states[k + 1].velocity.z() <= 0.0) {
            apex = states[k + 1].position.z() > states[k].position.z() ? k + 1 : k;
            break;
        }
    }
    const RockState& after = apex > 0 ? states[last_contact + 1] : states.back();
    m.rebounded = apex > 0;
    m.energy_after = kinetic_energy(after);
    // The rigid contact is instantaneous: the impulse is the momentum change, without the
    // weight's m g dt over the steps the contact was held.
    m.normal_impulse = m.mass * (after.velocity.z() - vz_touch);

    // The first contact alone (Eq. 6 is about one impact): until the first free step.
    std::size_t first_free = touch + 1;
    while (first_free + 1 < n && contact_step(states[first_free], states[first_free + 1], gravity))
        ++first_free;
    const Vec3 impulse = m.mass * (states[first_free].velocity - v_touch);
    m.first_impulse = impulse.z();
    m.compression_impulse = compression_impulse(before, states[first_free], v_touch, impulse,
                                                geometry, density, surface_z);
    m.restitution_impulse = m.first_impulse - m.compression_impulse;
    if (!m.rebounded) return m;
    m.rebound_speed = std::max(0.0, after.velocity.z());
    m.rebound_height = std::max(0.0, states[apex].position.z() - z_touch);
    m.cor_height = std::sqrt(m.rebound_height / m.drop_height);
    m.cor_speed = m.rebound_speed / m.approach_speed;
    m.cor_energy = std::sqrt(m.energy_after / m.energy_before);
    m.cor_kinetic =
        m.compression_impulse > 0.0 ? m.restitution_impulse / m.compression_impulse : 0.0;
    return m;
}

DropMeasurement run_drop(const DropTestSpec& spec, std::int64_t index) {
    const engine::Scenario scenario = drop_scenario(spec);
    const shapes::RockGeometry geometry = spec.rock.geometry();
    std::vector<RockState> states;
    engine::RunOptions options;
    // Every step: the engine samples at the first step at or after each multiple.
    options.trajectory_interval = 0.25 * spec.time_step;
    options.trajectory = [&states](int, const RockState& state) { states.push_back(state); };
    const std::uint64_t seed = drop_seed(spec.seed, index);
    const engine::Outcome outcome = engine::simulate(scenario, seed, options);
    if (outcome.rocks.front().stop == engine::StopReason::numerical_failure) {
        throw std::runtime_error("drop " + std::to_string(index) + " (seed " +
                                 std::to_string(seed) + "): numerical failure in the engine");
    }
    // The release puts the lowest point `height` above the surface.
    const RockState& first = states.front();
    const double surface_z = first.position.z() + lowest_offset(geometry, first) - spec.height;
    DropMeasurement m = measure_drop(states, geometry, spec.rock.density, surface_z, spec.gravity);
    m.index = index;
    m.seed = seed;
    return m;
}

namespace {

DropTestResult summarize(std::vector<DropMeasurement> drops) {
    DropTestResult r;
    r.drops = std::move(drops);
    std::vector<double> h, s, k, e, vin, vout, hr, j;
    for (const DropMeasurement& m : r.drops) {
        r.no_rebound += m.rebounded ? 0 : 1;
        h.push_back(m.cor_height);
        s.push_back(m.cor_speed);
        k.push_back(m.cor_kinetic);
        e.push_back(m.cor_energy);
        vin.push_back(m.approach_speed);
        vout.push_back(m.rebound_speed);
        hr.push_back(m.rebound_height);
        j.push_back(m.normal_impulse);
    }
    r.cor_height = sample_summary(h);
    r.cor_speed = sample_summary(s);
    r.cor_kinetic = sample_summary(k);
    r.cor_energy = sample_summary(e);
    r.approach_speed = sample_summary(vin);
    r.rebound_speed = sample_summary(vout);
    r.rebound_height = sample_summary(hr);
    r.normal_impulse = sample_summary(j);
    return r;
}

// Drops of several surface restitutions at once (one pool for all), each a full test.
std::vector<DropTestResult> run_tests(const DropTestSpec& spec, const std::vector<double>& values,
                                      int threads, std::int64_t done_before, std::int64_t total,
                                      const DropProgress& progress) {
    std::vector<DropTestSpec> specs(values.size(), spec);
    for (std::size_t v = 0; v < values.size(); ++v) specs[v].surface.restitution = values[v];
    const auto count = static_cast<std::int64_t>(values.size()) * spec.count;
    std::vector<DropMeasurement> drops(static_cast<std::size_t>(count));
    run_parallel(
        count, threads,
        [&](std::int64_t i) {
            drops[static_cast<std::size_t>(i)] =
                run_drop(specs[static_cast<std::size_t>(i / spec.count)], i % spec.count);
        },
        done_before, total, progress);
    std::vector<DropTestResult> results;
    for (std::size_t v = 0; v < values.size(); ++v) {
        const auto first = drops.begin() + static_cast<std::ptrdiff_t>(v) * spec.count;
        results.push_back(summarize({first, first + spec.count}));
    }
    return results;
}

}  // namespace

DropTestResult run_drop_test(const DropTestSpec& spec, int threads, const DropProgress& progress) {
    check_drop_spec(spec);
    return std::move(
        run_tests(spec, {spec.surface.restitution}, threads, 0, spec.count, progress).front());
}

RestitutionIdentification identify_surface_restitution(const DropTestSpec& spec, double target,
                                                       const RestitutionSearchOptions& options,
                                                       const DropProgress& progress) {
    check_drop_spec(spec);
    require_number("target_cor", target, 0.0, 1.0, true);
    detail::require(options.curve_points >= 2,
                    "curve points = " + std::to_string(options.curve_points) + ": must be >= 2");
    detail::require_positive("tolerance", options.tolerance, "");
    const auto matched = [&](const DropTestResult& r) {
        return options.definition == CorDefinition::height ? r.cor_height : r.cor_speed;
    };
    const auto point = [&](const SearchPoint& p) {
        return CurvePoint{p.parameter, 0.5 * (p.parameter + spec.rock.material.restitution),
                          p.value};
    };
    std::vector<double> values;
    for (int i = 0; i < options.curve_points; ++i) {
        values.push_back(static_cast<double>(i) / (options.curve_points - 1));
    }
    const std::int64_t total = spec.count * (options.curve_points + options.max_iterations);
    std::int64_t done = 0;
    const SearchEvaluator evaluate = [&](const std::vector<double>& restitutions) {
        const std::vector<DropTestResult> results =
            run_tests(spec, restitutions, options.threads, done, total, progress);
        done += spec.count * static_cast<std::int64_t>(restitutions.size());
        std::vector<SampleSummary> out;
        for (const DropTestResult& r : results) out.push_back(matched(r));
        return out;
    };
    const UnreachableTarget unreachable = [&](double lo, double hi,
                                              const std::vector<SearchPoint>& curve) {
        std::ostringstream message;
        message << "target_cor = " << target << ": must be in [" << lo << ", " << hi
                << "], the mean COR over surface restitution 0 to 1 for this rock (its own "
                   "restitution "
                << spec.rock.material.restitution
                << " enters the contact's mean; surface restitution: mean COR: "
                << curve_text(curve) << ")";
        throw std::invalid_argument(message.str());
    };
    const ParameterSearch search = search_parameter(
        values, target, {options.tolerance, options.max_iterations}, evaluate, unreachable);
    if (progress) progress(done, done);
    RestitutionIdentification id;
    id.target = target;
    const CurvePoint best = point(search.best);
    id.surface_restitution = best.surface_restitution;
    id.contact_restitution = best.contact_restitution;
    id.achieved = best.cor;
    id.consistent = search.consistent;
    for (const SearchPoint& p : search.curve) id.curve.push_back(point(p));
    for (const SearchPoint& p : search.refinements) id.refinements.push_back(point(p));
    return id;
}

}  // namespace rockfall::risk
