#pragma once
/// The rock that `rockfall shape` describes: a mesh file, a catalogue entry, a family or
/// Platonic kind, or a generated rock, scaled as the command line says.

#include "shapes/catalogue.hpp"
#include "shapes/rocks.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rockfall::scenario {

/// What `rockfall shape` is asked to describe, as given on its command line.
struct ShapeRequest {
    std::optional<std::string> file;
    std::optional<std::string> kind;
    std::optional<std::string> generate;
    std::optional<std::string> entry;
    std::optional<double> size;
    std::optional<double> long_axis;
    std::optional<double> scale;
    std::optional<double> sphericity;
    std::optional<double> roughness;
    std::optional<int> points;
    std::vector<double> ratios;
    std::optional<std::uint64_t> seed;
};

/// One rock, ready to measure and write.
struct ShapeResult {
    /// What it is: "massive", "cube", "mesh rock.obj", "catalogue entry 'a'", ...
    std::string label;
    /// How it was made, for the report: file, catalogue entry, generator and seed.
    std::string source;
    /// The rock as the engine simulates it.
    shapes::RockGeometry rock;
    /// The stretch t of a rock generated for a target sphericity.
    std::optional<double> stretch;
};

/// Names accepted by --kind (families and Platonic solids) and by --generate.
std::vector<std::string> shape_kind_names();
std::vector<std::string> generator_names();

/// Whether `file` names a catalogue (a folder or a .toml file) rather than a mesh.
bool is_catalogue(const std::string& file);

/// The rock the arguments describe; throws std::invalid_argument for inconsistent options and
/// shapes::GeometryError for bad geometry. Not for a catalogue without --entry.
ShapeResult make_shape(const ShapeRequest& args);

/// Every entry of a catalogue at the sizes its entries give (or --size / --long-axis).
std::vector<ShapeResult> catalogue_shapes(const ShapeRequest& args);

}  // namespace rockfall::scenario
