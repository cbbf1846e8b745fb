#pragma once
/// What `rockfall terrain` prints: a scenario's terrain mesh (size, bounding box, height above
/// the reference profile) or, for a scenario without one, its triangulated profile; and the
/// comment at the top of the OBJ file it writes. Lengths in m.

#include "shapes/terrain.hpp"

#include <nlohmann/json.hpp>

#include <ostream>
#include <string>

namespace rockfall::report {

/// A scenario's terrain mesh and its departure from the profile.
void print_terrain_text(std::ostream& out, const std::string& scenario,
                        const shapes::Terrain& terrain, const shapes::ProfileDeviation& deviation);
nlohmann::json terrain_json(const std::string& scenario, const shapes::Terrain& terrain,
                            const shapes::ProfileDeviation& deviation);

/// A scenario without a terrain: the size of its triangulated profile.
void print_profile_mesh_text(std::ostream& out, const std::string& scenario,
                             const shapes::TriangleMesh& mesh);
nlohmann::json profile_mesh_json(const std::string& scenario, const shapes::TriangleMesh& mesh);

/// The OBJ comment of a scenario's terrain mesh ("as the engine simulates it"), and of a
/// triangulated profile with the grid it was made with; `file` is the scenario's file name.
std::string terrain_mesh_comment(const std::string& file, const shapes::Terrain& terrain);
std::string profile_mesh_comment(const std::string& file, const shapes::TerrainGrid& grid);

}  // namespace rockfall::report
