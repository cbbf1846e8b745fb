#include "mesh_header.hpp"

#include "shapes/mesh_io.hpp"
#include "shapes/polyhedron.hpp"

#include <array>
#include <cctype>
#include <charconv>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <regex>
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

// A file refused by its format's rules, `extension` naming the format (".ply").
[[noreturn]] void refuse_as(const fs::path& file, const std::string& extension,
                            const std::string& problem) {
    throw GeometryError("mesh file '" + file.string() + "': cannot be read as " + extension + ": " +
                        problem);
}

[[noreturn]] void refuse(const fs::path& file, const std::string& problem) {
    refuse_as(file, ".ply", problem);
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

// The largest count a list's count type holds (1 to 4 bytes, signed or not).
std::uint64_t largest_count(const PlyProperty& list) {
    return (std::uint64_t{1} << (8 * list.count_bytes - (list.count_signed ? 1 : 0))) - 1;
}

// The data of a PLY file walked entry by entry, as assimp reads them, to check every list count
// before assimp sizes a list by it: a count must fit its type (a uchar count is at most 255)
// and the items it announces must follow, in a binary file in the bytes left, in an ASCII
// file on the entry's own line (assimp reads one entry a line). A count of 10^12 in an ASCII
// file made assimp take 22 GB of memory. The values themselves are left to assimp.
void check_ply_lists(const fs::path& file, std::istream& in, bool binary, bool big_endian,
                     const std::vector<PlyElement>& elements, int header_lines) {
    const std::string data{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    // assimp's ASCII reader stops a line at a NUL byte and goes on out of step with the entries
    // (a face line with a NUL took 2.7 GB: found by fuzz_mesh_ply).
    if (!binary && data.find('\0') != std::string::npos) {
        refuse(file, "the ASCII data hold a NUL byte: not a text file");
    }
    std::size_t at = 0;
    int line = header_lines;
    const auto bad_count = [&](const PlyElement& element, std::uint64_t entry,
                               const PlyProperty& list) {
        refuse(file, element.name + " entry " + std::to_string(entry) +
                         " has a list count that is not a whole number in [0, " +
                         std::to_string(largest_count(list)) + "] (its count type)");
    };
    const auto truncated = [&](const PlyElement& element, std::uint64_t entry) {
        refuse(file, "the data end inside " + element.name + " entry " + std::to_string(entry) +
                         " of " + std::to_string(element.count) + " (the file is truncated)");
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
        if (is_signed && (value >> (8 * bytes - 1)) != 0) {
            return static_cast<std::int64_t>(value) - (std::int64_t{1} << (8 * bytes));
        }
        return static_cast<std::int64_t>(value);
    };
    for (const PlyElement& element : elements) {
        for (std::uint64_t entry = 0; entry < element.count; ++entry) {
            if (binary) {
                for (const PlyProperty& property : element.properties) {
                    const std::size_t head = property.list ? property.count_bytes : property.bytes;
                    if (data.size() - at < head) truncated(element, entry);
                    if (!property.list) {
                        at += property.bytes;
                        continue;
                    }
                    const std::int64_t count = integer(property.count_bytes, property.count_signed);
                    if (count < 0) bad_count(element, entry, property);
                    if ((data.size() - at) / property.bytes < static_cast<std::uint64_t>(count)) {
                        truncated(element, entry);
                    }
                    at += static_cast<std::uint64_t>(count) * property.bytes;
                }
                continue;
            }
            if (at >= data.size()) truncated(element, entry);
            const std::size_t end = std::min(data.find('\n', at), data.size());
            const std::vector<std::string> values = words(data.substr(at, end - at));
            at = end + 1;
            ++line;
            const std::string where = "line " + std::to_string(line) + " (" + element.name +
                                      " entry " + std::to_string(entry) + "): ";
            std::size_t next = 0;
            for (const PlyProperty& property : element.properties) {
                if (next >= values.size()) {
                    refuse(file, where + "fewer values than the element's " +
                                     std::to_string(element.properties.size()) +
                                     " properties (each entry is one line)");
                }
                if (!property.list) {
                    ++next;
                    continue;
                }
                const std::string& text = values[next++];
                std::uint64_t count = 0;
                const auto [stop, error] =
                    std::from_chars(text.data(), text.data() + text.size(), count);
                if (error != std::errc() || stop != text.data() + text.size() ||
                    count > largest_count(property)) {
                    bad_count(element, entry, property);
                }
                if (count > values.size() - next) {
                    refuse(file, where + "a list of " + std::to_string(count) +
                                     " values, but the line holds only " +
                                     std::to_string(values.size() - next) + " more");
                }
                next += count;
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
            // An overflowing count is out of range for from_chars, not only a short read.
            const std::from_chars_result parsed =
                w.size() == 3 ? std::from_chars(w[2].data(), end, element.count)
                              : std::from_chars_result{nullptr, std::errc::invalid_argument};
            if (parsed.ec != std::errc() || parsed.ptr != end) {
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
    check_ply_lists(file, in, binary, format[1] == "binary_big_endian", elements, number);
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
        refuse_as(file, ".glb", problem + " (the file has " + std::to_string(bytes) + " bytes)");
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

// OFF (Geomview): a keyword (`OFF`, or with the prefixes ST, C, N, 4 as in `COFF`, `NOFF`,
// `STOFF`), the vertex, face and edge counts, then one line per vertex (x y z and optional
// colour, normal or texture values) and one per face (n, then n vertex indices from 0).
// assimp's reader trusts all of it: it sizes arrays by counts read as wrapping 32-bit numbers
// (129000000004 faces in an 849-byte file took 2.3 GB), counts a face's corners in one pass and
// reads them in another with other rules (more than 9 corners, a missing line), which left
// faces without corners and read past its vertex array (a crash); all found by fuzz_mesh_off.
// So the whole file is checked here against the form assimp reads correctly, and refused with
// the line that breaks it. Lines longer than assimp's 4096-byte line buffer are refused too.
void check_off(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    const std::string text{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const auto refuse_off = [&](const std::string& problem) { refuse_as(file, ".off", problem); };
    if (text.find('\0') != std::string::npos) refuse_off("it holds a NUL byte: not a text file");
    // Lines as assimp takes them: ended by CR or LF, empty ones skipped.
    std::vector<std::pair<int, std::string_view>> lines;
    int number = 1;
    for (std::size_t at = 0; at < text.size();) {
        const std::size_t end = std::min(text.find_first_of("\r\n", at), text.size());
        if (end > at) lines.emplace_back(number, std::string_view(text).substr(at, end - at));
        if (end < text.size() && text[end] == '\n') ++number;
        at = end + 1;
    }
    std::size_t next = 0;
    std::vector<std::string> header;
    // The keyword and the three counts, on one line or more; comment lines may come between.
    while (header.size() < 4 && next < lines.size()) {
        const std::vector<std::string> w = words(std::string(lines[next++].second));
        if (!w.empty() && w[0][0] == '#') continue;
        header.insert(header.end(), w.begin(), w.end());
    }
    const auto integer = [](std::string_view word, std::uint64_t& value) {
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        return error == std::errc() && end == word.data() + word.size();
    };
    std::array<std::uint64_t, 3> counts{};
    static const std::regex keyword("(ST)?C?N?4?OFF");
    if (header.size() != 4 || !std::regex_match(header[0], keyword) ||
        !integer(header[1], counts[0]) || !integer(header[2], counts[1]) ||
        !integer(header[3], counts[2])) {
        refuse_off(
            "it starts with its keyword (OFF, COFF, NOFF, STOFF, ...) and the vertex, "
            "face and edge counts, three whole numbers; this one does not");
    }
    const std::uint64_t vertices = counts[0];
    const std::uint64_t faces = counts[1];
    if (vertices > max_mesh_vertices) {
        refuse_off("the header announces " + std::to_string(vertices) +
                   " vertices, more than the " + std::to_string(max_mesh_vertices) +
                   " a mesh file may have (max_mesh_vertices)");
    }
    if (faces > lines.size() - next || vertices > lines.size() - next - faces) {
        refuse_off("the header announces " + std::to_string(vertices) + " vertices and " +
                   std::to_string(faces) + " faces, one line each, but only " +
                   std::to_string(lines.size() - next) + " lines follow it");
    }
    for (std::uint64_t i = 0; i < vertices + faces; ++i) {
        const auto [line, content] = lines[next + i];
        const std::string where = "line " + std::to_string(line) + " (" +
                                  shown(std::string(content.substr(0, 80))) + "): ";
        if (content.size() > 4095) refuse_off(where + "longer than 4095 characters");
        const std::vector<std::string> w = words(std::string(content));
        if (i < vertices) {
            double value = 0;
            bool numbers = w.size() >= 3;
            for (std::size_t k = 0; numbers && k < 3; ++k) {
                const auto [end, error] =
                    std::from_chars(w[k].data(), w[k].data() + w[k].size(), value);
                numbers = error == std::errc() && end == w[k].data() + w[k].size();
            }
            if (!numbers) refuse_off(where + "a vertex line starts with three numbers, x y z");
            continue;
        }
        std::uint64_t corners = 0;
        bool good = !w.empty() && integer(w[0], corners) && corners >= 1 && corners <= 9 &&
                    w.size() > corners;
        for (std::uint64_t k = 1; good && k <= corners; ++k) {
            std::uint64_t index = 0;
            good = integer(w[k], index) && index < vertices;
        }
        if (!good) {
            refuse_off(where + "a face line is n (1 to 9) and n vertex indices in [0, " +
                       std::to_string(vertices) + ")");
        }
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
