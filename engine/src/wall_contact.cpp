// The compliant contact at the reaction wall: analytic and nondimensional impact solutions
// (Hertz after Johnson 1985, the clamped linear spring-dashpot after Schwager and Poeschel 2007,
// Hertz with Tsuji, Tanaka and Ishida 1992 damping), overlap geometry, force laws (the sphere's
// and the rounded polyhedron's, docs/wall_contact.md) and friction.

#include "engine/wall_contact.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <stdexcept>
#include <string>

namespace rockfall::engine {
namespace {

using std::numbers::pi;

void check_restitution(double restitution) {
    if (!(restitution >= kMinWallRestitution && restitution <= 1.0)) {
        throw std::invalid_argument(
            "wall contact: mean restitution of wall and rock = " + std::to_string(restitution) +
            ": must be in [" + std::to_string(kMinWallRestitution) +
            ", 1] (the damping that gives e = 0 is infinite)");
    }
}

// Finds x in [0, inf) with decreasing(x) = target, where decreasing(0) >= target and
// decreasing falls towards 0: doubles an upper bracket, then bisects to round-off.
template <typename Function>
double solve_decreasing(Function decreasing, double target) {
    double low = 0.0;
    double high = 1.0;
    while (decreasing(high) > target) {
        low = high;
        high *= 2.0;
        assert(high < 1e6);
    }
    for (int i = 0; i < 200 && high - low > 1e-12 * (1.0 + high); ++i) {
        const double middle = 0.5 * (low + high);
        (decreasing(middle) > target ? low : high) = middle;
    }
    return 0.5 * (low + high);
}

// --- Hertz with Tsuji damping, nondimensional: d'' = -max(0, d^1.5 + alpha d^0.25 d'),
// d(0) = 0, d'(0) = 1. Scaling d by D = (m v0^2 / k)^(2/5) and t by D / v0 removes m, k and
// v0, so the restitution depends on alpha alone (Tsuji et al. 1992, eq. 14 ff.).

struct Phase {
    double overlap = 0.0;
    double rate = 0.0;
};

// Force over d^0.25, extended to d < 0 with the sign of d: continuous through the end of the
// contact, where it changes sign whether the force vanishes at d > 0 (damped) or at d = 0.
double force_sign(const Phase& s, double alpha) {
    const double root = std::sqrt(std::sqrt(std::abs(s.overlap)));
    const double elastic = s.overlap >= 0.0 ? s.overlap * root : -std::abs(s.overlap) * root;
    return elastic + alpha * s.rate;
}

double tsuji_force(const Phase& s, double alpha) {
    if (s.overlap <= 0.0) {
        return 0.0;
    }
    const double root = std::sqrt(std::sqrt(s.overlap));
    return std::max(0.0, root * (s.overlap * root + alpha * s.rate));
}

Phase rk4_step(const Phase& s, double h, double alpha) {
    const auto derivative = [alpha](const Phase& p) {
        return Phase{p.rate, -tsuji_force(p, alpha)};
    };
    const Phase k1 = derivative(s);
    const Phase k2 = derivative({s.overlap + 0.5 * h * k1.overlap, s.rate + 0.5 * h * k1.rate});
    const Phase k3 = derivative({s.overlap + 0.5 * h * k2.overlap, s.rate + 0.5 * h * k2.rate});
    const Phase k4 = derivative({s.overlap + h * k3.overlap, s.rate + h * k3.rate});
    return {s.overlap + h / 6.0 * (k1.overlap + 2.0 * k2.overlap + 2.0 * k3.overlap + k4.overlap),
            s.rate + h / 6.0 * (k1.rate + 2.0 * k2.rate + 2.0 * k3.rate + k4.rate)};
}

// Step of the nondimensional integration: the elastic contact lasts 3.22, so about 16,000
// steps; halving it changes restitution, peak force and duration by less than 2e-6 (relative;
// first order because of d^0.25 at first touch).
constexpr double kTsujiStep = 2e-4;

}  // namespace

double effective_modulus(double e1, double nu1, double e2, double nu2) {
    assert(e1 > 0.0 && e2 > 0.0);
    // Johnson (1985), eq. 4.22.
    return 1.0 / ((1.0 - nu1 * nu1) / e1 + (1.0 - nu2 * nu2) / e2);
}

double damping_ratio_from_restitution(double restitution) {
    assert(restitution > 0.0 && restitution <= 1.0);
    const double log_e = std::log(restitution);
    return -log_e / std::sqrt(pi * pi + log_e * log_e);
}

HertzImpact hertz_impact(double effective_modulus, double radius, double mass, double speed) {
    assert(effective_modulus > 0.0 && radius > 0.0 && mass > 0.0 && speed > 0.0);
    // Johnson (1985), sec. 11.4, eqs. 11.23-11.25.
    HertzImpact impact;
    impact.max_overlap =
        std::pow(15.0 * mass * speed * speed / (16.0 * effective_modulus * std::sqrt(radius)), 0.4);
    impact.peak_force =
        4.0 / 3.0 * effective_modulus * std::sqrt(radius) * std::pow(impact.max_overlap, 1.5);
    impact.duration =
        2.868 *
        std::pow(mass * mass / (radius * effective_modulus * effective_modulus * speed), 0.2);
    return impact;
}

LinearImpact linear_impact(double damping_ratio) {
    const double b = damping_ratio;
    assert(b >= 0.0);
    // x(t) of m x'' + c x' + k x = 0, x(0) = 0, x'(0) = v0, in units of v0 / omega0; the force
    // F = x + 2 b x' (units v0 sqrt(m k)) vanishes at t_end, where the clamped contact ends.
    LinearImpact impact;
    if (b < 1.0 - 1e-9) {
        const double s = std::sqrt(1.0 - b * b);
        const auto force = [b, s](double t) {
            return std::exp(-b * t) *
                   ((1.0 - 2.0 * b * b) / s * std::sin(s * t) + 2.0 * b * std::cos(s * t));
        };
        // dF/dt = 0 where tan(s t) = (1 - 4 b^2) s / (b (3 - 4 b^2)); for b >= 1/2 F falls
        // from its first value, the jump c v0.
        if (b < 0.5) {
            impact.peak_time = std::atan2((1.0 - 4.0 * b * b) * s, b * (3.0 - 4.0 * b * b)) / s;
        }
        impact.peak_force = force(impact.peak_time);
        const double end_phase = pi - std::atan2(2.0 * b * s, 1.0 - 2.0 * b * b);
        impact.duration = end_phase / s;
        impact.restitution =
            -std::exp(-b * impact.duration) * (std::cos(end_phase) - b / s * std::sin(end_phase));
    } else if (b <= 1.0 + 1e-9) {
        // Critical damping: x = t e^-t, F = (2 - t) e^-t.
        impact.peak_force = 2.0;
        impact.duration = 2.0;
        impact.restitution = std::exp(-2.0);
    } else {
        const double q = std::sqrt(b * b - 1.0);
        const double r1 = -b + q;
        const double r2 = -b - q;
        // 1 + 2 b r1 = -1 / (b + q)^2, written without the cancellation of its direct form.
        const double a1 = -1.0 / ((b + q) * (b + q));
        const double a2 = 1.0 + 2.0 * b * r2;
        impact.peak_force = 2.0 * b;
        impact.duration = std::log(a2 / a1) / (2.0 * q);
        const double t = impact.duration;
        impact.restitution = -(r1 * std::exp(r1 * t) - r2 * std::exp(r2 * t)) / (2.0 * q);
    }
    return impact;
}

double clamped_damping_ratio(double restitution) {
    check_restitution(restitution);
    if (restitution == 1.0) {
        return 0.0;
    }
    return solve_decreasing([](double b) { return linear_impact(b).restitution; }, restitution);
}

TsujiImpact tsuji_impact(double alpha) {
    assert(alpha >= 0.0);
    TsujiImpact impact;
    impact.alpha = alpha;
    Phase s{0.0, 1.0};
    double time = 0.0;
    for (;;) {
        const Phase next = rk4_step(s, kTsujiStep, alpha);
        if (next.rate < 0.0 && force_sign(next, alpha) <= 0.0) {
            break;
        }
        s = next;
        time += kTsujiStep;
        impact.peak_force = std::max(impact.peak_force, tsuji_force(s, alpha));
        assert(time < 100.0);
    }
    // The force vanishes within the last step: bisect on the length of a partial step.
    double low = 0.0;
    double high = kTsujiStep;
    for (int i = 0; i < 60; ++i) {
        const double middle = 0.5 * (low + high);
        const Phase p = rk4_step(s, middle, alpha);
        (p.rate < 0.0 && force_sign(p, alpha) <= 0.0 ? high : low) = middle;
    }
    impact.duration = time + high;
    impact.restitution = -rk4_step(s, high, alpha).rate;
    return impact;
}

const TsujiImpact& tsuji_impact_for_restitution(double restitution) {
    check_restitution(restitution);
    static std::mutex mutex;
    static std::map<double, TsujiImpact> cache;
    const std::lock_guard<std::mutex> lock(mutex);
    if (const auto found = cache.find(restitution); found != cache.end()) {
        return found->second;
    }
    const double alpha =
        restitution == 1.0
            ? 0.0
            : solve_decreasing([](double a) { return tsuji_impact(a).restitution; }, restitution);
    return cache.emplace(restitution, tsuji_impact(alpha)).first->second;
}

std::optional<WallOverlap> wall_overlap(const shapes::OrientedBox& wall,
                                        const shapes::RockGeometry& rock, const Vec3& position,
                                        const Eigen::Quaterniond& orientation,
                                        const HullFeatures* features) {
    Vec3 normal = Vec3::Zero();
    const double centre_distance = shapes::signed_distance(wall, position, &normal);
    if (centre_distance >= rock.bounding_radius) {
        return std::nullopt;
    }
    if (rock.radius > 0.0) {
        const double depth = rock.radius - centre_distance;
        if (depth <= 0.0) {
            return std::nullopt;
        }
        return WallOverlap{depth, normal, position - rock.radius * normal, {}};
    }
    // Hull: the vertices inside the wall, aggregated into one contact so that a face lying
    // flat on the wall is as stiff as a corner (the law's radius is the rock's, not a vertex's).
    const Eigen::Matrix3d rotation = orientation.toRotationMatrix();
    WallOverlap overlap;
    Vec3 weighted_point = Vec3::Zero();
    Vec3 deepest = Vec3::Zero();
    double weight = 0.0;
    for (const Vec3& body_vertex : rock.hull.vertices) {
        const Vec3 vertex = position + rotation * body_vertex;
        Vec3 face_normal = Vec3::Zero();
        const double depth = -shapes::signed_distance(wall, vertex, &face_normal);
        if (depth <= 0.0) {
            continue;
        }
        weighted_point += depth * vertex;
        weight += depth;
        if (depth > overlap.depth) {
            overlap.depth = depth;
            overlap.normal = face_normal;
            deepest = vertex;
        }
    }
    if (weight <= 0.0) {
        return std::nullopt;
    }
    overlap.point = weighted_point / weight;
    if (features != nullptr) {
        // The plane through the deepest vertex, in the body frame: x_b . n_b < offset inside.
        const Vec3 normal_body = rotation.transpose() * overlap.normal;
        const double offset = normal_body.dot(rotation.transpose() * (deepest - position));
        overlap.hull = hull_penetration(rock.hull, *features, normal_body, offset + overlap.depth);
    }
    return overlap;
}

WallContactLaw::WallContactLaw(const WallContact& spec, const Material& wall, const Material& rock,
                               double mass, double radius)
    : spec_(spec),
      friction_(0.5 * (wall.friction + rock.friction)),
      restitution_(0.5 * (wall.restitution + rock.restitution)),
      mass_(mass),
      radius_(radius),
      effective_modulus_(effective_modulus(spec.rock_youngs_modulus, spec.rock_poisson_ratio,
                                           spec.wall_youngs_modulus, spec.wall_poisson_ratio)) {
    assert(mass > 0.0 && radius > 0.0);
    hertz_stiffness_ = 4.0 / 3.0 * effective_modulus_ * std::sqrt(radius_);
    if (spec_.model == WallContact::Model::hertz) {
        damping_ = tsuji_impact_for_restitution(restitution_).alpha;
        return;
    }
    damping_ratio_ = clamped_damping_ratio(restitution_);
    if (spec_.linear_stiffness > 0.0) {
        stiffness_ = spec_.linear_stiffness;
        damping_ = 2.0 * damping_ratio_ * std::sqrt(mass_ * stiffness_);
    }
}

WallContactLaw::WallContactLaw(const WallContact& spec, const Material& wall, const Material& rock,
                               double mass, const shapes::RockGeometry& geometry)
    : WallContactLaw(spec, wall, rock, mass,
                     geometry.radius > 0.0 ? geometry.radius : 0.5 * geometry.nominal_size) {
    if (geometry.radius > 0.0 || spec.hull_model == WallContact::HullModel::sphere) {
        return;
    }
    if (spec.model != WallContact::Model::hertz) {
        throw std::invalid_argument(
            "wall contact: hull_model = \"rounded\" needs model = \"hertz\" (its corner is a "
            "Hertz contact)");
    }
    assert(spec.corner_roundness > 0.0 && spec.corner_roundness <= 1.0);
    rounded_ = true;
    features_ = engine::hull_features(geometry.hull);
    // Wadell roundness: mean corner radius over the inscribed radius (seed 001, eq. 2).
    corner_radius_ = spec.corner_roundness * features_.inscribed_radius;
    radius_ = corner_radius_;
    hertz_stiffness_ = 4.0 / 3.0 * effective_modulus_ * std::sqrt(radius_);
    // The edge and face laws are linear in the overlap: the clamped spring-dashpot's beta.
    damping_ratio_ = clamped_damping_ratio(restitution_);
}

double WallContactLaw::tsuji_duration(double hertz_stiffness, double speed) const {
    // Time unit D / v0 = (m / k)^(2/5) v0^(-1/5) of the nondimensional Tsuji impact.
    const double time_unit = std::pow(mass_ / hertz_stiffness, 0.4) * std::pow(speed, -0.2);
    return tsuji_impact_for_restitution(restitution_).duration * time_unit;
}

double WallContactLaw::linear_duration(double stiffness) const {
    return linear_impact(damping_ratio_).duration * std::sqrt(mass_ / stiffness);
}

double WallContactLaw::hertz_equivalent_stiffness(double approach_speed) const {
    // Peak of the linear law is v0 sqrt(m k) times linear_impact(beta).peak_force; setting it
    // equal to Hertz's elastic peak gives k in closed form.
    const double hertz_peak =
        hertz_impact(effective_modulus_, radius_, mass_, approach_speed).peak_force;
    const double unit_peak = approach_speed * linear_impact(damping_ratio_).peak_force;
    return hertz_peak * hertz_peak / (unit_peak * unit_peak * mass_);
}

double WallContactLaw::contact_duration(double approach_speed) const {
    const double speed = std::max(approach_speed, kMinContactSpeed);
    if (spec_.model == WallContact::Model::hertz) {
        const double corner = tsuji_duration(hertz_stiffness_, speed);
        if (!rounded_) {
            return corner;
        }
        // The stiffest edge and face the rock has (rounded_normal_force's laws).
        const double edge = linear_duration(pi / 4.0 * effective_modulus_ * features_.longest_edge);
        const double face =
            linear_duration(2.0 * effective_modulus_ * std::sqrt(features_.largest_face_area / pi));
        return std::min({corner, edge, face});
    }
    return linear_duration(spec_.linear_stiffness > 0.0 ? spec_.linear_stiffness
                                                        : hertz_equivalent_stiffness(speed));
}

double WallContactLaw::longest_contact_duration(double approach_speed) const {
    if (!rounded_) {
        return contact_duration(approach_speed);
    }
    // The rounded law's force is never below the corner's Hertz force.
    return tsuji_duration(hertz_stiffness_, std::max(approach_speed, kMinContactSpeed));
}

void WallContactLaw::begin_contact(double approach_speed) {
    const double speed = std::max(approach_speed, kMinContactSpeed);
    if (spec_.model == WallContact::Model::linear && spec_.linear_stiffness <= 0.0) {
        stiffness_ = hertz_equivalent_stiffness(speed);
        damping_ = 2.0 * damping_ratio_ * std::sqrt(mass_ * stiffness_);
    }
    friction_step_ = contact_duration(speed) / spec_.steps_per_contact;
}

double WallContactLaw::normal_force(double overlap, double overlap_rate) const {
    if (overlap <= 0.0) {
        return 0.0;
    }
    if (spec_.model == WallContact::Model::linear) {
        assert(stiffness_ > 0.0);
        return std::max(0.0, stiffness_ * overlap + damping_ * overlap_rate);
    }
    // Hertz (Johnson 1985, eq. 4.23) with Tsuji et al. (1992) damping
    // c = alpha sqrt(m k_n) d^(1/4).
    const double root = std::sqrt(std::sqrt(overlap));
    return std::max(0.0, hertz_stiffness_ * overlap * root * root +
                             damping_ * std::sqrt(mass_ * hertz_stiffness_) * root * overlap_rate);
}

RoundedForce WallContactLaw::rounded_normal_force(const WallOverlap& overlap,
                                                  double overlap_rate) const {
    assert(rounded_);
    // Each class's law is the contact of its rounded feature; the largest one carries the
    // contact. Every candidate is continuous in the rock's pose (the edge's and the section's
    // measures grow from zero as a feature reaches the plane), so the force has no jump when
    // the class changes, and no feature's force is counted twice.
    RoundedForce result{normal_force(overlap.depth, overlap_rate), HullContactClass::corner};
    // Spring-dashpot F = k d + 2 beta sqrt(m k) d' with the clamped law's beta, so a contact
    // of fixed k rebounds with the configured restitution (linear_impact).
    const auto linear = [this, overlap_rate](double stiffness, double depth) {
        return stiffness * depth +
               2.0 * damping_ratio_ * std::sqrt(mass_ * stiffness) * overlap_rate;
    };
    const HullPenetration& p = overlap.hull;
    if (p.edge_length > 0.0) {
        // A cylinder of radius r_c and length L on a half-space: Johnson (1985), pp. 99-104,
        // line contact of cylinders, linearised as F = pi/4 E* L d (its approach has a
        // logarithmic term besides).
        const double edge = linear(pi / 4.0 * effective_modulus_ * p.edge_length, p.edge_depth);
        if (edge > result.normal) {
            result = {edge, HullContactClass::edge};
        }
    }
    if (p.section_area > 0.0) {
        // A flat face with rounded rim as a rigid flat circular punch of the penetrating
        // polygon's area A: F = 2 E* a d, a = sqrt(A / pi) (Sneddon 1965; Johnson 1985, sec. 3.8),
        // d the mean depth over the section.
        const double face = linear(2.0 * effective_modulus_ * std::sqrt(p.section_area / pi),
                                   p.volume / p.section_area);
        if (face > result.normal) {
            result = {face, HullContactClass::face};
        }
    }
    return result;
}

WallForce WallContactLaw::force(const WallOverlap& overlap,
                                const Vec3& contact_point_velocity) const {
    assert(friction_step_ > 0.0);
    const Vec3& n = overlap.normal;
    const double normal_velocity = contact_point_velocity.dot(n);
    WallForce result;
    result.point = overlap.point;
    result.normal_direction = n;
    result.normal = rounded_ ? rounded_normal_force(overlap, -normal_velocity).normal
                             : normal_force(overlap.depth, -normal_velocity);
    result.force = result.normal * n;
    const Vec3 slip = contact_point_velocity - normal_velocity * n;
    const double slip_speed = slip.norm();
    if (slip_speed > 0.0 && result.normal > 0.0) {
        // Coulomb friction regularised for the explicit step: F_t = -mu F_n v_t / max(|v_t|,
        // v_eps) with v_eps = mu F_n dt / m_t, i.e. never more than the force that stops the
        // slip of the effective mass m_t within one fine step dt (no chatter when sticking).
        const double stopping = mass_ / kTangentialMassRatio * slip_speed / friction_step_;
        result.tangential = std::min(friction_ * result.normal, stopping);
        result.force -= result.tangential / slip_speed * slip;
    }
    return result;
}

}  // namespace rockfall::engine
