#pragma once
// Builds the solver of a soil scenario (private to the soil run).

#include "mpm/soil.hpp"
#include "mpm/solver.hpp"
#include "shapes/slope.hpp"

#include <memory>

namespace rockfall::mpm::detail {

// Boundary groups of the soil scenario.
inline constexpr int kSlopeGroup = 0;
inline constexpr int kWallGroup = 1;
inline constexpr int kBedGroup = 2;

template <int Dim>
struct SoilModel {
    explicit SoilModel(const shapes::SlopeSpec& spec) : slope(spec) {}
    shapes::Slope slope;
    std::unique_ptr<Solver<Dim>> solver;
    double particle_spacing = 0.0;
};

// The scenario must be valid.
template <int Dim>
SoilModel<Dim> build_soil_model(const SoilScenario& scenario);

}  // namespace rockfall::mpm::detail
