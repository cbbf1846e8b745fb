#pragma once
/// What `rockfall shape` prints about one rock: its measures as text or JSON, a catalogue
/// listing, and the header written into its hull files. Lengths in m, areas in m2, volumes in
/// m3, moments per unit density in m5 and at the report density in kg m2.

#include "shapes/measures.hpp"
#include "shapes/rocks.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <ostream>
#include <string>

namespace rockfall::report {

/// Density for the moments and mass in kg: a common granite value, 2600 kg/m3 (the moments per
/// unit density are printed too).
inline constexpr double kShapeReportDensity = 2600.0;

/// One rock to report on.
struct ShapeView {
    /// What it is: "massive", "cube", "mesh rock.obj", "catalogue entry 'a'", ...
    std::string label;
    /// How it was made: file, catalogue entry, generator and seed.
    std::string source;
    /// The rock as the engine simulates it.
    const shapes::RockGeometry* rock = nullptr;
    /// The stretch t of a rock generated for a target sphericity.
    std::optional<double> stretch;
};

/// The readable summary of a rock's measures.
void print_shape_text(std::ostream& out, const ShapeView& shape, const shapes::ShapeMeasures& m);

/// The same as one JSON object (units in the key names).
nlohmann::json shape_json(const ShapeView& shape, const shapes::ShapeMeasures& m);

/// The header line of a catalogue listing.
void print_catalogue_header(std::ostream& out, const std::string& catalogue);

/// One row of a catalogue listing: name, D, Wadell and Krumbein sphericity, axes.
void print_catalogue_row(std::ostream& out, const ShapeView& shape, const shapes::ShapeMeasures& m);

/// The comment at the top of the rock's OBJ file: what it is and in which frame.
std::string shape_mesh_header(const ShapeView& shape);

}  // namespace rockfall::report
