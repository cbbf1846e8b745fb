#pragma once
// Shared by the tests of the wall contact on its own: the seed's wall box, E* of a spec and an
// RK4 step of a 1-DOF impact.

#include "engine/scenario.hpp"
#include "engine/wall_contact.hpp"
#include "shapes/slope.hpp"

#include <functional>

namespace rockfall::engine::test {

// The seed's wall: front face at x = 9.75 facing upslope (-x), 0.5 m thick, 1.5 m high.
inline shapes::OrientedBox seed_wall() {
    shapes::OrientedBox wall;
    wall.center = Vec3(10.0, 0.0, 0.75);
    wall.half_extents = Vec3(0.25, 2.5, 0.75);
    wall.role = shapes::SurfaceRole::reaction_wall;
    return wall;
}

// E* of the rock and wall moduli of `spec`, Pa.
inline double effective_modulus_of(const WallContact& spec) {
    return effective_modulus(spec.rock_youngs_modulus, spec.rock_poisson_ratio,
                             spec.wall_youngs_modulus, spec.wall_poisson_ratio);
}

// Position (m) and velocity (m/s) of a 1-DOF motion x'' = acceleration(x, x').
struct Motion {
    double x = 0.0;
    double v = 0.0;
};

// One classical Runge-Kutta step of length dt (s).
inline Motion rk4_step(const std::function<double(double x, double v)>& acceleration,
                       const Motion& s, double dt) {
    const double k1x = s.v;
    const double k1v = acceleration(s.x, s.v);
    const double k2x = s.v + 0.5 * dt * k1v;
    const double k2v = acceleration(s.x + 0.5 * dt * k1x, s.v + 0.5 * dt * k1v);
    const double k3x = s.v + 0.5 * dt * k2v;
    const double k3v = acceleration(s.x + 0.5 * dt * k2x, s.v + 0.5 * dt * k2v);
    const double k4x = s.v + dt * k3v;
    const double k4v = acceleration(s.x + dt * k3x, s.v + dt * k3v);
    return {s.x + dt / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
            s.v + dt / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v)};
}

}  // namespace rockfall::engine::test
