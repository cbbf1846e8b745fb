#pragma once
/// The compliant contact between a rock and the reaction wall, and the load cell that turns
/// its forces into hit events. Pure functions of state: no Bullet here, so the law can be
/// checked against analytic solutions on its own.

#include "engine/outcome.hpp"
#include "engine/scenario.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Geometry>

#include <array>
#include <optional>
#include <vector>

namespace rockfall::engine {

/// Effective modulus E* = 1 / ((1 - nu1^2) / E1 + (1 - nu2^2) / E2), Pa.
double effective_modulus(double e1, double nu1, double e2, double nu2);

/// Critical damping ratio of a linear spring-dashpot with restitution e in (0, 1]:
/// beta = -ln e / sqrt(pi^2 + ln^2 e) (inverse of e = exp(-beta pi / sqrt(1 - beta^2))).
/// This is the restitution of the dashpot that may pull; the wall's clamped law uses
/// clamped_damping_ratio instead.
double damping_ratio_from_restitution(double restitution);

/// Elastic Hertz impact of a sphere (mass m kg, radius R m) on a half-space at speed v m/s
/// with effective modulus E* Pa (Johnson, Contact Mechanics, 1985, sec. 11.4).
struct HertzImpact {
    double max_overlap = 0.0;  ///< m
    double peak_force = 0.0;   ///< N
    double duration = 0.0;     ///< s
};
HertzImpact hertz_impact(double effective_modulus, double radius, double mass, double speed);

/// Smallest restitution the wall contact models can be calibrated to (their damping grows
/// without bound as e -> 0).
inline constexpr double kMinWallRestitution = 0.01;

/// Impact of a mass on a linear spring-dashpot F = max(0, k d + c d'), c = 2 beta sqrt(m k),
/// in closed form (the contact ends when the force vanishes, before the overlap does; Schwager
/// and Poeschel, Granular Matter 9, 2007). Nondimensional: force in units of v0 sqrt(m k),
/// time in units of 1 / omega0 = sqrt(m / k).
struct LinearImpact {
    /// Peak force (the dashpot's jump 2 beta at first touch when beta >= 0.5).
    double peak_force = 0.0;
    /// Time of the peak (0 when the jump is the peak).
    double peak_time = 0.0;
    /// Time when the force vanishes: the contact duration.
    double duration = 0.0;
    /// Rebound over impact speed at that time, in (0, 1].
    double restitution = 0.0;
};
/// The impact for a critical damping ratio beta >= 0.
LinearImpact linear_impact(double damping_ratio);

/// Damping ratio beta >= 0 with which the clamped linear law rebounds with restitution e in
/// [kMinWallRestitution, 1] (inverse of linear_impact(beta).restitution, by bisection).
double clamped_damping_ratio(double restitution);

/// Impact of a sphere on the Hertz law with Tsuji, Tanaka and Ishida (1992) damping,
/// F = max(0, k d^1.5 + alpha sqrt(m k) d^0.25 d'), k = 4/3 E* sqrt(R), solved numerically
/// (RK4). Nondimensional: overlap in units of D = (m v0^2 / k)^(2/5), time in units of
/// D / v0, force in units of k D^1.5. The restitution depends on alpha only.
struct TsujiImpact {
    /// Damping constant alpha (>= 0).
    double alpha = 0.0;
    /// Peak force.
    double peak_force = 0.0;
    /// Time when the force vanishes: the contact duration.
    double duration = 0.0;
    /// Rebound over impact speed, in (0, 1].
    double restitution = 0.0;
};
/// The impact for a given alpha >= 0.
TsujiImpact tsuji_impact(double alpha);
/// The impact whose restitution is e in [kMinWallRestitution, 1]: alpha by bisection, cached
/// per e (thread-safe).
const TsujiImpact& tsuji_impact_for_restitution(double restitution);

/// A convex hull as the rounded-polyhedron wall law sees it, computed once per rock.
struct HullFeatures {
    /// Feature edges (between faces that are not coplanar), as index pairs into the hull's
    /// vertices; the diagonals of a face's triangles are left out.
    std::vector<std::array<int, 2>> edges;
    /// Radius of the largest sphere about the centroid (the body-frame origin) inside the
    /// hull: the smallest distance from the centroid to a face plane, m (> 0).
    double inscribed_radius = 0.0;
    /// Area of the largest face (coplanar triangles merged), m2.
    double largest_face_area = 0.0;
    /// Length of the longest feature edge, m.
    double longest_edge = 0.0;
};
/// The features of a hull whose centroid is the origin (shapes::RockGeometry's body frame).
HullFeatures hull_features(const shapes::ConvexPolyhedron& hull);

/// How deep a hull reaches into the wall's plane, for the rounded-polyhedron law. Depth is
/// measured from the plane along its normal; all zero when nothing penetrates.
struct HullPenetration {
    /// Penetrating length of the feature edge with the largest integral of depth along it, m.
    double edge_length = 0.0;
    /// Mean depth along that penetrating length, m.
    double edge_depth = 0.0;
    /// Area of the hull's section by the plane (the penetrating polygon), m2.
    double section_area = 0.0;
    /// Volume of the hull beyond the plane, m3.
    double volume = 0.0;
};
/// Penetration of `hull` (body frame) into the half-space {x : normal . x < offset}, normal a
/// unit vector in the body frame.
HullPenetration hull_penetration(const shapes::ConvexPolyhedron& hull, const HullFeatures& features,
                                 const Vec3& normal, double offset);

/// Overlap of a rock with the wall box at one instant.
struct WallOverlap {
    /// Penetration depth, m (> 0).
    double depth = 0.0;
    /// Unit normal pointing out of the wall, into the rock.
    Vec3 normal = Vec3::Zero();
    /// Contact point (depth-weighted mean of the penetrating points), world frame, m.
    Vec3 point = Vec3::Zero();
    /// A hull's penetration into the plane through its deepest vertex normal to `normal`
    /// (only when wall_overlap was given the hull's features; zero otherwise).
    HullPenetration hull;
};

/// Overlap of a rock (geometry in its body frame, placed at `position` with `orientation`)
/// with the wall box; empty when they do not touch. A sphere's penetrating point is its
/// deepest point; a hull's are its vertices inside the box, aggregated into one contact (the
/// stiffness does not multiply with the number of touching vertices). With `features` (those
/// of the rock's hull) a hull's penetration is measured too.
std::optional<WallOverlap> wall_overlap(const shapes::OrientedBox& wall,
                                        const shapes::RockGeometry& rock, const Vec3& position,
                                        const Eigen::Quaterniond& orientation,
                                        const HullFeatures* features = nullptr);

/// Force on the rock from the wall, world frame, and the point where it acts.
struct WallForce {
    Vec3 force = Vec3::Zero();  ///< N, acts on the rock (the wall feels the opposite)
    Vec3 point = Vec3::Zero();  ///< m
    double normal = 0.0;        ///< normal component, N (>= 0)
    double tangential = 0.0;    ///< magnitude of the friction component, N
    /// Unit normal out of the wall (the overlap's normal).
    Vec3 normal_direction = Vec3::Zero();
};

/// What of a hull carries the rounded-polyhedron law's force.
enum class HullContactClass {
    corner,  ///< Hertz at a sphere of the corner radius
    edge,    ///< line contact of a cylinder of the corner radius
    face,    ///< flat punch of the penetrating polygon
};

/// The rounded-polyhedron law's normal force and the class that gives it.
struct RoundedForce {
    double normal = 0.0;  ///< N (>= 0)
    HullContactClass contact_class = HullContactClass::corner;
};

/// Normal force law and Coulomb friction for one rock against the wall.
class WallContactLaw {
  public:
    /// spec: elastic constants and model; wall and rock: materials (their mean restitution
    /// and friction are used); mass in kg; radius is the rock's radius of curvature at the
    /// contact, m (the sphere radius, or half the nominal size for hulls). Throws
    /// std::invalid_argument when the mean restitution is below kMinWallRestitution.
    WallContactLaw(const WallContact& spec, const Material& wall, const Material& rock, double mass,
                   double radius);
    /// The law of `geometry` (body frame, centroid at the origin): a sphere's Hertz law with
    /// its radius; a hull's per spec.hull_model, either `model` with half the nominal size or
    /// the rounded-polyhedron law (which needs model = hertz).
    WallContactLaw(const WallContact& spec, const Material& wall, const Material& rock, double mass,
                   const shapes::RockGeometry& geometry);

    /// Contact duration (first touch to vanishing force) for a normal approach speed v
    /// (m/s, > 0), s. For the rounded law the shortest of its classes (the largest face
    /// landing flat, or the longest edge), which sets the fine step.
    double contact_duration(double approach_speed) const;
    /// The longest contact duration for approach speed v (m/s, > 0), s: contact_duration for
    /// the sphere laws, the corner's Hertz contact for the rounded law.
    double longest_contact_duration(double approach_speed) const;
    /// The hull's features when the rounded law is in use (pass them to wall_overlap), else
    /// null.
    const HullFeatures* hull_features() const { return rounded_ ? &features_ : nullptr; }
    /// Corner radius of the rounded law, m (0 for the sphere laws).
    double corner_radius() const { return corner_radius_; }
    /// The rounded law's normal force for an overlap with its hull penetration and the
    /// overlap rate (m/s): the largest of corner, edge and face (clamped at 0).
    RoundedForce rounded_normal_force(const WallOverlap& overlap, double overlap_rate) const;
    /// Call at first touch with the normal approach speed (m/s); fixes velocity-dependent
    /// parameters (the Hertz-equivalent linear stiffness, the friction regularisation).
    /// Speeds below kMinContactSpeed count as that speed.
    void begin_contact(double approach_speed);
    /// Force on the rock for the given overlap and the velocity of the rock's material point
    /// at the contact (m/s, world frame). begin_contact must have been called.
    WallForce force(const WallOverlap& overlap, const Vec3& contact_point_velocity) const;

    /// Normal force, N (>= 0: the wall never pulls), for overlap d m and its rate m/s.
    /// begin_contact must have been called for the Hertz-equivalent linear model.
    double normal_force(double overlap, double overlap_rate) const;

    /// Linear stiffness in use, N/m (0 for the Hertz model or before begin_contact when
    /// Hertz-equivalent).
    double stiffness() const { return stiffness_; }
    /// Mean restitution of wall and rock, in [kMinWallRestitution, 1].
    double restitution() const { return restitution_; }
    /// Mean friction coefficient of wall and rock.
    double friction() const { return friction_; }

    /// Approach speeds below this are raised to it at begin_contact, m/s: the
    /// Hertz-equivalent stiffness (~ v^0.4) and the contact time (~ v^-0.2) degenerate at 0.
    static constexpr double kMinContactSpeed = 0.1;
    /// Assumed upper bound of m / m_t, the ratio of the rock's mass to its effective mass for
    /// sliding at the contact point (3.5 for a sphere, up to 6.6 at a corner of a 1 : 0.8 :
    /// 0.35 box), which bounds the friction force that stops the slip within one step.
    static constexpr double kTangentialMassRatio = 7.0;

  private:
    // Linear stiffness giving Hertz's elastic peak force at this approach speed, N/m.
    double hertz_equivalent_stiffness(double approach_speed) const;

    // Tsuji duration of a Hertz contact of stiffness k_n (N/m^1.5) at speed v, s.
    double tsuji_duration(double hertz_stiffness, double speed) const;
    // Clamped spring-dashpot duration of stiffness k (N/m), s.
    double linear_duration(double stiffness) const;

    WallContact spec_;
    bool rounded_ = false;
    HullFeatures features_;
    double corner_radius_ = 0.0;  // r_c = roundness x inscribed radius, m
    double friction_ = 0.0;
    double restitution_ = 0.0;
    double mass_ = 0.0;
    double radius_ = 0.0;
    double effective_modulus_ = 0.0;
    double hertz_stiffness_ = 0.0;  // k_n = 4/3 E* sqrt(R), N/m^1.5
    double stiffness_ = 0.0;        // linear model, N/m
    double damping_ = 0.0;          // linear: N s/m; Hertz and rounded: Tsuji's alpha
    double damping_ratio_ = 0.0;    // linear model's beta (and the rounded edge's and face's)
    double friction_step_ = 0.0;    // fine step assumed by the friction regularisation, s
};

/// Turns the wall force at each fine step into WallHit events (the load cell). A step "with
/// force" is one whose force has a positive normal component: an event opens at the first
/// such step and closes at the first step without (separation: with the clamped law the
/// force vanishes while the geometric overlap lingers).
class LoadCell {
  public:
    /// Records one step of length dt (s) ending at `after.time`; `force` is the force applied
    /// during that step, empty when the rock did not touch the wall; `before` and `after` are
    /// the rock's states at the start and the end of the step. `holding`: the rock still
    /// touches the wall in a resting contact, so a step without force (the rigid contact's
    /// impulse can vanish for a step while the rock leans on it) keeps the event open.
    void record(double dt, const std::optional<WallForce>& force, const RockState& before,
                const RockState& after, bool holding = false);
    /// Closes an open event (at the end of a run).
    void finish(const RockState& state);
    /// True while a hit is in progress.
    bool in_contact() const { return open_.has_value(); }
    /// Completed hits, in time order.
    const std::vector<WallHit>& hits() const { return hits_; }

  private:
    void close();

    std::optional<WallHit> open_;
    std::vector<WallHit> hits_;
};

}  // namespace rockfall::engine
