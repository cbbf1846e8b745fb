#include "mesh_header.hpp"

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
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

struct PlyProperty {
    // Bytes of the value, or of a list's item; a list's count takes count_bytes first.
    std::size_t bytes = 0;
    bool list = false;
    std::size_t count_bytes = 0;
    bool count_signed = false;
};

struct PlyElement {
    std::string name;
    std::uint64_t count = 0;
    std::vector<PlyProperty> properties;
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

// The data of a PLY file walked entry by entry, as a reader does, to check every list count
// before assimp sizes a list by it: a count must fit its type (a uchar count is at most 255)
// and the items it announces must follow in the file. A count of 10^12 in an ASCII file made
// assimp take 22 GB of memory. Values themselves are left to assimp.
void check_ply_lists(const fs::path& file, std::istream& in, bool binary, bool big_endian,
                     const std::vector<PlyElement>& elements) {
    const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    std::size_t at = 0;
    const auto truncated = [&](const PlyElement& element, std::uint64_t entry) {
        refuse(file, "the data end inside " + element.name + " entry " + std::to_string(entry) +
                         " of " + std::to_string(element.count) + " (the file is truncated)");
    };
    // The next ASCII value, or nothing at the end of the data.
    const auto token = [&]() -> std::string_view {
        while (at < data.size() && std::isspace(static_cast<unsigned char>(data[at]))) ++at;
        const std::size_t start = at;
        while (at < data.size() && !std::isspace(static_cast<unsigned char>(data[at]))) ++at;
        return std::string_view(data).substr(start, at - start);
    };
    // A binary integer of `bytes` bytes as the file's byte order gives it.
    const auto integer = [&](std::size_t bytes, bool is_signed) -> std::int64_t {
        std::uint64_t value = 0;
        for (std::size_t i = 0; i < bytes; ++i) {
            const auto byte =
                static_cast<unsigned char>(data[at + (big_endian ? i : bytes - 1 - i)]);
            value = value << 8U | byte;
        }
        at += bytes;
        if (is_signed && bytes < 8 && (value >> (8 * bytes - 1)) != 0) {
            return static_cast<std::int64_t>(value) - (std::int64_t{1} << (8 * bytes));
        }
        return static_cast<std::int64_t>(value);
    };
    for (const PlyElement& element : elements) {
        for (std::uint64_t entry = 0; entry < element.count; ++entry) {
            for (const PlyProperty& property : element.properties) {
                if (!property.list) {
                    if (binary ? data.size() - at < property.bytes : token().empty())
                        truncated(element, entry);
                    if (binary) at += property.bytes;
                    continue;
                }
                const std::uint64_t largest =
                    (std::uint64_t{1} << (8 * property.count_bytes - property.count_signed)) - 1;
                std::int64_t count = 0;
                if (binary) {
                    if (data.size() - at < property.count_bytes) truncated(element, entry);
                    count = integer(property.count_bytes, property.count_signed);
                } else {
                    const std::string_view text = token();
                    if (text.empty()) truncated(element, entry);
                    const auto [end, error] =
                        std::from_chars(text.data(), text.data() + text.size(), count);
                    if (error != std::errc() || end != text.data() + text.size()) count = -1;
                }
                if (count < 0 || static_cast<std::uint64_t>(count) > largest) {
                    refuse(file, element.name + " entry " + std::to_string(entry) +
                                     " has a list count that is not a whole number in [0, " +
                                     std::to_string(largest) + "] (its count type)");
                }
                const auto items = static_cast<std::uint64_t>(count);
                if (binary) {
                    if ((data.size() - at) / property.bytes < items) truncated(element, entry);
                    at += items * property.bytes;
                } else {
                    for (std::uint64_t i = 0; i < items; ++i)
                        if (token().empty()) truncated(element, entry);
                }
            }
        }
    }
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
            const std::string& count_type = w[2];
            if (list && (count_type == "float" || count_type == "float32" ||
                         count_type == "double" || count_type == "float64")) {
                refuse(file, where +
                                 "a list's count type must be an integer type (uchar, "
                                 "ushort, uint, ...), not " +
                                 count_type);
            }
            elements.back().properties.push_back(
                list ? PlyProperty{scalar_bytes(w[3]), true, scalar_bytes(count_type),
                                   count_type == "char" || count_type == "int8" ||
                                       count_type == "short" || count_type == "int16" ||
                                       count_type == "int" || count_type == "int32"}
                     : PlyProperty{scalar_bytes(w[1]), false, 0, false});
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
            binary ? element.least_bytes
                   : 2 * static_cast<std::uint64_t>(element.properties.size());
        if (per_entry == 0) continue;
        if (element.count > left / per_entry) {
            refuse(file, "the header announces " + std::to_string(element.count) + " " +
                             element.name + " entries of at least " + std::to_string(per_entry) +
                             " bytes each, but only " + std::to_string(data_bytes) +
                             " bytes follow it (the file is truncated)");
        }
        left -= element.count * per_entry;
    }
    check_ply_lists(file, in, binary, format[1] == "binary_big_endian", elements);
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

std::uint32_t little_endian_32(const unsigned char* bytes) {
    return std::uint32_t{bytes[0]} | std::uint32_t{bytes[1]} << 8U |
           std::uint32_t{bytes[2]} << 16U | std::uint32_t{bytes[3]} << 24U;
}

// Binary glTF (Khronos glTF 2.0, "GLB File Format Specification"): a 12-byte header (magic
// `glTF`, version, total length), then chunks of a 4-byte length, a 4-byte type and the data;
// version 1 (KHR_binary_glTF) has a 20-byte header whose fourth word is the JSON's length.
// assimp allocates a chunk's declared length before reading it (a 3.9 GB JSON chunk in an
// 848-byte file, found by fuzz_mesh_glb), so every length must fit in the file.
void check_glb(const fs::path& file) {
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(file, error);
    std::ifstream in(file, std::ios::binary);
    std::array<unsigned char, 20> head{};
    if (error || bytes < 12 || !in.read(reinterpret_cast<char*>(head.data()), 12) ||
        std::string_view(reinterpret_cast<const char*>(head.data()), 4) != "glTF") {
        return;  // not binary glTF at all: assimp says so
    }
    const auto refuse_glb = [&](const std::string& problem) {
        throw GeometryError("mesh file '" + file.string() + "': cannot be read as .glb: " +
                            problem + " (the file has " + std::to_string(bytes) + " bytes)");
    };
    const std::uint32_t version = little_endian_32(&head[4]);
    if (version == 1) {
        if (bytes < 20 || !in.read(reinterpret_cast<char*>(&head[12]), 8)) {
            refuse_glb("a version 1 header is 20 bytes");
        }
        const std::uint32_t content = little_endian_32(&head[12]);
        if (content > bytes - 20) {
            refuse_glb("the header announces " + std::to_string(content) + " bytes of JSON");
        }
        return;
    }
    if (version != 2) return;
    const std::uint32_t length = little_endian_32(&head[8]);
    if (length > bytes) refuse_glb("the header announces " + std::to_string(length) + " bytes");
    std::uint64_t at = 12;
    for (int chunk = 1; at + 8 <= length; ++chunk) {
        std::array<unsigned char, 8> chunk_head{};
        in.seekg(static_cast<std::streamoff>(at));
        if (!in.read(reinterpret_cast<char*>(chunk_head.data()), 8)) break;
        const std::uint32_t chunk_bytes = little_endian_32(chunk_head.data());
        if (chunk_bytes > length - at - 8) {
            refuse_glb("chunk " + std::to_string(chunk) + " announces " +
                       std::to_string(chunk_bytes) + " bytes, but only " +
                       std::to_string(length - at - 8) + " follow it");
        }
        at += 8 + std::uint64_t{chunk_bytes};
    }
}

// OFF (Geomview): a keyword line (`OFF`, or with prefixes as `COFF`, `NOFF`, `STOFF`, `4OFF`),
// then the vertex, face and edge counts, then the vertices and the faces as text. assimp
// sizes its arrays by the counts, read as 32-bit numbers that wrap (an 849-byte file that
// announced 129000000004 faces took 2.3 GB: found by fuzz_mesh_off), so the counts must be
// ones the rest of the file can hold: a vertex takes at least 6 bytes (three values and their
// blanks), a face 2. A header that is not of this form is left to assimp.
void check_off(const fs::path& file) {
    std::error_code error;
    const std::uintmax_t bytes = fs::file_size(file, error);
    std::ifstream in(file, std::ios::binary);
    std::string keyword;
    if (error || !(in >> keyword) || keyword.size() < 3 ||
        keyword.compare(keyword.size() - 3, 3, "OFF") != 0) {
        return;
    }
    std::array<std::uint64_t, 2> counts{};
    for (std::uint64_t& count : counts) {
        std::string word;
        if (!(in >> word)) return;
        const auto [end, parse_error] =
            std::from_chars(word.data(), word.data() + word.size(), count);
        if (parse_error != std::errc() || end != word.data() + word.size()) return;
    }
    const std::streamoff read = in.tellg();
    const std::uint64_t left = read > 0 && bytes > static_cast<std::uintmax_t>(read)
                                   ? bytes - static_cast<std::uint64_t>(read)
                                   : 0;
    const auto refuse_off = [&](const std::string& problem) {
        throw GeometryError("mesh file '" + file.string() +
                            "': cannot be read as .off: " + problem);
    };
    if (counts[0] > max_mesh_vertices) {
        refuse_off("the header announces " + std::to_string(counts[0]) +
                   " vertices, more than the " + std::to_string(max_mesh_vertices) +
                   " a mesh file may have (max_mesh_vertices)");
    }
    if (counts[1] > left / 2 || 6 * counts[0] > left + 1 - 2 * counts[1]) {
        refuse_off("the header announces " + std::to_string(counts[0]) + " vertices and " +
                   std::to_string(counts[1]) + " faces, but only " + std::to_string(left) +
                   " bytes follow it (at least 6 a vertex and 2 a face: the file is truncated)");
    }
}

}  // namespace

void check_mesh_header(const fs::path& file, const std::string& extension) {
    if (extension == ".ply") check_ply(file);
    if (extension == ".stl") check_stl(file);
    if (extension == ".glb") check_glb(file);
    if (extension == ".off") check_off(file);
}

}  // namespace rockfall::shapes
