#pragma once
/// The compliant contact between a rock and the reaction wall, and the load cell that turns
/// its forces into hit events. Pure functions of state: no Bullet here, so the law can be
/// checked against analytic solutions on its own.

#include <optional>
#include <vector>

#include <Eigen/Geometry>

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

namespace rockfall::engine {

/// Effective modulus E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2), Pa.
double effective_modulus(double e1, double nu1, double e2, double nu2);

/// Critical damping ratio of a linear spring-dashpot with restitution e in (0, 1]:
/// beta = -ln e / sqrt(pi^2 + ln^2 e) (inverse of e = exp(-beta pi / sqrt(1 - beta^2))).
double damping_ratio_from_restitution(double restitution);

/// Elastic Hertz impact of a sphere (mass m kg, radius R m) on a half-space at speed v m/s
/// with effective modulus E* Pa (Johnson, Contact Mechanics, 1985, sec. 11.4).
struct HertzImpact {
    double max_overlap = 0.0;  ///< m
    double peak_force = 0.0;   ///< N
    double duration = 0.0;     ///< s
};
HertzImpact hertz_impact(double effective_modulus, double radius, double mass, double speed);

/// Overlap of a rock with the wall box at one instant.
struct WallOverlap {
    /// Penetration depth, m (> 0).
    double depth = 0.0;
    /// Unit normal pointing out of the wall, into the rock.
    Vec3 normal = Vec3::Zero();
    /// Contact point (depth-weighted mean of the penetrating points), world frame, m.
    Vec3 point = Vec3::Zero();
};

/// Overlap of a rock (geometry in its body frame, placed at `position` with `orientation`)
/// with the wall box; empty when they do not touch.
std::optional<WallOverlap> wall_overlap(const shapes::OrientedBox& wall,
                                        const shapes::RockGeometry& rock, const Vec3& position,
                                        const Eigen::Quaterniond& orientation);

/// Force on the rock from the wall, world frame, and the point where it acts.
struct WallForce {
    Vec3 force = Vec3::Zero();  ///< N, acts on the rock (the wall feels the opposite)
    Vec3 point = Vec3::Zero();  ///< m
    double normal = 0.0;        ///< normal component, N (>= 0)
    double tangential = 0.0;    ///< magnitude of the friction component, N
};

/// Normal force law and Coulomb friction for one rock against the wall.
class WallContactLaw {
public:
    /// spec: elastic constants and model; wall and rock: materials (their mean restitution
    /// and friction are used); mass in kg; radius is the rock's radius of curvature at the
    /// contact, m (the sphere radius, or half the nominal size for hulls).
    WallContactLaw(const WallContact& spec, const Material& wall, const Material& rock,
                   double mass, double radius);

    /// Estimated contact duration for a normal approach speed v (m/s, > 0), s.
    double contact_duration(double approach_speed) const;
    /// Call at first touch with the normal approach speed (m/s); fixes velocity-dependent
    /// parameters (the Hertz-equivalent linear stiffness).
    void begin_contact(double approach_speed);
    /// Force on the rock for the given overlap and the velocity of the rock's material point
    /// at the contact (m/s, world frame).
    WallForce force(const WallOverlap& overlap, const Vec3& contact_point_velocity) const;

    /// Normal force, N (>= 0: the wall never pulls), for overlap d m and its rate m/s.
    double normal_force(double overlap, double overlap_rate) const;

private:
    WallContact spec_;
    double friction_ = 0.0;
    double restitution_ = 0.0;
    double mass_ = 0.0;
    double radius_ = 0.0;
    double effective_modulus_ = 0.0;
    double stiffness_ = 0.0;  // linear model, N/m
    double damping_ = 0.0;    // linear: N s/m; Hertz: Tsuji's alpha
};

/// Turns the wall force at each fine step into WallHit events (the load cell).
class LoadCell {
public:
    /// Records one step of length dt (s) ending at `after.time`; `force` is the force applied
    /// during that step, empty when the rock did not touch the wall; `before` and `after` are
    /// the rock's states at the start and the end of the step.
    void record(double dt, const std::optional<WallForce>& force, const RockState& before,
                const RockState& after);
    /// Closes an open event (at the end of a run).
    void finish(const RockState& state);
    /// True while a hit is in progress.
    bool in_contact() const { return open_.has_value(); }
    /// Completed hits, in time order.
    const std::vector<WallHit>& hits() const { return hits_; }

private:
    std::optional<WallHit> open_;
    std::vector<WallHit> hits_;
};

}  // namespace rockfall::engine
