#pragma once
/// Material points, stored as one array per field (struct of arrays).

#include "mpm/math.hpp"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace rockfall::mpm {

/// The material points of one simulation. In 2D (plane strain) masses and volumes are per metre
/// of out-of-plane width (kg/m, m2/m). All arrays have the same length.
template <int Dim>
struct Particles {
    /// Position, m.
    std::vector<Vec<Dim>> position;
    /// Velocity, m/s.
    std::vector<Vec<Dim>> velocity;
    /// APIC affine velocity C (Jiang et al. 2015), the particle's velocity gradient, 1/s.
    std::vector<Mat<Dim>> affine;
    /// Cauchy stress, Pa, tension positive (3x3 also in 2D: index 2 is out of plane).
    std::vector<Mat3> stress;
    /// Mass, kg (> 0).
    std::vector<double> mass;
    /// Current volume, m3 (> 0).
    std::vector<double> volume;
    /// Accumulated plastic shear strain (plastic multiplier), dimensionless (>= 0).
    std::vector<double> plastic_shear_strain;

    /// Number of particles.
    std::size_t size() const { return position.size(); }

    /// Appends a point at rest with zero stress: position m, volume m3 (> 0), density kg/m3
    /// (> 0).
    void add(const Vec<Dim>& x, double point_volume, double density) {
        position.push_back(x);
        velocity.push_back(Vec<Dim>::Zero());
        affine.push_back(Mat<Dim>::Zero());
        stress.push_back(Mat3::Zero());
        mass.push_back(point_volume * density);
        volume.push_back(point_volume);
        plastic_shear_strain.push_back(0.0);
    }

    /// Total mass, kg.
    double total_mass() const {
        double sum = 0.0;
        for (const double m : mass) {
            sum += m;
        }
        return sum;
    }

    /// Total linear momentum, kg m/s.
    Vec<Dim> momentum() const {
        Vec<Dim> sum = Vec<Dim>::Zero();
        for (std::size_t p = 0; p < size(); ++p) {
            sum += mass[p] * velocity[p];
        }
        return sum;
    }

    /// Total kinetic energy, J (J/m in 2D).
    double kinetic_energy() const {
        double sum = 0.0;
        for (std::size_t p = 0; p < size(); ++p) {
            sum += 0.5 * mass[p] * velocity[p].squaredNorm();
        }
        return sum;
    }

    /// Front: the largest x, m (downslope in the soil flow, along the collapse); -infinity
    /// without particles.
    double front() const {
        double x = -std::numeric_limits<double>::infinity();
        for (const Vec<Dim>& p : position) {
            x = std::max(x, p[0]);
        }
        return x;
    }

    /// Centre of mass, m (the particles must not be empty).
    Vec<Dim> centre_of_mass() const {
        Vec<Dim> sum = Vec<Dim>::Zero();
        for (std::size_t p = 0; p < size(); ++p) {
            sum += mass[p] * position[p];
        }
        return sum / total_mass();
    }
};

}  // namespace rockfall::mpm
