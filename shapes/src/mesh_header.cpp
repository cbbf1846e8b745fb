#include "mesh_header.hpp"

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <array>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

namespace rockfall::shapes {
namespace {

namespace fs = std::filesystem;

// The PLY format (Turk 1994, "The PLY Polygon File Format"): a header of text lines, `ply`,
// `format ascii|binary_little_endian|binary_big_endian 1.0`, then `comment`, `obj_info`,
// `element NAME COUNT` and `property TYPE NAME` / `property list COUNT_TYPE TYPE NAME` lines,
// ended by `end_header`; the data follow. A header is text, so one longer than this is not one.
constexpr std::size_t kMaxPlyHeaderBytes = std::size_t{1} << 20;

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::size_t properties = 0;
    // Bytes of one entry in a binary file, lists counted with no items (the least they take).
    std::uint64_t least_bytes = 0;
};

[[noreturn]] void refuse(const fs::path& file, const std::string& problem) {
    throw GeometryError("mesh file '" + file.string() + "': cannot be read as .ply: " + problem);
}

// Size in bytes of a PLY scalar type, 0 for an unknown name.
std::size_t scalar_bytes(std::string_view type) {
    static constexpr std::array<std::pair<std::string_view, std::size_t>, 16> types{{
        {"char", 1},
        {"uchar", 1},
        {"int8", 1},
        {"uint8", 1},
        {"short", 2},
        {"ushort", 2},
        {"int16", 2},
        {"uint16", 2},
        {"int", 4},
        {"uint", 4},
        {"int32", 4},
        {"uint32", 4},
        {"float", 4},
        {"float32", 4},
        {"double", 8},
        {"float64", 8},
    }};
    for (const auto& [name, bytes] : types) {
        if (name == type) return bytes;
    }
    return 0;
}

std::vector<std::string> words(const std::string& line) {
    std::istringstream in(line);
    std::vector<std::string> out;
    for (std::string word; in >> word;) out.push_back(word);
    return out;
}

std::string shown(const std::string& line) {
    return "\"" + (line.size() > 60 ? line.substr(0, 60) + "..." : line) + "\"";
}

void check_ply(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::error_code error;
    const std::uintmax_t file_bytes = fs::file_size(file, error);
    std::string line;
    std::size_t read = 0;
    int number = 0;
    bool binary = false;
    std::vector<PlyElement> elements;
    const auto next_line = [&]() -> bool {
        line.clear();
        for (char c; read < kMaxPlyHeaderBytes && in.get(c);) {
            ++read;
            if (c == '\n') {
                if (!line.empty() && line.back() == '\r') line.pop_back();
                ++number;
                return true;
            }
            line += c;
        }
        // A last line without its newline still counts, unless the header limit cut it.
        if (line.empty() || read >= kMaxPlyHeaderBytes) return false;
        ++number;
        return true;
    };
    if (!next_line() || line != "ply") {
        refuse(file, "a PLY file starts with the line `ply`, this one with " + shown(line));
    }
    if (!next_line()) refuse(file, "the header ends after `ply`, without a `format` line");
    const std::vector<std::string> format = words(line);
    if (format.size() != 3 || format[0] != "format" || format[2] != "1.0" ||
        (format[1] != "ascii" && format[1] != "binary_little_endian" &&
         format[1] != "binary_big_endian")) {
        refuse(file, "line 2 is " + shown(line) +
                         ", not `format ascii 1.0`, `format binary_little_endian 1.0` or `format "
                         "binary_big_endian 1.0`");
    }
    binary = format[1] != "ascii";
    for (;;) {
        if (!next_line()) {
            refuse(file, read >= kMaxPlyHeaderBytes
                             ? "no `end_header` line in its first " +
                                   std::to_string(kMaxPlyHeaderBytes >> 20) +
                                   " MiB (a PLY header is a few text lines ended by `end_header`)"
                             : "the header has no `end_header` line (the file ends at line " +
                                   std::to_string(number) + " without one)");
        }
        const std::vector<std::string> w = words(line);
        if (w.empty() || w[0] == "comment" || w[0] == "obj_info") continue;
        const std::string where = "line " + std::to_string(number) + " (" + shown(line) + "): ";
        if (w[0] == "end_header" && w.size() == 1) break;
        if (w[0] == "element") {
            PlyElement element;
            const char* end = w.size() == 3 ? w[2].data() + w[2].size() : nullptr;
            if (w.size() != 3 || std::from_chars(w[2].data(), end, element.count).ptr != end) {
                refuse(file, where + "an element line is `element NAME COUNT`, COUNT >= 0");
            }
            element.name = w[1];
            elements.push_back(element);
        } else if (w[0] == "property") {
            const bool list = w.size() == 5 && w[1] == "list";
            if (elements.empty()) refuse(file, where + "a property before any element");
            if (!(w.size() == 3 && scalar_bytes(w[1]) > 0) &&
                !(list && scalar_bytes(w[2]) > 0 && scalar_bytes(w[3]) > 0)) {
                refuse(file, where +
                                 "a property line is `property TYPE NAME` or `property list "
                                 "COUNT_TYPE TYPE NAME`, TYPE one of char, uchar, short, ushort, "
                                 "int, uint, float, double (or int8 ... float64)");
            }
            elements.back().properties += 1;
            elements.back().least_bytes += scalar_bytes(list ? w[2] : w[1]);
        } else {
            refuse(file, where +
                             "not a header line (comment, obj_info, element, property or "
                             "end_header); is the `end_header` line missing?");
        }
    }
    // What the header announces must fit in what follows it, before anything is allocated for
    // it: a binary entry takes its fixed bytes, an ASCII value at least a digit and a space
    // (the last one without its space).
    std::uint64_t left = (file_bytes > read ? file_bytes - read : 0) + (binary ? 0 : 1);
    const std::uint64_t data_bytes = left - (binary ? 0 : 1);
    for (const PlyElement& element : elements) {
        if (element.name == "vertex" && element.count > max_mesh_vertices) {
            refuse(file, "the header announces " + std::to_string(element.count) +
                             " vertices, more than the " + std::to_string(max_mesh_vertices) +
                             " a mesh file may have (max_mesh_vertices)");
        }
        const std::uint64_t per_entry =
            binary ? element.least_bytes : 2 * static_cast<std::uint64_t>(element.properties);
        if (per_entry == 0) continue;
        if (element.count > left / per_entry) {
            refuse(file, "the header announces " + std::to_string(element.count) + " " +
                             element.name + " entries of at least " + std::to_string(per_entry) +
                             " bytes each, but only " + std::to_string(data_bytes) +
                             " bytes follow it (the file is truncated)");
        }
        left -= element.count * per_entry;
    }
}

// A binary STL is an 80-byte header, a 32-bit little-endian triangle count and 50 bytes per
// triangle; a file of exactly that size is read as one (as assimp decides), three vertices per
// triangle.
void check_stl(const fs::path& file) {
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(file, error);
    if (error || bytes < 84) return;
    std::ifstream in(file, std::ios::binary);
    std::array<unsigned char, 84> head{};
    if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return;
    const std::uint64_t triangles = std::uint64_t{head[80]} | std::uint64_t{head[81]} << 8U |
                                    std::uint64_t{head[82]} << 16U | std::uint64_t{head[83]} << 24U;
    if (bytes != 84 + 50 * triangles || 3 * triangles <= max_mesh_vertices) return;
    throw GeometryError("mesh file '" + file.string() + "': a binary STL of " +
                        std::to_string(triangles) + " triangles has " +
                        std::to_string(3 * triangles) + " vertices, more than the " +
                        std::to_string(max_mesh_vertices) +
                        " a mesh file may have (max_mesh_vertices): simplify it first, e.g. by "
                        "quadric decimation in MeshLab or Blender");
}

}  // namespace

void check_mesh_header(const fs::path& file, const std::string& extension) {
    if (extension == ".ply") check_ply(file);
    if (extension == ".stl") check_stl(file);
}

}  // namespace rockfall::shapes
