#include "soil_model.hpp"

#include "mpm/setup.hpp"
#include "mpm/soil.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::mpm {
namespace {

// Collects every problem of a scenario as `field = value unit: must be range`.
class Problems {
  public:
    void check(bool ok, const std::string& field, double value, const char* unit,
               const char* range) {
        if (!ok) {
            std::ostringstream line;
            line << field << " = " << value << (unit[0] != '\0' ? " " : "") << unit << ": must be "
                 << range;
            lines_.push_back(line.str());
        }
    }
    void add(const std::string& line) { lines_.push_back(line); }
    void throw_if_any() const {
        if (lines_.empty()) {
            return;
        }
        std::string all;
        for (const std::string& line : lines_) {
            all += (all.empty() ? "" : "\n") + line;
        }
        throw std::invalid_argument(all);
    }

  private:
    std::vector<std::string> lines_;
};

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

void check_slope(const shapes::SlopeSpec& slope, Problems& problems) {
    problems.check(!slope.segments.empty(), "slope.segments.size", 0.0, "", ">= 1");
    for (std::size_t i = 0; i < slope.segments.size(); ++i) {
        const std::string name = "slope.segments[" + std::to_string(i) + "].";
        problems.check(positive(slope.segments[i].length), name + "length",
                       slope.segments[i].length, "m", "> 0");
        problems.check(slope.segments[i].angle_deg >= 0.0 && slope.segments[i].angle_deg <= 80.0,
                       name + "angle_deg", slope.segments[i].angle_deg, "deg", "in [0, 80]");
    }
    problems.check(positive(slope.width), "slope.width", slope.width, "m", "> 0");
    problems.check(positive(slope.thickness), "slope.thickness", slope.thickness, "m", "> 0");
    if (slope.side_walls.enabled) {
        problems.check(positive(slope.side_walls.height), "slope.side_walls.height",
                       slope.side_walls.height, "m", "> 0");
        problems.check(positive(slope.side_walls.thickness), "slope.side_walls.thickness",
                       slope.side_walls.thickness, "m", "> 0");
    }
    if (slope.bars.enabled) {
        problems.check(positive(slope.bars.leg), "slope.bars.leg", slope.bars.leg, "m", "> 0");
        problems.check(positive(slope.bars.thickness) && slope.bars.thickness <= slope.bars.leg,
                       "slope.bars.thickness", slope.bars.thickness, "m", "in (0, leg]");
        problems.check(positive(slope.bars.spacing), "slope.bars.spacing", slope.bars.spacing, "m",
                       "> 0");
        for (std::size_t i = 0; i < slope.bars.segments.size(); ++i) {
            const int index = slope.bars.segments[i];
            problems.check(index >= 0 && index < static_cast<int>(slope.segments.size()),
                           "slope.bars.segments[" + std::to_string(i) + "]", index, "",
                           "a segment index");
        }
    }
    if (slope.wall.enabled && !slope.segments.empty()) {
        const shapes::SlopeSegment& last = slope.segments.back();
        const double run_out = last.length * std::cos(radians(last.angle_deg));
        problems.check(
            positive(slope.wall.distance_from_toe) && slope.wall.distance_from_toe < run_out,
            "slope.wall.distance_from_toe", slope.wall.distance_from_toe, "m",
            "> 0 and less than the last segment's horizontal length");
        problems.check(positive(slope.wall.height), "slope.wall.height", slope.wall.height, "m",
                       "> 0");
        problems.check(positive(slope.wall.thickness), "slope.wall.thickness", slope.wall.thickness,
                       "m", "> 0");
    }
}

shapes::OrientedBox box_between(const Vec3& lo, const Vec3& hi) {
    shapes::OrientedBox box;
    box.center = 0.5 * (lo + hi);
    box.half_extents = 0.5 * (hi - lo);
    return box;
}

}  // namespace

shapes::SlopeSpec seed_soil_slope() {
    shapes::SlopeSpec spec;
    spec.bars.enabled = false;
    return spec;
}

void validate(const SoilScenario& s) {
    Problems problems;
    check_slope(s.slope, problems);
    try {
        validate(Material{s.material}, "material.");
    } catch (const std::invalid_argument& e) {
        problems.add(e.what());
    }
    problems.check(positive(s.density), "density", s.density, "kg/m3", "> 0");
    const SoilRelease& r = s.release;
    problems.check(positive(r.length), "release.length", r.length, "m", "> 0");
    problems.check(positive(r.width), "release.width", r.width, "m", "> 0");
    problems.check(positive(r.thickness), "release.thickness", r.thickness, "m", "> 0");
    problems.check(r.bed_angle_deg > 0.0 && r.bed_angle_deg < 90.0, "release.bed_angle_deg",
                   r.bed_angle_deg, "deg", "in (0, 90)");
    problems.check(r.initial_bed_angle_deg >= 0.0 && r.initial_bed_angle_deg <= r.bed_angle_deg,
                   "release.initial_bed_angle_deg", r.initial_bed_angle_deg, "deg",
                   "in [0, bed_angle_deg]");
    problems.check(std::isfinite(r.tilt_duration) && r.tilt_duration >= 0.0,
                   "release.tilt_duration", r.tilt_duration, "s", ">= 0");
    problems.check(std::isfinite(r.hinge_offset_x), "release.hinge_offset_x", r.hinge_offset_x, "m",
                   "finite");
    problems.check(std::isfinite(r.hinge_offset_z), "release.hinge_offset_z", r.hinge_offset_z, "m",
                   "finite");
    problems.check(std::isfinite(r.side_board_height) && r.side_board_height >= 0.0,
                   "release.side_board_height", r.side_board_height, "m", ">= 0");
    const SoilBoundaries& b = s.boundaries;
    problems.check(b.basal_friction_angle_deg >= 0.0 && b.basal_friction_angle_deg <= 89.0,
                   "boundaries.basal_friction_angle_deg", b.basal_friction_angle_deg, "deg",
                   "in [0, 89]");
    problems.check(b.bed_friction_angle_deg >= 0.0 && b.bed_friction_angle_deg <= 89.0,
                   "boundaries.bed_friction_angle_deg", b.bed_friction_angle_deg, "deg",
                   "in [0, 89]");
    if (b.wall_support == WallSupport::spring) {
        problems.check(positive(b.wall_facing_mass), "boundaries.wall_facing_mass",
                       b.wall_facing_mass, "kg/m2", "> 0");
        problems.check(positive(b.wall_stiffness), "boundaries.wall_stiffness", b.wall_stiffness,
                       "Pa/m", "> 0");
        problems.check(b.wall_damping_ratio >= 0.0 && b.wall_damping_ratio <= 10.0,
                       "boundaries.wall_damping_ratio", b.wall_damping_ratio, "", "in [0, 10]");
        if (!s.slope.wall.enabled) {
            problems.add(
                "boundaries.wall_support = \"spring\": must be \"rigid\" without a wall "
                "(slope.wall.enabled = false)");
        }
    }
    const SoilNumerics& n = s.numerics;
    problems.check(n.dimension == 2 || n.dimension == 3, "numerics.dimension", n.dimension, "",
                   "2 or 3");
    problems.check(positive(n.cell_size), "numerics.cell_size", n.cell_size, "m", "> 0");
    problems.check(n.particles_per_cell >= 1 && n.particles_per_cell <= 8,
                   "numerics.particles_per_cell", n.particles_per_cell, "", "in [1, 8]");
    problems.check(n.cfl > 0.0 && n.cfl <= 1.0, "numerics.cfl", n.cfl, "", "in (0, 1]");
    problems.check(n.boundary_reach >= 0.0 && n.boundary_reach <= 0.5, "numerics.boundary_reach",
                   n.boundary_reach, "", "in [0, 0.5]");
    problems.check(n.flip >= 0.0 && n.flip <= 1.0, "numerics.flip", n.flip, "", "in [0, 1]");
    problems.check(n.min_density_ratio >= 0.0 && n.min_density_ratio < 1.0,
                   "numerics.min_density_ratio", n.min_density_ratio, "", "in [0, 1)");
    problems.check(n.threads >= 0, "numerics.threads", n.threads, "", ">= 0");
    const SoilOutput& o = s.output;
    problems.check(positive(o.duration), "output.duration", o.duration, "s", "> 0");
    problems.check(positive(o.sample_interval) && o.sample_interval <= o.duration,
                   "output.sample_interval", o.sample_interval, "s", "in (0, duration]");
    problems.check(std::isfinite(o.filter_window) && o.filter_window >= 0.0, "output.filter_window",
                   o.filter_window, "s", ">= 0");
    problems.check(positive(o.frame_interval), "output.frame_interval", o.frame_interval, "s",
                   "> 0");
    problems.throw_if_any();
}

namespace detail {

template <int Dim>
SoilModel<Dim> build_soil_model(const SoilScenario& scenario) {
    SoilModel<Dim> model(scenario.slope);
    const shapes::Slope& slope = model.slope;
    const double h = scenario.numerics.cell_size;
    const SoilBoundaries& friction = scenario.boundaries;
    const double mu_basal = std::tan(radians(friction.basal_friction_angle_deg));

    std::vector<StaticBoundary> statics;
    for (const shapes::OrientedBox& box : slope.solids()) {
        StaticBoundary b;
        b.box = box;
        if (box.role == shapes::SurfaceRole::reaction_wall) {
            b.group = kWallGroup;
            b.kind = friction.wall_fixed ? BoundaryKind::fixed : BoundaryKind::frictional;
        } else {
            b.group = kSlopeGroup;
            b.kind = BoundaryKind::frictional;
        }
        b.friction_coefficient = mu_basal;
        statics.push_back(b);
    }

    const SoilRelease& r = scenario.release;
    const Vec3 hinge(slope.profile().front().x() + r.hinge_offset_x, 0.0,
                     slope.profile().front().y() + r.hinge_offset_z);
    const double bed_thickness = std::max(0.1, 2.0 * h);
    const double half_width = 0.5 * r.width;
    const double board = 0.1;
    HingedBoundary bed;
    bed.hinge = hinge;
    bed.boxes.push_back(box_between(hinge + Vec3(-r.length, -half_width - board, -bed_thickness),
                                    hinge + Vec3(0.0, half_width + board, 0.0)));
    if (Dim == 3 && r.side_board_height > 0.0) {
        for (const double side : {-1.0, 1.0}) {
            const double inner = side * half_width;
            const double outer = side * (half_width + board);
            bed.boxes.push_back(
                box_between(hinge + Vec3(-r.length, std::min(inner, outer), -bed_thickness),
                            hinge + Vec3(0.0, std::max(inner, outer), r.side_board_height)));
        }
    }
    // A bed steeper than the first segment leaves a wedge open below the hinge between the bed's
    // end face and the segment's start face (both normal to their surfaces), through which the
    // soil turning onto the slope leaked under it. A static box continuing the bed past the
    // hinge at its steepest angle closes it: it lies below the segment's surface, and below the
    // bed's at every angle of the tilt (the wedge only narrows as the bed tilts up to that angle).
    const double wedge_deg = r.bed_angle_deg - scenario.slope.segments.front().angle_deg;
    if (wedge_deg > 0.0) {
        StaticBoundary filler;
        const double length = bed_thickness * std::tan(radians(std::min(wedge_deg, 80.0))) + h;
        filler.box =
            rotated_about(box_between(hinge + Vec3(0.0, -half_width - board, -bed_thickness),
                                      hinge + Vec3(length, half_width + board, 0.0)),
                          hinge, rotation_y(radians(r.bed_angle_deg)));
        filler.group = kSlopeGroup;
        filler.kind = BoundaryKind::frictional;
        filler.friction_coefficient = mu_basal;
        statics.push_back(filler);
    }
    bed.start_angle_deg = r.initial_bed_angle_deg;
    bed.end_angle_deg = r.bed_angle_deg;
    bed.duration = r.tilt_duration;
    bed.kind = BoundaryKind::frictional;
    bed.friction_coefficient = std::tan(radians(friction.bed_friction_angle_deg));
    bed.group = kBedGroup;

    const shapes::OrientedBox block =
        rotated_about(box_between(hinge + Vec3(-r.length, -half_width, 0.0),
                                  hinge + Vec3(0.0, half_width, r.thickness)),
                      hinge, rotation_y(radians(r.initial_bed_angle_deg)));
    Particles<Dim> particles;
    model.particle_spacing = h / scenario.numerics.particles_per_cell;
    add_box_particles<Dim>(particles, block, model.particle_spacing, scenario.density);

    // Domain: the bed and block over their whole rotation, the slope from the crown to the
    // wall's back (or the end), the full slope width; three cells of margin.
    Vec3 lo = Vec3::Constant(1e300);
    Vec3 hi = Vec3::Constant(-1e300);
    auto include = [&](const Vec3& p) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    };
    const double reach = std::max(r.thickness, r.side_board_height);
    for (double angle = r.initial_bed_angle_deg;; angle += 5.0) {
        const double a = std::min(angle, r.bed_angle_deg);
        const Mat3 rot = rotation_y(radians(a));
        for (const Vec3& corner :
             {Vec3(-r.length, 0.0, -bed_thickness), Vec3(-r.length, 0.0, reach),
              Vec3(0.0, 0.0, reach), Vec3(0.0, 0.0, -bed_thickness)}) {
            include(hinge + rot * corner);
        }
        if (a >= r.bed_angle_deg) {
            break;
        }
    }
    const double x_end =
        slope.wall() ? slope.wall_x() + scenario.slope.wall.thickness : slope.end_x();
    for (const Eigen::Vector2d& vertex : slope.profile()) {
        if (vertex.x() <= x_end) {
            include(Vec3(vertex.x(), 0.0, vertex.y()));
        }
    }
    include(Vec3(x_end, 0.0, slope.surface_height(x_end)));
    if (slope.wall()) {
        include(Vec3(x_end, 0.0, slope.surface_height(x_end) + scenario.slope.wall.height));
    }
    const double half_slope = 0.5 * scenario.slope.width;
    include(Vec3(lo.x(), -std::max(half_slope, half_width + board), lo.z()));
    include(Vec3(lo.x(), std::max(half_slope, half_width + board), lo.z()));

    SolverSettings settings;
    settings.cell_size = h;
    settings.domain_min = lo - Vec3::Constant(3.0 * h);
    if (scenario.numerics.align_grid) {
        // Node planes on the wall's face and the run-out surface: move the first node down
        // (by less than a cell) to the lattice through that point.
        const double anchor_x = slope.wall() ? slope.wall_x() : slope.toe_x();
        const double anchor_z = slope.surface_height(slope.toe_x());
        settings.domain_min.x() =
            anchor_x - std::ceil((anchor_x - settings.domain_min.x()) / h) * h;
        settings.domain_min.z() =
            anchor_z - std::ceil((anchor_z - settings.domain_min.z()) / h) * h;
    }
    settings.domain_max = hi + Vec3::Constant(3.0 * h);
    settings.boundary_reach = scenario.numerics.boundary_reach;
    settings.volumetric_averaging = scenario.numerics.volumetric_averaging;
    settings.flip = scenario.numerics.flip;
    settings.min_density_ratio = scenario.numerics.min_density_ratio;
    settings.cfl = scenario.numerics.cfl;
    settings.threads = scenario.numerics.threads;
    settings.max_time_step = scenario.output.sample_interval;
    std::optional<SpringSupport> spring;
    if (friction.wall_support == WallSupport::spring && slope.wall()) {
        // One facing over the whole front face (per metre of width in 2D), moving along +x.
        const double area = scenario.slope.wall.height * (Dim == 3 ? scenario.slope.width : 1.0);
        spring = SpringSupport{};
        spring->group = kWallGroup;
        spring->direction = Vec3::UnitX();
        spring->mass = friction.wall_facing_mass * area;
        spring->stiffness = friction.wall_stiffness * area;
        spring->damping =
            2.0 * friction.wall_damping_ratio * std::sqrt(spring->stiffness * spring->mass);
    }
    model.solver =
        std::make_unique<Solver<Dim>>(settings, Material{scenario.material}, std::move(particles),
                                      std::move(statics), std::vector<HingedBoundary>{bed}, spring);
    return model;
}

template SoilModel<2> build_soil_model<2>(const SoilScenario&);
template SoilModel<3> build_soil_model<3>(const SoilScenario&);

}  // namespace detail
}  // namespace rockfall::mpm
