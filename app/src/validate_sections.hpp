#pragma once
/// The sections of `rockfall validate`'s verification and validation report that the program
/// computes itself (report/vv_report.hpp has the page): the engine's analytic checks, mass
/// properties and sphericities, the MPM solver's cases, seed 000's identified coefficients and
/// the calibration tests. Each runs in-process and fills its checks with reference, source,
/// simulated value, tolerance and the tolerance's reason.

#include "report/vv_report.hpp"

namespace rockfall::app {

/// What to run.
struct VvOptions {
    /// The --quick subset (the heap test is left out); everything else runs in both.
    bool quick = false;
    /// Worker threads for the drop and heap tests (>= 1).
    int threads = 1;
};

/// Free fall, sliding, rolling, bounces at two step sizes; the wall's impulse, Hertz and
/// spring-dashpot peak forces (engine/verification_scenes.hpp). Two figures.
report::VvSection engine_section(const VvOptions& options);

/// Volume, area, moment of inertia and Wadell sphericity of the five Platonic solids against
/// their closed forms; generated rocks against their target sphericity.
report::VvSection shapes_section(const VvOptions& options);

/// The elastic bar, the column at rest (K0), the column collapse and the sliding block
/// (mpm/verification.hpp). Three figures.
report::VvSection mpm_section(const VvOptions& options);

/// Seed 000's lambda, alpha and beta identified (as `rockfall fit` does) on direct wall
/// impacts against the 2.95 GPa facing. One figure.
report::VvSection seed000_section(const VvOptions& options);

/// Seed 001's drop test (restitution identified for the paper's mean COR 0.30) and, in the
/// full run, its heap test (angle of repose 25.2 deg at the paper's DEM friction).
report::VvSection calibration_section(const VvOptions& options);

}  // namespace rockfall::app
