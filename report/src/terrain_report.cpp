// The text and JSON of `rockfall terrain` (see terrain_report.hpp).

#include "report/terrain_report.hpp"

#include "report/text_format.hpp"

namespace rockfall::report {
namespace {

constexpr const char* kSlopeFrame = "slope frame (m): x downslope from the crown, y across, z up";

nlohmann::json array(const shapes::Vec3& v) { return nlohmann::json{v[0], v[1], v[2]}; }

}  // namespace

void print_terrain_text(std::ostream& out, const std::string& scenario,
                        const shapes::Terrain& terrain, const shapes::ProfileDeviation& d) {
    out << "terrain: " << terrain.name() << " (" << scenario << ")\n"
        << "mesh: " << terrain.mesh().vertices.size() << " vertices, "
        << terrain.mesh().triangles.size() << " triangles";
    if (terrain.dropped_triangles() > 0) {
        out << " (" << terrain.dropped_triangles() << " degenerate triangles dropped)";
    }
    out << "\nbounding box: " << triple(terrain.lower()) << " to " << triple(terrain.upper())
        << " m\nheight above the reference profile, " << d.vertices
        << " vertices over the footprint: largest |dz| " << short_number(d.max) << " m, rms "
        << short_number(d.rms) << " m\n";
}

nlohmann::json terrain_json(const std::string& scenario, const shapes::Terrain& terrain,
                            const shapes::ProfileDeviation& d) {
    return {{"scenario", scenario},
            {"name", terrain.name()},
            {"vertices", terrain.mesh().vertices.size()},
            {"triangles", terrain.mesh().triangles.size()},
            {"dropped_triangles", terrain.dropped_triangles()},
            {"lower_m", array(terrain.lower())},
            {"upper_m", array(terrain.upper())},
            {"profile_deviation_max_m", d.max},
            {"profile_deviation_rms_m", d.rms}};
}

void print_profile_mesh_text(std::ostream& out, const std::string& scenario,
                             const shapes::TriangleMesh& mesh) {
    out << "terrain: none (" << scenario
        << " uses its profile segments); triangulated profile: " << mesh.vertices.size()
        << " vertices, " << mesh.triangles.size() << " triangles\n";
}

nlohmann::json profile_mesh_json(const std::string& scenario, const shapes::TriangleMesh& mesh) {
    return {{"scenario", scenario},
            {"name", nullptr},
            {"vertices", mesh.vertices.size()},
            {"triangles", mesh.triangles.size()}};
}

std::string terrain_mesh_comment(const std::string& file, const shapes::Terrain& terrain) {
    return "rockfall terrain: " + terrain.name() + " of " + file + " as the engine simulates it\n" +
           kSlopeFrame;
}

std::string profile_mesh_comment(const std::string& file, const shapes::TerrainGrid& grid) {
    return "rockfall terrain: the reference profile of " + file + "\nspacing " +
           short_number(grid.spacing) + " m, margin " + short_number(grid.margin) +
           " m, relief rms " + short_number(grid.roughness) + " m, shortest wavelength " +
           short_number(grid.wavelength) + " m, seed " + std::to_string(grid.seed) + "\n" +
           kSlopeFrame;
}

}  // namespace rockfall::report
