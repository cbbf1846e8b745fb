#pragma once
/// Shape catalogues: named rock shapes, from a folder of mesh files or a TOML list.
///
/// A folder catalogue holds one entry per mesh file directly in the folder (see
/// is_mesh_file), named by the file name without its extension. A TOML catalogue lists
/// entries as
///
///     [[shape]]
///     name = "cube"            # unique, non-empty
///     file = "meshes/cube.obj" # relative to the catalogue file
///     scale = 0.001            # optional, file units to metres (default 1)
///     size = 0.2               # optional, volume-equivalent diameter, m
///     long_axis = 0.3          # optional, long axis, m (not together with size)
///
/// and nothing else. Meshes are read only when an entry is loaded.

#include "shapes/mesh_io.hpp"
#include "shapes/rocks.hpp"

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::shapes {

/// One named shape of a catalogue.
struct CatalogueEntry {
    /// Name the entry is looked up by.
    std::string name;
    /// The mesh file (relative paths already resolved against the catalogue's folder).
    std::filesystem::path file;
    /// Scaling of the mesh to metres and to a size.
    MeshScaling scaling;
    /// Where the entry was written, "catalogue.toml:12", or the mesh file for a folder.
    std::string origin;
};

/// A catalogue's entries, in file order (a folder's sorted by name).
struct ShapeCatalogue {
    /// The folder or TOML file it was read from.
    std::filesystem::path source;
    /// The entries; names are unique.
    std::vector<CatalogueEntry> entries;
};

/// Reads a catalogue: a folder of meshes, or a TOML file (any other file is an error). Checks
/// names, keys, types and values but reads no mesh. Throws GeometryError naming the
/// catalogue (and file:line for TOML) for a missing path, a TOML syntax error, an unknown key,
/// a wrong type or value, a duplicate name and a catalogue without entries.
ShapeCatalogue read_catalogue(const std::filesystem::path& source);

/// The entry called `name`; throws GeometryError listing the catalogue's names when absent.
const CatalogueEntry& find_entry(const ShapeCatalogue& catalogue, std::string_view name);

/// The entry's rock shape: the scaled hull of its mesh (read_mesh_hull), named after the
/// entry. Throws GeometryError naming the entry and its mesh file.
CustomShape load_entry(const CatalogueEntry& entry);

}  // namespace rockfall::shapes
