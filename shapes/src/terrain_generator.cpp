#include "shapes/random.hpp"
#include "shapes/slope.hpp"
#include "shapes/terrain.hpp"

#include <cmath>
#include <numbers>
#include <sstream>

namespace rockfall::shapes {
namespace {

// Plane waves summed into the relief: enough for an irregular surface, few enough to stay
// smooth at the shortest wavelength.
constexpr int kWaves = 12;
// Longest over shortest wavelength of the relief.
constexpr double kWavelengthSpan = 8.0;

void check_grid(const TerrainGrid& grid) {
    std::ostringstream problem;
    if (!(std::isfinite(grid.spacing) && grid.spacing > 0.0)) {
        problem << "spacing = " << grid.spacing << " m: must be finite and > 0";
    } else if (!(std::isfinite(grid.margin) && grid.margin >= 0.0)) {
        problem << "margin = " << grid.margin << " m: must be finite and >= 0";
    } else if (!(std::isfinite(grid.roughness) && grid.roughness >= 0.0)) {
        problem << "roughness = " << grid.roughness << " m: must be finite and >= 0";
    } else if (!(std::isfinite(grid.wavelength) && grid.wavelength >= 2.0 * grid.spacing)) {
        problem << "wavelength = " << grid.wavelength << " m: must be >= twice the spacing ("
                << 2.0 * grid.spacing << " m), or the grid cannot resolve the relief";
    }
    if (!problem.str().empty()) throw GeometryError("terrain grid: " + problem.str());
}

// Stations from `from` to `to` (both included except `to` when `last` is false) with steps of
// at most `spacing`.
void subdivide(double from, double to, double spacing, bool last, std::vector<double>& out) {
    const int steps = std::max(1, static_cast<int>(std::ceil(std::abs(to - from) / spacing)));
    for (int k = 0; k < steps + (last ? 1 : 0); ++k) {
        out.push_back(from + (to - from) * static_cast<double>(k) / steps);
    }
}

// A smooth random relief of root-mean-square height `roughness`: plane waves with log-uniform
// wavelengths, uniform directions and phases, amplitudes proportional to the wavelength (longer
// undulations are higher, as on natural slopes).
class Relief {
  public:
    explicit Relief(const TerrainGrid& grid) {
        std::mt19937_64 random = make_generator(grid.seed);
        double power = 0.0;
        for (Wave& wave : waves_) {
            const double wavelength =
                grid.wavelength * std::pow(kWavelengthSpan, uniform01(random));
            const double direction = 2.0 * std::numbers::pi * uniform01(random);
            const double k = 2.0 * std::numbers::pi / wavelength;
            wave = {k * std::cos(direction), k * std::sin(direction),
                    2.0 * std::numbers::pi * uniform01(random), wavelength};
            // A cosine of amplitude A has mean square A^2 / 2.
            power += 0.5 * wavelength * wavelength;
        }
        const double factor = power > 0.0 ? grid.roughness / std::sqrt(power) : 0.0;
        for (Wave& wave : waves_) wave.amplitude *= factor;
    }

    double operator()(double x, double y) const {
        double z = 0.0;
        for (const Wave& wave : waves_) {
            z += wave.amplitude * std::cos(wave.kx * x + wave.ky * y + wave.phase);
        }
        return z;
    }

  private:
    struct Wave {
        double kx = 0.0;
        double ky = 0.0;
        double phase = 0.0;
        double amplitude = 0.0;
    };
    std::array<Wave, kWaves> waves_{};
};

}  // namespace

TriangleMesh profile_terrain(const SlopeSpec& spec, const TerrainGrid& grid) {
    check_grid(grid);
    const Slope slope(spec);
    const std::vector<Eigen::Vector2d>& profile = slope.profile();

    // Along x: the margin before the crown, each segment split into steps of at most `spacing`
    // along its surface (so that every kink is a vertex row), the margin after the end.
    std::vector<double> xs;
    if (grid.margin > 0.0) subdivide(-grid.margin, 0.0, grid.spacing, false, xs);
    for (std::size_t i = 0; i < spec.segments.size(); ++i) {
        const double cos_angle = std::cos(spec.segments[i].angle_deg * std::numbers::pi / 180.0);
        const double step = grid.spacing * cos_angle;
        subdivide(profile[i].x(), profile[i + 1].x(), step, false, xs);
    }
    if (grid.margin > 0.0) {
        subdivide(slope.end_x(), slope.end_x() + grid.margin, grid.spacing, true, xs);
    } else {
        xs.push_back(slope.end_x());
    }
    std::vector<double> ys;
    const double half = 0.5 * spec.width + grid.margin;
    subdivide(-half, half, grid.spacing, true, ys);

    const Relief relief(grid);
    TriangleMesh mesh;
    mesh.vertices.reserve(xs.size() * ys.size());
    for (const double x : xs) {
        // The profile is flat beyond its ends (surface_height clamps).
        const double z = slope.surface_height(x);
        for (const double y : ys) mesh.vertices.emplace_back(x, y, z + relief(x, y));
    }
    const auto rows = static_cast<int>(ys.size());
    const auto index = [rows](int i, int j) { return i * rows + j; };
    for (int i = 0; i + 1 < static_cast<int>(xs.size()); ++i) {
        for (int j = 0; j + 1 < rows; ++j) {
            // Counter-clockwise seen from above (normals up); the diagonal alternates so that
            // the triangulation has no preferred direction.
            if ((i + j) % 2 == 0) {
                mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i + 1, j + 1)});
                mesh.triangles.push_back({index(i, j), index(i + 1, j + 1), index(i, j + 1)});
            } else {
                mesh.triangles.push_back({index(i, j), index(i + 1, j), index(i, j + 1)});
                mesh.triangles.push_back({index(i + 1, j), index(i + 1, j + 1), index(i, j + 1)});
            }
        }
    }
    return mesh;
}

}  // namespace rockfall::shapes
