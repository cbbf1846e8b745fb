#pragma once
/// Impact design formulas for a rock hitting the soil cushion (fill layer) on the roof of a
/// rock shed or gallery: the peak (or equivalent static) force on the cushion.
///
/// Both are Hertz-type laws, F ~ M_E^(2/5) R^(1/5) (kinetic energy)^(3/5), like the Japan Road
/// Association formula (formulas.hpp), but written with the cushion's plate-load modulus M_E
/// instead of a Lame constant and with the block radius instead of its mass^(1/3). Their
/// numeric factors only work in the units they were published in (kN, kN/m2, m, t, kJ): the
/// functions take SI units and convert inside.
///
/// Sources. The forms below are transcribed from their citations in Schellenberg, "On the
/// design of rockfall protection galleries" (ETH Zurich thesis, 2009) and Volkwein et al.,
/// "Rockfall characterisation and structural protection - a review", Nat. Hazards Earth Syst.
/// Sci. 11 (2011) 2617-2651. The primary texts (Labiouse et al. 1996; ASTRA 12 006, edition
/// 2008 V2.03) could not be read while this was written: check the coefficients against them
/// before a design relies on these functions.

namespace rockfall::risk {

/// Inputs of the Labiouse et al. (1996) cushion formula, in SI units.
struct LabiouseInputs {
    /// Rock mass, kg (> 0).
    double mass = 0.0;
    /// Impact velocity, m/s (> 0).
    double velocity = 0.0;
    /// Rock radius R (of the volume-equivalent sphere), m (> 0).
    double radius = 0.0;
    /// Plate-load modulus M_E of the cushion, Pa (> 0); the formula uses it in kN/m2.
    double cushion_modulus = 0.0;
};

/// Labiouse, Descoeudres and Montani (1996), "Experimental study of rock sheds impacted by
/// rock blocks", Structural Engineering International 6(3), 171-176:
///   F = 1.765 M_E^(2/5) R^(1/5) (W H)^(3/5)   [kN]
/// with M_E in kN/m2, R in m, W = m g the block weight in kN and H the fall height in m, so
/// W H = m v^2 / 2 is the kinetic energy in kJ and g drops out. Returns F in N.
/// Validity: Hertz contact of a rigid sphere on an elastic half-space, fitted to 1:1 drop tests
/// of blocks up to about 1 t from heights up to about 10 m onto gravel cushions (as reported
/// by the citing works); the cushion must be thick compared with the block (no thickness term).
/// Throws std::invalid_argument naming the field, value, unit and allowed range.
double labiouse_impact_force(const LabiouseInputs& inputs);

/// Inputs of the ASTRA (2008) gallery formula, in SI units.
struct AstraInputs {
    /// Rock mass m_k, kg (> 0); the formula uses it in tonnes.
    double mass = 0.0;
    /// Impact velocity v_k, m/s (> 0).
    double velocity = 0.0;
    /// Equivalent block radius r, m (> 0).
    double radius = 0.0;
    /// Plate-load modulus M_E of the cushion, Pa (> 0); the formula uses it in kN/m2.
    double cushion_modulus = 0.0;
    /// Cushion thickness e, m (> 0).
    double cushion_thickness = 0.0;
    /// Internal friction angle phi_k of the cushion material, degrees, in (0, 90).
    double friction_angle_deg = 0.0;
};

/// Swiss Federal Roads Office (ASTRA/FEDRO) with SBB, guideline ASTRA 12 006 "Einwirkungen
/// infolge Steinschlags auf Schutzgalerien" (Actions from rockfall on protection galleries),
/// edition 2008 V2.03, equivalent static force of the impact:
///   F_k = 2.8 e^(-1/2) r^(7/10) M_E^(2/5) tan(phi_k)^(1/5) (m_k v_k^2 / 2)^(3/5)   [kN]
/// with e and r in m, M_E in kN/m2, m_k in t and v_k in m/s (so m_k v_k^2 / 2 is in kJ).
/// Returns F_k in N: a characteristic value, before the guideline's design factors, which
/// are not applied here. Validity: gravel or soil cushions on galleries (the citing works trace
/// it to the EPFL drop tests behind Labiouse et al.); the e^(-1/2) term diverges as e -> 0, so
/// it is meant for cushions of the order of the block diameter or thicker. Throws
/// std::invalid_argument naming the field, value, unit and allowed range.
double astra_impact_force(const AstraInputs& inputs);

/// Radius of the sphere with the volume of a rock of the given mass (kg, > 0) and density
/// (kg/m3, > 0), in m: r = (3 m / (4 pi rho))^(1/3). Throws std::invalid_argument otherwise.
double equivalent_radius(double mass, double density);

}  // namespace rockfall::risk
