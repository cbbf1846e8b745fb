#include "shapes/catalogue.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <sstream>
#include <system_error>

namespace rockfall::shapes {
namespace {

namespace fs = std::filesystem;

constexpr std::string_view kEntryKeys[] = {"name", "file", "scale", "size", "long_axis"};

std::string at(const fs::path& file, const toml::node& node) {
    return file.string() + ":" + std::to_string(node.source().begin.line);
}

[[noreturn]] void fail(const std::string& where, const std::string& problem) {
    throw GeometryError("shape catalogue " + where + ": " + problem);
}

std::string text_of(const toml::table& table, std::string_view key, const fs::path& file,
                    const std::string& path) {
    const toml::node* node = table.get(key);
    if (node == nullptr) fail(at(file, table), path + "." + std::string(key) + " is missing");
    const auto* text = node->as_string();
    if (text == nullptr || text->get().empty()) {
        fail(at(file, *node), path + "." + std::string(key) + ": must be a non-empty string");
    }
    return text->get();
}

// An optional positive number (integers allowed); `fallback` when absent.
double number_of(const toml::table& table, std::string_view key, std::string_view unit,
                 double fallback, const fs::path& file, const std::string& path) {
    const toml::node* node = table.get(key);
    if (node == nullptr) return fallback;
    std::optional<double> value;
    if (const auto* real = node->as_floating_point()) value = real->get();
    if (const auto* integer = node->as_integer()) value = static_cast<double>(integer->get());
    if (!value || !std::isfinite(*value) || *value <= 0.0) {
        std::ostringstream problem;
        problem << path << "." << key << " = ";
        node->visit([&problem](const auto& concrete) { problem << concrete; });
        problem << (unit.empty() ? "" : " " + std::string(unit)) << ": must be a finite number > 0";
        fail(at(file, *node), problem.str());
    }
    return *value;
}

CatalogueEntry read_entry(const toml::node& node, const fs::path& file, std::size_t index) {
    const std::string path = "shape[" + std::to_string(index) + "]";
    const auto* table = node.as_table();
    if (table == nullptr) fail(at(file, node), path + ": must be a table ([[shape]])");
    for (const auto& [key, value] : *table) {
        if (std::find(std::begin(kEntryKeys), std::end(kEntryKeys), key.str()) ==
            std::end(kEntryKeys)) {
            fail(at(file, value), path + "." + std::string(key.str()) +
                                      ": unknown key; allowed: name, file, scale, size, "
                                      "long_axis");
        }
    }
    CatalogueEntry entry;
    entry.name = text_of(*table, "name", file, path);
    entry.file = (file.parent_path() / text_of(*table, "file", file, path)).lexically_normal();
    entry.scaling.scale = number_of(*table, "scale", "", 1.0, file, path);
    entry.scaling.size = number_of(*table, "size", "m", 0.0, file, path);
    entry.scaling.long_axis = number_of(*table, "long_axis", "m", 0.0, file, path);
    if (entry.scaling.size > 0.0 && entry.scaling.long_axis > 0.0) {
        fail(at(file, *table), path + ": give size or long_axis, not both");
    }
    entry.origin = at(file, *table);
    return entry;
}

ShapeCatalogue read_toml(const fs::path& file) {
    toml::table root;
    try {
        root = toml::parse_file(file.string());
    } catch (const toml::parse_error& error) {
        fail(file.string() + ":" + std::to_string(error.source().begin.line),
             "TOML syntax error: " + std::string(error.description()));
    }
    ShapeCatalogue catalogue;
    catalogue.source = file;
    for (const auto& [key, value] : root) {
        if (key.str() != "shape") {
            fail(at(file, value),
                 std::string(key.str()) + ": unknown key; a catalogue holds only [[shape]] tables");
        }
    }
    const toml::node* shapes = root.get("shape");
    const toml::array* list = shapes != nullptr ? shapes->as_array() : nullptr;
    if (shapes != nullptr && list == nullptr) {
        fail(at(file, *shapes), "shape: must be an array of tables ([[shape]])");
    }
    for (std::size_t i = 0; list != nullptr && i < list->size(); ++i) {
        catalogue.entries.push_back(read_entry(*list->get(i), file, i));
    }
    return catalogue;
}

ShapeCatalogue read_folder(const fs::path& folder) {
    ShapeCatalogue catalogue;
    catalogue.source = folder;
    std::error_code error;
    for (const fs::directory_entry& item : fs::directory_iterator(folder, error)) {
        if (!item.is_regular_file() || !is_mesh_file(item.path())) continue;
        CatalogueEntry entry;
        entry.name = item.path().stem().string();
        entry.file = item.path();
        entry.origin = item.path().string();
        catalogue.entries.push_back(std::move(entry));
    }
    if (error) fail("'" + folder.string() + "'", "cannot list the folder: " + error.message());
    std::sort(catalogue.entries.begin(), catalogue.entries.end(),
              [](const CatalogueEntry& a, const CatalogueEntry& b) {
                  return a.name < b.name || (a.name == b.name && a.file < b.file);
              });
    return catalogue;
}

}  // namespace

ShapeCatalogue read_catalogue(const fs::path& source) {
    std::error_code error;
    const fs::file_status status = fs::status(source, error);
    const std::string name = "'" + source.string() + "'";
    if (!fs::exists(status)) fail(name, "no such file or folder");
    ShapeCatalogue catalogue;
    if (fs::is_directory(status)) {
        catalogue = read_folder(source);
    } else if (source.extension() == ".toml") {
        catalogue = read_toml(source);
    } else {
        fail(name, "must be a folder of meshes or a .toml file");
    }
    if (catalogue.entries.empty()) {
        fail(name,
             fs::is_directory(status) ? "the folder holds no mesh file" : "lists no [[shape]]");
    }
    for (std::size_t i = 1; i < catalogue.entries.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j) {
            if (catalogue.entries[i].name == catalogue.entries[j].name) {
                fail(name, "two entries are named '" + catalogue.entries[i].name + "' (" +
                               catalogue.entries[j].origin + " and " + catalogue.entries[i].origin +
                               ")");
            }
        }
    }
    return catalogue;
}

const CatalogueEntry& find_entry(const ShapeCatalogue& catalogue, std::string_view name) {
    const auto found =
        std::find_if(catalogue.entries.begin(), catalogue.entries.end(),
                     [&](const CatalogueEntry& entry) { return entry.name == name; });
    if (found != catalogue.entries.end()) return *found;
    std::string names;
    for (const CatalogueEntry& entry : catalogue.entries) {
        names += (names.empty() ? "" : ", ") + entry.name;
    }
    fail("'" + catalogue.source.string() + "'",
         "no entry named '" + std::string(name) + "'; entries: " + names);
}

CustomShape load_entry(const CatalogueEntry& entry) {
    CustomShape shape;
    shape.name = entry.name;
    try {
        shape.hull = read_mesh_hull(entry.file, entry.scaling);
    } catch (const GeometryError& error) {
        throw GeometryError("shape catalogue entry '" + entry.name + "' (" + entry.origin +
                            "): " + error.what());
    }
    return shape;
}

}  // namespace rockfall::shapes
