#pragma once
/// A validated rockfall scenario: plain structs with documented defaults, SI units.

#include "engine/pressure_cells.hpp"
#include "shapes/grading.hpp"
#include "shapes/release_box.hpp"
#include "shapes/rocks.hpp"
#include "shapes/slope.hpp"

#include <Eigen/Core>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::engine {

using Vec3 = Eigen::Vector3d;

/// Contact coefficients of one surface or rock material. A contact between two materials uses
/// the arithmetic mean of their values (see docs/contact_model.md).
struct Material {
    /// Coulomb friction coefficient, in [0, 2].
    double friction = 0.6;
    /// Kinematic (Newton) coefficient of restitution, normal rebound / impact speed, in [0, 1].
    double restitution = 0.3;
    /// Rolling resistance coefficient (resisting torque = coefficient * r * normal force),
    /// dimensionless, in [0, 1].
    double rolling_resistance = 0.02;
};

/// Materials of the static surfaces.
struct SurfaceMaterials {
    Material slope;
    Material bars{0.4, 0.3, 0.02};
    Material side_walls{0.4, 0.3, 0.02};
    /// Reaction wall (concrete). Restitution sets the compliant contact's damping.
    Material wall{0.5, 0.3, 0.0};
};

/// Elastic constants of the rock and the wall for the compliant wall contact.
struct WallContact {
    /// Force law at the reaction wall.
    enum class Model {
        hertz,   ///< F = 4/3 E* sqrt(R) d^1.5 with Tsuji et al. (1992) damping from restitution
        linear,  ///< F = k d + c d', c from restitution (critical damping ratio beta)
    };
    Model model = Model::hertz;
    /// Young's modulus of the rock, Pa (> 0).
    double rock_youngs_modulus = 30e9;
    /// Poisson's ratio of the rock, in [0, 0.5).
    double rock_poisson_ratio = 0.2;
    /// Young's modulus of the wall facing, Pa (> 0).
    double wall_youngs_modulus = 30e9;
    /// Poisson's ratio of the wall, in [0, 0.5).
    double wall_poisson_ratio = 0.2;
    /// Linear model stiffness, N/m; 0 means Hertz-equivalent (matched to Hertz's peak force at
    /// each hit's impact speed). Ignored by the Hertz model.
    double linear_stiffness = 0.0;
    /// Time steps per estimated contact duration near the wall, in [20, 1000].
    int steps_per_contact = 100;
    /// Force law of a hull rock at the wall (spheres always use `model` with their radius).
    enum class HullModel {
        sphere,   ///< `model` with R = half the nominal size
        rounded,  ///< rounded polyhedron: Hertz at a corner, line contact along an edge, flat
                  ///< punch on a face (docs/wall_contact.md); needs model = hertz
    };
    HullModel hull_model = HullModel::sphere;
    /// Wadell roundness of a hull rock's corners and edges (mean corner radius over the
    /// inscribed radius), in (0, 1]; the rounded model's corner radius is this times the hull's
    /// inscribed radius about its centroid. Default: seed 001's measured mean.
    double corner_roundness = 0.38;
};

/// One rock: its shape, size and material.
struct RockSpec {
    /// Shape family; RockKind::custom exactly when `shape` is set.
    shapes::RockKind kind = shapes::RockKind::sphere;
    /// Nominal size: volume-equivalent diameter, m, in [0.01, 10]; a custom shape is scaled to
    /// it.
    double size = 0.2;
    /// Density, kg/m3, in [500, 10000].
    double density = 2600.0;
    /// Contact coefficients of the rock.
    Material material;
    /// The hull of a custom rock (a mesh file, a catalogue entry, a generated rock), at any
    /// scale; null for the families. Shared, as many rocks may use one shape.
    std::shared_ptr<const shapes::CustomShape> shape;

    /// The rock's geometry in its body frame, as the engine simulates it: the one place that
    /// turns a kind or a custom shape and a size into a rock.
    shapes::RockGeometry geometry() const {
        return shape ? shapes::make_rock(*shape, size) : shapes::make_rock(kind, size);
    }
};

/// How and where a rock starts.
struct Release {
    /// Distance along the slope surface from the crown to the release point, m (>= 0).
    double distance = 0.5;
    /// Lateral position y, m, inside the slope width.
    double lateral = 0.0;
    /// Gap between the rock's lowest point and the surface, m (>= 0).
    double height = 0.0;
    /// Initial velocity in the world frame, m/s.
    Vec3 velocity = Vec3::Zero();
    /// Initial angular velocity in the world frame, rad/s.
    Vec3 spin = Vec3::Zero();
    /// Initial orientation as x-y-z Euler angles, degrees, applied in the slope's surface frame.
    Vec3 orientation_deg = Vec3::Zero();
    /// When true the orientation is drawn uniformly at random from the run's seed instead.
    bool random_orientation = false;
};

/// A rock and its release.
struct RockRelease {
    /// Name shown in outputs (a tracked rock), or empty.
    std::string name;
    RockSpec rock;
    Release release;
};

/// A marked rock of a cluster (seed 001 tracked four): named, with its own shape, dropped into
/// the release box at a given spot after the drawn rocks, and reported one by one.
struct MarkedRock {
    /// Name shown in outputs, unique among the scenario's rocks; not empty.
    std::string name;
    /// Shape (family or custom hull), size, density and material.
    RockSpec rock;
    /// Spot in the box: distance from its back (upslope) face along the slope, m, and offset
    /// across from its centre line, m; the rock's bounding sphere must fit inside the walls.
    double along = 0.2;
    double across = 0.0;
    /// Orientation as x-y-z Euler angles in the slope's surface frame, degrees, or (empty) drawn
    /// at random from the run's seed like the other cluster rocks.
    std::optional<Vec3> orientation_deg;
};

/// How the compliant wall contact of an impact is stepped.
enum class WallStepping {
    /// Sub-stepped on the rocks that touch the wall, inside the world's coarse step (the
    /// default; docs/scenarios.md, "Wall stepping").
    per_rock,
    /// The whole world takes the contact's fine step while any rock makes an impact.
    world,
};

/// How rocks find their contacts with a perforated sheet (docs/scenarios.md, "Linings").
enum class SheetContact {
    /// From the sheet's structure: hull vertices against the top face, GJK against the rims of
    /// the holes a rock dips into (the default).
    structured,
    /// Bullet's triangle-mesh contact, a GJK query per triangle near the rock.
    mesh,
};

/// Time stepping and stop rule.
struct Numerics {
    /// Coarse time step away from the wall, s, in [1e-5, 1e-2].
    double time_step = 1e-3;
    /// Simulated time limit, s (> 0).
    double max_time = 30.0;
    /// A rock is at rest when its speed stays below this, m/s (> 0) ...
    double rest_speed = 0.02;
    /// ... for this long, s (> 0).
    double rest_duration = 0.5;
    /// Impacts slower than this (normal approach speed at first touch) do not bounce, m/s, in
    /// [0.001, 1]: far below any bounce that matters, above the g dt a resting contact gains
    /// per step (0.01 m/s at 1 ms).
    double restitution_threshold = 0.05;
    /// Solver iterations per step, in [1, 100].
    int solver_iterations = 10;
    /// Penetration the position correction leaves in place, in units of g dt^2 (the depth a
    /// contact sinks in one unsupported step; 19.6 um at the default step), in [0, 100]: a
    /// resting contact then stays in the solver every step instead of being pushed clear and
    /// dropped every other one (docs/contact_model.md, "Resting contacts"). 0: every penetration
    /// is corrected (Bullet's behaviour).
    double contact_slop = 2.0;
    /// Steps per coarse step while a rock approaching an angle bar at 1 m/s or more is within
    /// two coarse steps' travel of it, in [1, 64] (1: none). A coarse step lets a rock land
    /// beside a bar and strike its edge in one step, two impacts milliseconds apart solved as
    /// one (docs/sweeps.md, "Step size"); 4 reads the sweep tails of a 0.25 ms step at 1.1 to
    /// 1.25 times the cost of 1 ms.
    int bar_refinement = 4;
    /// Stepping of wall impacts.
    WallStepping wall_stepping = WallStepping::per_rock;
    /// Contact detection against a perforated sheet.
    SheetContact sheet_contact = SheetContact::structured;
};

/// A cluster of rocks released together from a box (seed 001): sizes drawn from a grain-size
/// distribution by the run's seed, packed in the release box, settled there behind a closed
/// gate, then released at t = 0 when the gate opens. Its rocks follow `rocks` in the outcome.
struct Cluster {
    /// Grain sizes (volume-equivalent diameters) and their number or solid volume.
    shapes::Grading grading;
    /// Family (default massive) or custom hull (a catalogue entry, a mesh), density and
    /// material of every cluster rock; its size is the drawn one.
    RockSpec rock = [] {
        RockSpec spec;
        spec.kind = shapes::RockKind::massive;
        return spec;
    }();
    /// The box at the top of the first segment.
    shapes::ReleaseBox box;
    /// When > 0, each drawn rock is instead a random hull of this Wadell sphericity (its own
    /// from the run's seed, shapes::rock_with_sphericity), in [0.5, 0.95].
    double sphericity = 0.0;
    /// Time the packed rocks settle in the closed box before the gate opens, s (> 0).
    double settle_time = 1.0;
    /// Marked rocks, after the drawn ones in the outcome.
    std::vector<MarkedRock> marked;
};

/// Everything one simulation needs.
struct Scenario {
    /// Free-text name, echoed in outputs.
    std::string name = "scenario";
    /// Slope, bars, side walls and reaction wall.
    shapes::SlopeSpec slope;
    /// Surface materials.
    SurfaceMaterials materials;
    /// Compliant contact at the reaction wall.
    WallContact wall_contact;
    /// Pressure cells over the reaction wall's face (engine/pressure_cells.hpp), if any.
    std::optional<PressureCells> wall_cells;
    /// Rocks released together (at least one, or a cluster).
    std::vector<RockRelease> rocks = {RockRelease{}};
    /// A cluster released with them, or none.
    std::optional<Cluster> cluster;
    /// Horizontal distances from the toe where stations record crossings, m (seed: 0 and 4).
    std::vector<double> stations = {0.0, 4.0};
    /// Stepping and stop rule.
    Numerics numerics;
    /// Gravitational acceleration, m/s2 (> 0).
    double gravity = 9.81;
};

}  // namespace rockfall::engine
