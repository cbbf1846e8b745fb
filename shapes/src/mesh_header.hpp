#pragma once
// Checks of a mesh file's header before assimp reads it (private to the shapes library): a
// header assimp would loop on or over-allocate for is refused at once, with the rule it breaks.

#include <filesystem>
#include <string>

namespace rockfall::shapes {

/// Throws GeometryError naming the file when its header breaks its format's rules; `extension`
/// is the file's lower-case extension (".ply"). Formats without a checked header pass.
void check_mesh_header(const std::filesystem::path& file, const std::string& extension);

}  // namespace rockfall::shapes
