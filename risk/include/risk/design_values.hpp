#pragma once
/// Design values of a falling rock in the manner of the Italian standard UNI 11211-4:2012
/// ("Opere di difesa dalla caduta massi - Parte 4: Progetto definitivo ed esecutivo"): a
/// characteristic percentile of the speed and of the bounce (passing) height from a sample of
/// trajectories, multiplied by partial factors, gives the design speed, height and energy a
/// barrier or wall is checked against:
///   v_d = v_t gamma_Tr gamma_Dp        h_d = h_t gamma_Tr gamma_Dp
///   m_d = m gamma_VolF1 gamma_gamma    E_d = m_d v_d^2 / 2
/// with v_t and h_t the percentile (95th by default) of the sample. The resistance side (the
/// barrier's energy class divided by gamma_E, its height minus the free margin f_min) is the
/// designer's and is not computed here.
///
/// Source of the factors: the standard as summarised by Peila and Ronco, "Technical Note:
/// Design of rockfall net fences and the new ETAG 027 European guideline", Nat. Hazards Earth
/// Syst. Sci. 9 (2009) 1291-1298, and by the UNI 11211-4 design page of the Rocscience RocFall
/// manual; the standard itself (paywalled) was not read.

#include <cstddef>
#include <string>
#include <vector>

namespace rockfall::risk {

/// Partial factors on the action side (each finite and >= 1, dimensionless). The defaults are
/// the standard's less favourable class of each, because a simulation sweep is usually run
/// with contact parameters taken from the literature on an idealised slope; lower them to
/// 1.02 only with the evidence the standard asks for.
struct PartialFactors {
    /// gamma_Tr, reliability of the trajectory simulation: 1.02 when its restitution
    /// coefficients come from back-analysis of observed falls, 1.10 when from the literature.
    double trajectory = 1.10;
    /// gamma_Dp, quality of the slope survey: 1.02 for a high-quality topographic survey,
    /// 1.10 for a low-quality one.
    double survey = 1.10;
    /// gamma_VolF1, precision of the design-block volume survey: 1.02 precise, 1.10 not.
    double volume = 1.10;
    /// gamma_gamma, on the rock's unit weight: >= 1, generally 1.00.
    double unit_weight = 1.00;
};

/// A sample of trajectories as the standard reads it: one speed and one bounce height per rock.
struct DesignSample {
    /// Where it was read from, echoed in reports.
    std::string source;
    /// Speeds, m/s, and bounce (passing) heights, m, each >= 0.
    std::vector<double> speeds;
    std::vector<double> heights;
};

/// The design values and the characteristic values they come from.
struct DesignValues {
    /// Percentile used, as a fraction in (0, 1).
    double percentile = 0.95;
    /// Sample sizes of the speeds and the heights.
    std::size_t speed_count = 0;
    std::size_t height_count = 0;
    /// v_t, the percentile of the speeds, m/s.
    double characteristic_speed = 0.0;
    /// h_t, the percentile of the bounce heights, m.
    double characteristic_height = 0.0;
    /// v_d = v_t gamma_Tr gamma_Dp, m/s.
    double design_speed = 0.0;
    /// h_d = h_t gamma_Tr gamma_Dp, m.
    double design_height = 0.0;
    /// m_d = m gamma_VolF1 gamma_gamma, kg.
    double design_mass = 0.0;
    /// E_d = m_d v_d^2 / 2, J.
    double design_energy = 0.0;
};

/// Design values from a sample of speeds (m/s, each finite and >= 0, at least one) and bounce
/// heights (m, each finite and >= 0, at least one; the two samples may differ in size), the
/// design block's mass (kg, > 0), the percentile (fraction in (0, 1)) and the partial factors.
/// Percentiles are type 7 (risk::quantile). Throws std::invalid_argument on bad input.
DesignValues uni_design_values(const std::vector<double>& speeds,
                               const std::vector<double>& heights, double mass,
                               double percentile = 0.95, const PartialFactors& factors = {});

}  // namespace rockfall::risk
