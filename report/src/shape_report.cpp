// What `rockfall shape` prints (see shape_report.hpp).

#include "report/shape_report.hpp"

#include "report/text_format.hpp"

#include <algorithm>

namespace rockfall::report {

void print_shape_text(std::ostream& out, const ShapeView& shape, const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    const shapes::RockGeometry& rock = *shape.rock;
    constexpr double density = kShapeReportDensity;
    out << "shape: " << shape.label << " (" << shape.source << ")\n"
        << "kind: " << shapes::to_string(rock.kind) << '\n'
        << "volume-equivalent diameter: " << short_number(m.equivalent_diameter) << " m\n"
        << "volume: " << short_number(p.volume) << " m3\n"
        << "surface area: " << short_number(p.surface_area) << " m2\n"
        << "centre of mass (body frame): " << triple(p.centroid) << " m\n"
        << "principal moments per unit density: " << triple(p.principal_moments) << " m5\n"
        << "principal moments at density " << short_number(density)
        << " kg/m3: " << triple(density * p.principal_moments) << " kg m2\n"
        << "mass at density " << short_number(density)
        << " kg/m3: " << short_number(density * p.volume) << " kg\n"
        << "axis lengths a b c: " << triple(m.axis_lengths) << " m\n"
        << "elongation b/a: " << short_number(m.elongation) << '\n'
        << "flatness c/b: " << short_number(m.flatness) << '\n'
        << "Wadell sphericity: " << short_number(m.wadell_sphericity) << '\n'
        << "Krumbein sphericity: " << short_number(m.krumbein_sphericity) << '\n';
    if (shape.stretch)
        out << "stretch t (axes 1 : t : t^2): " << short_number(*shape.stretch) << '\n';
    out << "hull: " << rock.hull.vertices.size() << " vertices, " << rock.hull.triangles.size()
        << " triangles"
        << (rock.radius > 0.0 ? " (display only: simulated as an exact sphere)" : "") << '\n';
}

nlohmann::json shape_json(const ShapeView& shape, const shapes::ShapeMeasures& m) {
    const shapes::MassProperties& p = m.properties;
    const shapes::RockGeometry& rock = *shape.rock;
    constexpr double density = kShapeReportDensity;
    const auto array = [](const shapes::Vec3& v) { return nlohmann::json{v[0], v[1], v[2]}; };
    nlohmann::json out = {{"name", shape.label},
                          {"source", shape.source},
                          {"kind", shapes::to_string(rock.kind)},
                          {"equivalent_diameter_m", m.equivalent_diameter},
                          {"volume_m3", p.volume},
                          {"surface_area_m2", p.surface_area},
                          {"centroid_m", array(p.centroid)},
                          {"principal_moments_per_density_m5", array(p.principal_moments)},
                          {"density_kg_m3", density},
                          {"principal_moments_kg_m2", array(density * p.principal_moments)},
                          {"mass_kg", density * p.volume},
                          {"axis_lengths_m", array(m.axis_lengths)},
                          {"elongation", m.elongation},
                          {"flatness", m.flatness},
                          {"wadell_sphericity", m.wadell_sphericity},
                          {"krumbein_sphericity", m.krumbein_sphericity},
                          {"hull_vertices", rock.hull.vertices.size()},
                          {"hull_triangles", rock.hull.triangles.size()},
                          {"exact_sphere", rock.radius > 0.0}};
    if (shape.stretch) out["stretch"] = *shape.stretch;
    return out;
}

void print_catalogue_header(std::ostream& out, const std::string& catalogue) {
    out << "catalogue " << catalogue << "\n"
        << "name                 D (m)      Wadell  Krumbein  a b c (m)\n";
}

void print_catalogue_row(std::ostream& out, const ShapeView& shape,
                         const shapes::ShapeMeasures& m) {
    std::string name = shape.label;
    name.resize(std::max<std::size_t>(name.size(), 20), ' ');
    out << name << ' ' << fmt("%-10.4g", m.equivalent_diameter) << ' '
        << fmt("%-7.3f", m.wadell_sphericity) << ' ' << fmt("%-9.3f", m.krumbein_sphericity) << ' '
        << triple(m.axis_lengths) << '\n';
}

std::string shape_mesh_header(const ShapeView& shape) {
    std::string text = "rockfall shape: " + shape.label + " (" + shape.source +
                       ")\nthe simulated hull in the body frame (m; centroid at the origin, "
                       "principal axes along x, y, z, long axis x)";
    if (shape.rock->radius > 0.0) {
        text += "\ndisplay tessellation: the engine simulates an exact sphere of radius " +
                short_number(shape.rock->radius) + " m";
    }
    return text;
}

}  // namespace rockfall::report
