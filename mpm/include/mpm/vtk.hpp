#pragma once
/// Particle output for ParaView.

#include "mpm/soil.hpp"

#include <filesystem>

namespace rockfall::mpm {

/// Writes a particle frame as a legacy binary VTK POLYDATA file (points with one vertex cell
/// each; point data: velocity in m/s, mass in kg, mean_stress and deviatoric_stress in Pa,
/// plastic_shear_strain); the frame's time is in the header line. Throws std::runtime_error
/// naming the file when it cannot be written.
void write_vtk(const std::filesystem::path& file, const ParticleFrame& frame);

}  // namespace rockfall::mpm
