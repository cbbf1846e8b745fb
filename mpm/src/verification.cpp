// The MPM verification cases (see verification.hpp).

#include "mpm/verification.hpp"

#include "mpm/setup.hpp"
#include "mpm/solver.hpp"

#include <Eigen/Cholesky>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

namespace rockfall::mpm::verification {

namespace {

constexpr double g = 9.81;  // m/s2
// Density of the collapse's soil and of the sliding layer, kg/m3.
constexpr double kSoilDensity = 1600.0;

double to_radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

// Running sums of an ordinary least-squares line y = intercept + slope x (the cases' data are
// a few hundred to a few thousand points of like magnitude, so the uncentred sums are enough).
struct LineSums {
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    void add(double x, double y) {
        n += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    /// NaN with fewer than two distinct x.
    double slope() const {
        const double d = n * sxx - sx * sx;
        return n >= 2.0 && d > 0.0 ? (n * sxy - sx * sy) / d
                                   : std::numeric_limits<double>::quiet_NaN();
    }
    double intercept() const { return (sy - slope() * sx) / n; }
};

}  // namespace

shapes::OrientedBox axis_box(const Vec3& lo, const Vec3& hi) {
    shapes::OrientedBox box;
    box.center = 0.5 * (lo + hi);
    box.half_extents = 0.5 * (hi - lo);
    return box;
}

shapes::OrientedBox inclined_box(double angle_deg, const Vec3& center, const Vec3& half) {
    const double a = to_radians(angle_deg);
    shapes::OrientedBox box;
    box.rotation.col(0) = Vec3(std::cos(a), 0.0, -std::sin(a));
    box.rotation.col(1) = Vec3::UnitY();
    box.rotation.col(2) = Vec3(std::sin(a), 0.0, std::cos(a));
    box.center = center;
    box.half_extents = half;
    return box;
}

StaticBoundary solid(const shapes::OrientedBox& box, BoundaryKind kind, double mu, int group) {
    StaticBoundary b;
    b.box = box;
    b.kind = kind;
    b.friction_coefficient = mu;
    b.group = group;
    return b;
}

ElasticBar elastic_bar(double cell_size) {
    const double length = 1.0;
    const double h = cell_size;
    const double youngs = 1.0e7;
    const double density = 1000.0;
    const double v0 = 0.1;
    const double c = std::sqrt(youngs / density);
    const double omega = std::numbers::pi * c / (2.0 * length);
    const double k = std::numbers::pi / (2.0 * length);
    ElasticBar bar;
    bar.cell_size = h;
    bar.expected_period = 2.0 * std::numbers::pi / omega;
    // The tip is tracked by the particles of the last lattice column, at L - h/4.
    bar.expected_tip_amplitude = v0 / omega * std::sin(k * (length - h / 4.0));
    bar.expected_velocity_amplitude = v0 * 2.0 / std::numbers::pi;

    Particles<2> particles;
    add_box_particles<2>(particles, axis_box(Vec3(0.0, -0.5, 0.5), Vec3(length, 0.5, 0.6)), h / 2.0,
                         density);
    for (std::size_t p = 0; p < particles.size(); ++p) {
        const double x = particles.position[p][0];
        particles.velocity[p] = Vec<2>(v0 * std::sin(k * x), 0.0);
        particles.affine[p](0, 0) = v0 * k * std::cos(k * x);
    }
    const double mass = particles.total_mass();
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(-0.3, 0.0, 0.2);
    s.domain_max = Vec3(1.3, 0.0, 0.9);
    s.gravity = Vec3::Zero();
    std::vector<StaticBoundary> clamp{
        solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 1.0, 2.0)), BoundaryKind::fixed, 0.0, 0)};
    Solver<2> solver(s, LinearElastic{youngs, 0.0}, std::move(particles), std::move(clamp));

    const auto tip_displacement = [&](const Particles<2>& p) {
        double sum = 0.0;
        double weight = 0.0;
        for (std::size_t i = 0; i < p.size(); ++i) {
            const double x = p.position[i][0];
            if (x > length - h / 2.0 - 0.01) {
                sum += x - (length - h / 4.0);
                weight += 1.0;
            }
        }
        return sum / weight;
    };
    const double dt = solver.stable_time_step();
    const double period = bar.expected_period;
    std::vector<double> crossings;
    double previous_v = bar.expected_velocity_amplitude;
    while (solver.time() < 3.0 * period) {
        solver.step(dt);
        const double v = solver.particles().momentum()[0] / mass;
        bar.time.push_back(solver.time());
        bar.mean_velocity.push_back(v);
        if ((previous_v > 0.0) != (v > 0.0)) {
            crossings.push_back(solver.time() - dt * v / (v - previous_v));
        }
        previous_v = v;
        if (solver.time() < period) {
            bar.tip_amplitude =
                std::max(bar.tip_amplitude, std::abs(tip_displacement(solver.particles())));
        }
        if (solver.time() > 2.0 * period) {
            bar.late_velocity_amplitude = std::max(bar.late_velocity_amplitude, std::abs(v));
        }
    }
    if (crossings.size() < 5) {
        throw std::runtime_error("elastic bar: the mean velocity crossed zero only " +
                                 std::to_string(crossings.size()) + " times in three periods");
    }
    // Zero crossings of the mean velocity are half a period apart.
    bar.period = 2.0 * (crossings[4] - crossings[0]) / 4.0;
    return bar;
}

ColumnForces column_at_rest(double nu, double cell, double width, double offset, double reach,
                            bool averaging) {
    const double height = 2.0;
    const double density = 2000.0;
    Particles<2> column;
    add_box_particles<2>(column, axis_box(Vec3(0.0, -0.5, 0.0), Vec3(width, 0.5, height)),
                         cell / 2.0, density);
    SolverSettings s;
    s.threads = 1;
    s.cell_size = cell;
    s.boundary_reach = reach;
    s.volumetric_averaging = averaging;
    s.domain_min = Vec3(-offset, 0.0, -offset);
    s.domain_max = Vec3(width + 0.5, 0.0, height + 0.5);
    s.damping = 60.0;
    std::vector<StaticBoundary> box{
        solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(width + 1.0, 1.0, 0.0)),
              BoundaryKind::frictional, 0.0, 0),
        solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 1.0, 3.0)), BoundaryKind::frictional, 0.0,
              1),
        solid(axis_box(Vec3(width, -1.0, -1.0), Vec3(width + 1.0, 1.0, 3.0)),
              BoundaryKind::frictional, 0.0, 2)};
    Solver<2> solver(s, LinearElastic{1.0e7, nu}, std::move(column), std::move(box));

    const double duration = 1.0;
    const double window = 0.2;
    std::array<Vec3, kBoundaryGroups> impulse = zero_impulses();
    double averaged_time = 0.0;
    while (solver.time() < duration) {
        const StepReport& r = solver.step(solver.stable_time_step());
        if (solver.time() > duration - window) {
            for (int i = 0; i < kBoundaryGroups; ++i) impulse[i] += r.impulse[i];
            averaged_time += r.dt;
        }
    }
    const double k0 = nu / (1.0 - nu);
    return {density * g * width * height, k0 * density * g * height * height / 2.0,
            -impulse[0].z() / averaged_time, -impulse[1].x() / averaged_time,
            impulse[2].x() / averaged_time};
}

double lube_runout(double a) {
    if (a <= 1.8) return 1.2 * a;
    if (a >= 2.8) return 1.9 * std::pow(a, 2.0 / 3.0);
    // Between the two regimes the fit is not given: the larger of the two branches.
    return std::max(1.2 * a, 1.9 * std::pow(a, 2.0 / 3.0));
}

double lajeunesse_runout(double a) { return a < 3.0 ? 1.8 * a : 2.3 * std::pow(a, 2.0 / 3.0); }

namespace {

// The soil of the collapse and the sliding layer: Drucker-Prager, phi 30 deg matched in plane
// strain, no cohesion, dilatancy 0, E 1 MPa, nu 0.3, started geostatic with K0 = nu / (1 - nu).
DruckerPrager verification_soil() {
    DruckerPrager soil;
    soil.youngs_modulus = 1.0e6;
    soil.poisson_ratio = 0.3;
    soil.friction_angle_deg = 30.0;
    soil.cohesion = 0.0;
    soil.match = ConeMatch::plane_strain;
    return soil;
}

constexpr double kSoilK0 = 0.3 / 0.7;

// The floor z <= 0 (boundary group 0) with friction coefficient mu.
StaticBoundary floor_solid(double mu) {
    return solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(10.0, 1.0, 0.0)), BoundaryKind::frictional,
                 mu, 0);
}

}  // namespace

ColumnCollapse column_collapse(double aspect, int cells_per_length,
                               const CollapseNumerics& numerics) {
    if (!(aspect > 0.0) || cells_per_length < 4) {
        throw std::invalid_argument("column_collapse: aspect must be > 0 and cells >= 4");
    }
    const double length = collapse_length;
    const double height = aspect * length;
    const double h = length / cells_per_length;
    Particles<2> column;
    add_box_particles<2>(column, axis_box(Vec3(0.0, -0.5, 0.0), Vec3(length, 0.5, height)), h / 2.0,
                         kSoilDensity);
    SolverSettings s;
    s.threads = numerics.threads;
    s.cell_size = h;
    s.cfl = numerics.cfl;
    s.flip = numerics.flip;
    s.domain_min = Vec3(-0.1, 0.0, -0.1);
    s.domain_max = Vec3(length * (1.0 + 2.5 * aspect) + 0.3, 0.0, height + 0.1);
    const double mu = std::tan(std::numbers::pi / 6.0);
    std::vector<StaticBoundary> box{floor_solid(mu),
                                    solid(axis_box(Vec3(-1.0, -1.0, -1.0), Vec3(0.0, 1.0, 10.0)),
                                          BoundaryKind::frictional, mu, 1)};
    DruckerPrager soil = verification_soil();
    soil.friction_angle_deg = numerics.friction_angle_deg;
    Solver<2> solver(s, soil, std::move(column), std::move(box));
    set_geostatic_stress<2>(solver.particles(), height, g, kSoilK0);
    ColumnCollapse result;
    result.aspect = aspect;
    result.cells_per_length = cells_per_length;
    const Particles<2>& particles = solver.particles();
    const double time_scale = std::sqrt(height / g);
    bool early = true;
    while (solver.time() < 20.0 * time_scale) {
        const StepReport& r = solver.step(solver.stable_time_step());
        result.clamped_steps += r.clamped_particles > 0 ? 1 : 0;
        if (early && solver.time() >= time_scale) {
            early = false;
            result.early_kinetic_energy = particles.kinetic_energy();
        }
        if (solver.time() > 2.0 * time_scale && r.max_speed < 0.005 * std::sqrt(g * length)) break;
    }
    const double front = particles.front();
    result.centre_of_mass = particles.centre_of_mass();
    result.runout = (front + h / 4.0 - length) / length;
    result.time = solver.time();
    result.deposit = particles.position;
    result.deposit_mass = particles.mass;
    return result;
}

namespace {

// The deposit's thickness per h-wide grid column from x = 0 (m): its particles' mass over
// (1600 kg/m3 h). Particles behind the back wall are left out.
std::vector<double> column_thickness(const ColumnCollapse& collapse) {
    const double h = collapse_length / collapse.cells_per_length;
    std::vector<double> thickness;
    for (std::size_t i = 0; i < collapse.deposit.size(); ++i) {
        const double x = collapse.deposit[i][0];
        if (x < 0.0) continue;
        const auto column = static_cast<std::size_t>(x / h);
        if (column >= thickness.size()) thickness.resize(column + 1, 0.0);
        thickness[column] += collapse.deposit_mass[i] / (kSoilDensity * h);
    }
    return thickness;
}

}  // namespace

double deposit_front(const ColumnCollapse& collapse, double thickness) {
    const double h = collapse_length / collapse.cells_per_length;
    const std::vector<double> column = column_thickness(collapse);
    double front = 0.0;
    for (std::size_t c = 0; c < column.size(); ++c) {
        if (column[c] > thickness) front = static_cast<double>(c + 1) * h;
    }
    return (front - collapse_length) / collapse_length;
}

double surface_toe(const ColumnCollapse& collapse, double lower, double upper) {
    const double h = collapse_length / collapse.cells_per_length;
    const std::vector<double> column = column_thickness(collapse);
    const auto thickest = std::max_element(column.begin(), column.end()) - column.begin();
    // Least-squares line thickness = t0 + slope x through the columns' centres.
    LineSums line;
    for (auto c = thickest + 1; c < static_cast<std::ptrdiff_t>(column.size()); ++c) {
        const double t = column[static_cast<std::size_t>(c)];
        if (t >= lower && t <= upper) line.add((static_cast<double>(c) + 0.5) * h, t);
    }
    const double slope = line.slope();
    if (!(slope < 0.0)) return std::numeric_limits<double>::quiet_NaN();
    return (-line.intercept() / slope - collapse_length) / collapse_length;
}

BlockSlide sliding_block(double angle_deg, double friction_angle_deg, double duration,
                         double damping) {
    const double a = to_radians(angle_deg);
    const Vec3 down(std::cos(a), 0.0, -std::sin(a));
    const Vec3 normal(std::sin(a), 0.0, std::cos(a));
    const Vec3 top(0.6, 0.0, 2.2);
    const double h = 0.05;
    Particles<2> block;
    add_box_particles<2>(block, inclined_box(angle_deg, top + 0.1 * normal, Vec3(0.2, 0.5, 0.1)),
                         h / 2.0, 2000.0);
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    s.domain_min = Vec3(-0.5, 0.0, -0.5);
    s.domain_max = Vec3(3.5, 0.0, 3.0);
    s.damping = damping;
    const double mu = std::tan(to_radians(friction_angle_deg));
    std::vector<StaticBoundary> incline{
        solid(inclined_box(angle_deg, top - 0.5 * normal, Vec3(4.0, 1.0, 0.5)),
              BoundaryKind::frictional, mu, 0)};
    Solver<2> solver(s, LinearElastic{5.0e6, 0.3}, std::move(block), std::move(incline));

    BlockSlide result;
    result.expected_acceleration = std::max(0.0, g * (std::sin(a) - mu * std::cos(a)));
    const Vec3 start = to_scene<2>(solver.particles().centre_of_mass());
    // Normal equations of the quadratic fit in t.
    Eigen::Matrix3d normal_matrix = Eigen::Matrix3d::Zero();
    Vec3 rhs = Vec3::Zero();
    while (solver.time() < duration) {
        solver.step(solver.stable_time_step());
        const double t = solver.time();
        const double along = (to_scene<2>(solver.particles().centre_of_mass()) - start).dot(down);
        const Vec3 basis(1.0, t, 0.5 * t * t);
        normal_matrix += basis * basis.transpose();
        rhs += basis * along;
        result.time.push_back(t);
        result.along.push_back(along);
    }
    result.fitted_acceleration = normal_matrix.ldlt().solve(rhs)[2];
    result.displacement = result.along.empty() ? 0.0 : result.along.back();
    return result;
}

LayerSlide sliding_layer(double cell_size, double thickness, double friction_angle_deg) {
    if (!(cell_size > 0.0) || !(thickness > 0.0)) {
        throw std::invalid_argument("sliding_layer: cell size and thickness must be > 0");
    }
    const double length = 1.0;
    const double v0 = 1.0;
    const double h = cell_size;
    Particles<2> layer;
    add_box_particles<2>(layer, axis_box(Vec3(0.0, -0.5, 0.0), Vec3(length, 0.5, thickness)),
                         h / 2.0, kSoilDensity);
    for (Vec<2>& v : layer.velocity) v = Vec<2>(v0, 0.0);
    SolverSettings s;
    s.threads = 1;
    s.cell_size = h;
    // Node planes on the floor (z = 0).
    s.domain_min = Vec3(-0.2, 0.0, -4.0 * h);
    s.domain_max = Vec3(length + 0.6, 0.0, thickness + 0.2);
    const double mu = std::tan(to_radians(friction_angle_deg));
    Solver<2> solver(s, verification_soil(), std::move(layer), {floor_solid(mu)});
    set_geostatic_stress<2>(solver.particles(), thickness, g, kSoilK0);
    const double mass = solver.particles().total_mass();
    // Least-squares line v = v0 - a t through the mean velocity of every step.
    LineSums line;
    while (solver.time() < 1.0) {
        solver.step(solver.stable_time_step());
        const double v = solver.particles().momentum()[0] / mass;
        if (v < 0.5 * v0) break;
        line.add(solver.time(), v);
    }
    LayerSlide result;
    result.fitted_deceleration = -line.slope();
    result.expected_deceleration = mu * g;
    return result;
}

}  // namespace rockfall::mpm::verification
