#pragma once
/// Soil materials: parameters as a user gives them, and the stress-update strategies.
///
/// Stress is the Cauchy stress, tension positive, in Pa; p = tr(sigma)/3 is the mean stress
/// (negative in compression) and q = sqrt(J2) the deviatoric stress invariant.
/// The update is in small-strain rate form: the stress is first co-rotated with the material
/// spin (Jaumann rate, done by the solver), then an elastic predictor with the strain increment
/// D dt is returned to the yield surface (de Souza Neto, Peric and Owen 2008, Computational
/// Methods for Plasticity, ch. 8, Drucker-Prager return to the smooth cone; perfectly
/// plastic; the same hypoelastic-plastic update is used in MPM by Zhang, Chen and Liu 2016,
/// The Material Point Method, ch. 4).

#include "mpm/math.hpp"

#include <algorithm>
#include <cmath>
#include <variant>

namespace rockfall::mpm {

/// How the Drucker-Prager cone is matched to the Mohr-Coulomb friction angle and cohesion
/// (de Souza Neto et al. 2008, ch. 6, Drucker-Prager approximations to Mohr-Coulomb).
enum class ConeMatch {
    /// Outer cone: agrees with Mohr-Coulomb in triaxial compression.
    compression,
    /// Inner cone: agrees with Mohr-Coulomb in triaxial extension.
    extension,
    /// Plane-strain match: same collapse load as Mohr-Coulomb in plane strain.
    plane_strain,
};

/// Isotropic linear (hypo)elastic material, for verification tests.
struct LinearElastic {
    /// Young's modulus, Pa (> 0).
    double youngs_modulus = 1.0e6;
    /// Poisson's ratio, [0, 0.5).
    double poisson_ratio = 0.30;
};

/// Elastic-perfectly plastic Drucker-Prager soil; defaults are the seed's Table 1
/// (seed 000: crushed stone of the soil-flow experiment).
struct DruckerPrager {
    /// Young's modulus, Pa (> 0); seed 1.0e3 kN/m2.
    double youngs_modulus = 1.0e6;
    /// Poisson's ratio, [0, 0.5); seed 0.30.
    double poisson_ratio = 0.30;
    /// Internal friction angle (Mohr-Coulomb), degrees, [0, 70]; seed 34.6.
    double friction_angle_deg = 34.6;
    /// Dilatancy angle of the plastic potential, degrees, [0, friction angle]; seed 0.
    double dilatancy_angle_deg = 0.0;
    /// Cohesion (Mohr-Coulomb), Pa (>= 0); seed 2.10 kN/m2.
    double cohesion = 2.10e3;
    /// Tensile strength: cut-off on the mean stress p, Pa (>= 0), capped at the cone's apex;
    /// seed 0.
    double tensile_strength = 0.0;
    /// Cone matching to Mohr-Coulomb.
    ConeMatch match = ConeMatch::plane_strain;
};

/// A material choice: the strategy used in the solver's stress-update phase.
using Material = std::variant<LinearElastic, DruckerPrager>;

/// Checks the parameters; throws std::invalid_argument naming the first field out of range
/// (`where` prefixes the field name, e.g. "material.").
void validate(const Material& material, const char* where = "material.");

/// P-wave (constrained) modulus lambda + 2 mu, Pa: sets the elastic wave speed of the CFL.
double p_wave_modulus(const Material& material);

/// Drucker-Prager cone coefficients for f = q + eta p - xi c (q = sqrt(J2)).
struct ConeCoefficients {
    /// Pressure coefficient eta (dimensionless, >= 0).
    double eta = 0.0;
    /// Cohesion coefficient xi (dimensionless, > 0).
    double xi = 0.0;
};

/// Cone coefficients for a Mohr-Coulomb angle in degrees (de Souza Neto et al. 2008, ch. 6):
/// compression eta = 6 sin(phi) / (sqrt(3) (3 - sin(phi))),
/// xi = 6 cos(phi) / (sqrt(3) (3 - sin(phi))); extension the same with 3 + sin(phi);
/// plane strain eta = 3 tan(phi) / sqrt(9 + 12 tan^2(phi)), xi = 3 / sqrt(9 + 12 tan^2(phi)).
ConeCoefficients cone_coefficients(double angle_deg, ConeMatch match);

/// Linear elastic stress update (Hooke's law on the strain increment).
class LinearElasticModel {
  public:
    /// From validated parameters.
    explicit LinearElasticModel(const LinearElastic& params);

    /// New stress from the co-rotated stress and the strain increment D dt;
    /// `plastic_shear_strain` is left unchanged.
    Mat3 update(const Mat3& stress, const Mat3& strain_increment,
                [[maybe_unused]] double& plastic_shear_strain) const {
        return stress + lambda_ * strain_increment.trace() * Mat3::Identity() +
               2.0 * shear_ * strain_increment;
    }

  private:
    double lambda_;
    double shear_;
};

/// Drucker-Prager return mapping, perfectly plastic, non-associated (dilatancy angle for the
/// flow potential g = q + eta_bar p), with a tension cut-off on the mean stress.
class DruckerPragerModel {
  public:
    /// From validated parameters.
    explicit DruckerPragerModel(const DruckerPrager& params);

    /// Yield function f = q + eta p - xi c, Pa (> 0 outside the cone).
    double yield_function(const Mat3& stress) const;
    /// Highest admissible mean stress, Pa: min(tensile strength, apex xi c / eta).
    double tension_cutoff() const { return tension_cutoff_; }

    /// New stress from the co-rotated stress and the strain increment D dt; adds the plastic
    /// multiplier increment (engineering plastic shear strain in simple shear) to
    /// `plastic_shear_strain`.
    Mat3 update(const Mat3& stress, const Mat3& strain_increment,
                double& plastic_shear_strain) const {
        // Plain arrays (column-major, as Eigen stores Mat3): this runs once per particle and
        // step, and Eigen's coefficient asserts stay on in RelWithDebInfo.
        const double* sigma = stress.data();
        const double* e = strain_increment.data();
        const double volumetric = lambda_ * (e[0] + e[4] + e[8]);
        double s[9];
        for (int i = 0; i < 9; ++i) {
            s[i] = sigma[i] + 2.0 * shear_ * e[i];
        }
        const double p = (s[0] + s[4] + s[8]) / 3.0 + volumetric;
        const double trial_mean = (s[0] + s[4] + s[8]) / 3.0;
        s[0] -= trial_mean;
        s[4] -= trial_mean;
        s[8] -= trial_mean;
        double norm2 = 0.0;
        for (int i = 0; i < 9; ++i) {
            norm2 += s[i] * s[i];
        }
        const double q = std::sqrt(0.5 * norm2);
        double scale = 1.0;
        double mean = p;
        if (p > tension_cutoff_) {
            // Tension cut-off: the mean stress is held at the cut-off and the deviator is
            // scaled back onto the cone at that pressure.
            const double q_limit = std::max(0.0, xi_c_ - eta_ * tension_cutoff_);
            if (q > q_limit) {
                plastic_shear_strain += (q - q_limit) / shear_;
                scale = q_limit / q;
            }
            mean = tension_cutoff_;
        } else {
            const double f = q + eta_ * p - xi_c_;
            if (f > 0.0) {
                // Return to the smooth cone (de Souza Neto et al. 2008, ch. 8, with no
                // hardening): dgamma = f / (G + K eta eta_bar). Below the cut-off p <= apex, so
                // q - G dgamma >= 0 and the apex return is never needed.
                const double dgamma = f / (shear_ + bulk_ * eta_ * eta_bar_);
                scale = std::max(0.0, 1.0 - shear_ * dgamma / q);
                mean = p - bulk_ * eta_bar_ * dgamma;
                plastic_shear_strain += dgamma;
            }
        }
        Mat3 out;
        double* o = out.data();
        for (int i = 0; i < 9; ++i) {
            o[i] = scale * s[i];
        }
        o[0] += mean;
        o[4] += mean;
        o[8] += mean;
        return out;
    }

  private:
    double lambda_;
    double shear_;
    double bulk_;
    double eta_;
    double eta_bar_;
    double xi_c_;
    double tension_cutoff_;
};

}  // namespace rockfall::mpm
