// Scenario -> complete TOML document, in the order docs/scenarios.md documents the keys.

#include "scenario/scenario_file.hpp"
#include "scenario_cluster.hpp"
#include "scenario_lining.hpp"
#include "scenario_schema.hpp"

#include "shapes/terrain.hpp"

#include <variant>

namespace rockfall::scenario {
namespace {

using detail::format_number;
using detail::toml_string;

// TOML floats need a '.' or an exponent ("2600.0", not "2600").
std::string float_text(double value) {
    std::string text = format_number(value);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

std::string value_text(double value) { return float_text(value); }
std::string value_text(int value) { return std::to_string(value); }
std::string value_text(bool value) { return value ? "true" : "false"; }
std::string value_text(const engine::Vec3& value) {
    return "[" + float_text(value.x()) + ", " + float_text(value.y()) + ", " +
           float_text(value.z()) + "]";
}

class Writer {
  public:
    void header(std::string_view name) { out_ += "\n[" + std::string(name) + "]\n"; }
    void array_header(std::string_view name) { out_ += "\n[[" + std::string(name) + "]]\n"; }
    void line(std::string_view key, const std::string& value) {
        out_ += std::string(key) + " = " + value + "\n";
    }
    template <class S, std::size_t N>
    void fields(const S& object, const detail::Fields<S, N>& fields) {
        for (const detail::Field<S>& field : fields) {
            std::visit([&](auto member) { line(field.key, value_text(object.*member)); },
                       field.member);
        }
    }
    template <class T, class Text>
    void list(std::string_view key, const std::vector<T>& values, Text text) {
        std::string items;
        for (std::size_t i = 0; i < values.size(); ++i)
            items += (i == 0 ? "" : ", ") + text(values[i]);
        line(key, "[" + items + "]");
    }
    std::string str() && { return std::move(out_); }

  private:
    std::string out_;
};

// A rock's family, or its hull itself so that the text stands alone (no mesh file to look
// for).
void write_shape(Writer& w, const engine::RockSpec& rock) {
    if (rock.shape) {
        w.line("shape_name", toml_string(rock.shape->name));
        std::string points;
        for (const shapes::Vec3& v : rock.shape->hull.vertices) {
            points += "\n    " + value_text(engine::Vec3(v)) + ",";
        }
        w.line("vertices", "[" + points + "\n]");
    } else {
        w.line("kind", toml_string(shapes::to_string(rock.kind)));
    }
}

// A rock's own keys (read_rock_spec) into the current table, its material as
// [<table>.material].
void write_rock_spec(Writer& w, const engine::RockSpec& rock, std::string_view table) {
    write_shape(w, rock);
    w.fields(rock, detail::rock_fields);
    w.header(std::string(table) + ".material");
    w.fields(rock.material, detail::material_fields);
}

}  // namespace

std::string format_scenario(const engine::Scenario& s) {
    Writer w;
    w.line("name", toml_string(s.name));
    w.fields(s, detail::scenario_fields);
    w.list("stations", s.stations, [](double v) { return float_text(v); });

    w.header("slope");
    w.fields(s.slope, detail::slope_fields);
    for (const shapes::SlopeSegment& segment : s.slope.segments) {
        w.array_header("slope.segments");
        w.fields(segment, detail::segment_fields);
    }
    w.header("slope.side_walls");
    w.fields(s.slope.side_walls, detail::side_wall_fields);
    w.header("slope.bars");
    w.fields(s.slope.bars, detail::bar_fields);
    w.list("segments", s.slope.bars.segments, [](int v) { return std::to_string(v); });
    w.header("slope.wall");
    w.fields(s.slope.wall, detail::wall_fields);
    if (s.slope.lining) {
        const shapes::Lining& lining = *s.slope.lining;
        const auto segments = [&](const std::vector<int>& list) {
            w.list("segments", list, [](int v) { return std::to_string(v); });
        };
        if (lining.spheres) {
            w.header("slope.lining.spheres");
            w.fields(*lining.spheres, detail::sphere_layer_fields);
            segments(lining.spheres->segments);
        }
        if (lining.bumps) {
            w.header("slope.lining.bumps");
            w.fields(*lining.bumps, detail::bump_fields);
            segments(lining.bumps->segments);
        }
        if (lining.sheet) {
            w.header("slope.lining.sheet");
            w.fields(*lining.sheet, detail::sheet_fields);
            segments(lining.sheet->segments);
        }
    }
    if (s.slope.terrain) {
        // The mesh itself, placed and cleaned, so that the text stands alone.
        const shapes::Terrain& terrain = *s.slope.terrain;
        w.header("slope.terrain");
        w.line("name", toml_string(terrain.name()));
        std::string points;
        for (const shapes::Vec3& v : terrain.mesh().vertices) {
            points += "\n    " + value_text(engine::Vec3(v)) + ",";
        }
        w.line("vertices", "[" + points + "\n]");
        std::string corners;
        for (const auto& [a, b, c] : terrain.mesh().triangles) {
            corners += "\n    [" + std::to_string(a) + ", " + std::to_string(b) + ", " +
                       std::to_string(c) + "],";
        }
        w.line("triangles", "[" + corners + "\n]");
    }

    const std::pair<std::string_view, const engine::Material*> materials[] = {
        {"materials.slope", &s.materials.slope},
        {"materials.bars", &s.materials.bars},
        {"materials.side_walls", &s.materials.side_walls},
        {"materials.wall", &s.materials.wall},
    };
    for (const auto& [name, material] : materials) {
        w.header(name);
        w.fields(*material, detail::material_fields);
    }

    w.header("wall_contact");
    w.line("model", toml_string(detail::name_of(detail::wall_model_names, s.wall_contact.model)));
    w.line("hull_model",
           toml_string(detail::name_of(detail::wall_hull_model_names, s.wall_contact.hull_model)));
    w.fields(s.wall_contact, detail::wall_contact_fields);
    if (s.wall_cells) {
        w.header("wall_cells");
        w.fields(*s.wall_cells, detail::wall_cells_fields);
    }

    for (const engine::RockRelease& rock : s.rocks) {
        w.array_header("rocks");
        if (!rock.name.empty()) w.line("name", toml_string(rock.name));
        write_rock_spec(w, rock.rock, "rocks");
        w.header("rocks.release");
        w.fields(rock.release, detail::release_fields);
    }

    if (s.cluster) {
        const engine::Cluster& cluster = *s.cluster;
        w.header("cluster");
        write_shape(w, cluster.rock);
        w.line("density", value_text(cluster.rock.density));
        w.fields(cluster.grading, detail::grading_fields);
        w.fields(cluster, detail::cluster_fields);
        w.header("cluster.material");
        w.fields(cluster.rock.material, detail::material_fields);
        w.header("cluster.box");
        w.fields(cluster.box, detail::release_box_fields);
        w.line("packing", toml_string(detail::name_of(detail::packing_names, cluster.box.packing)));
        for (const engine::MarkedRock& marked : cluster.marked) {
            w.array_header("cluster.marked");
            w.line("name", toml_string(marked.name));
            w.fields(marked, detail::marked_rock_fields);
            if (marked.orientation_deg) {
                w.line("orientation_deg", value_text(*marked.orientation_deg));
            }
            write_rock_spec(w, marked.rock, "cluster.marked");
        }
    }

    w.header("numerics");
    w.fields(s.numerics, detail::numerics_fields);
    w.line("wall_stepping",
           toml_string(detail::name_of(detail::wall_stepping_names, s.numerics.wall_stepping)));
    w.line("sheet_contact",
           toml_string(detail::name_of(detail::sheet_contact_names, s.numerics.sheet_contact)));
    return std::move(w).str();
}

}  // namespace rockfall::scenario
