// Reading the shape keys of [sweep.rock]: kind (families, "custom" and named shapes),
// catalogue, [[sweep.rock.shapes]] and sphericity. Names and types only, plus what needs the
// file: which names exist, and where each key was written; sweep_validation.cpp and
// risk::find_problems check the values.

#include "scenario_rock_shape.hpp"
#include "sweep_reader.hpp"

#include "shapes/catalogue.hpp"
#include "shapes/polyhedron.hpp"

#include <algorithm>
#include <memory>
#include <optional>
#include <utility>

namespace rockfall::scenario::detail {
namespace {

// Entries listed in a message about an unknown name, before "... (N in all)".
constexpr std::size_t listed_names = 20;

using ShapePtr = std::shared_ptr<const shapes::CustomShape>;

// Where named shapes come from: hulls given inline and a catalogue.
struct NamedShapes {
    // [[sweep.rock.shapes]] with valid names, in file order, with the node of each name and
    // its index in the file's list.
    std::vector<ShapePtr> inline_shapes;
    std::vector<const toml::node*> inline_nodes;
    std::vector<std::size_t> inline_indices;
    // The catalogue, when given and readable.
    std::optional<shapes::ShapeCatalogue> catalogue;
    // Entries loaded so far, by name: an entry named twice is read once.
    std::vector<ShapePtr> loaded;

    // "cube", "flat", ... (every name kind may give besides the families), shortened.
    std::string names() const {
        std::vector<std::string> all;
        for (const ShapePtr& shape : inline_shapes) all.push_back("\"" + shape->name + "\"");
        if (catalogue) {
            for (const shapes::CatalogueEntry& e : catalogue->entries) {
                all.push_back("\"" + e.name + "\"");
            }
        }
        std::string text;
        for (std::size_t i = 0; i < all.size() && i < listed_names; ++i) {
            text += (i == 0 ? "" : ", ") + all[i];
        }
        if (all.size() > listed_names) {
            text += ", ... (" + std::to_string(all.size()) + " in all)";
        }
        return text;
    }
};

constexpr std::string_view generated_name = "generated";

// One name of a kind choice: a family (or "custom"), a named shape or generated rocks.
struct ShapeChoice {
    shapes::RockKind kind = shapes::RockKind::sphere;
    ShapePtr entry;
    bool generated = false;
};

// "sphere", "massive", "planar", "custom", "generated": the names kind takes besides entries.
std::string family_names() {
    std::string text;
    for (const shapes::RockKind kind : sweep_rock_kinds) {
        text +=
            std::string(text.empty() ? "\"" : ", \"") + std::string(shapes::to_string(kind)) + "\"";
    }
    return text + ", \"" + std::string(generated_name) + "\"";
}

void read_catalogue_key(TableReader& rock, NamedShapes& named) {
    const toml::node* node = rock.get("catalogue");
    if (node == nullptr) return;
    Context& context = rock.context();
    const auto* text = node->as_string();
    if (text == nullptr || text->get().empty()) {
        context.report(*node, rock.path("catalogue"),
                       describe(*node) +
                           ": must be the path of a shape catalogue, a folder of meshes or a "
                           ".toml file (a non-empty string, relative to this file)");
        return;
    }
    try {
        named.catalogue = shapes::read_catalogue(resolve_path(*node, text->get(), context));
    } catch (const shapes::GeometryError& error) {
        context.report(*node, rock.path("catalogue"), describe(*node) + ": " + error.what());
    }
}

// [[sweep.rock.shapes]]: name = "...", vertices = [[x, y, z], ...] (m).
void read_inline_shapes(TableReader& rock, NamedShapes& named) {
    struct Inline {
        ShapePtr shape;
        const toml::node* name_node = nullptr;
        bool named = false;
    };
    std::vector<Inline> read_shapes;
    Context& context = rock.context();
    with_table_array(rock, "shapes", read_shapes, [&](TableReader& r, Inline& element) {
        std::string name;
        read(r, "name", name);
        element.name_node = r.get("name");
        // read() reports a name that is not a string.
        const bool text = element.name_node != nullptr && element.name_node->is_string();
        if (element.name_node == nullptr) {
            const Location where = context.sources.find(r.path("name"));
            context.problems.push_back({where.file, where.line, r.path("name"),
                                        "missing: each shape needs a name for kind to draw it"});
        } else if (text && name.empty()) {
            context.report(*element.name_node, r.path("name"), "\"\": must not be empty");
        } else if (text && risk::is_reserved_shape_name(name)) {
            context.report(*element.name_node, r.path("name"),
                           toml_string(name) + ": names a family or kind (" + family_names() +
                               "); give the shape another name");
        } else {
            element.named = text;
        }
        const toml::node* vertices = r.get("vertices");
        if (vertices == nullptr) {
            const Location where = context.sources.find(r.path("vertices"));
            context.problems.push_back({where.file, where.line, r.path("vertices"),
                                        "missing: give the shape's points [[x, y, z], ...] (m)"});
            return;
        }
        const std::optional<std::vector<shapes::Vec3>> cloud = read_vertices(r, *vertices);
        if (!cloud) return;
        try {
            element.shape = std::make_shared<const shapes::CustomShape>(
                shapes::CustomShape{name, shapes::convex_hull(*cloud)});
        } catch (const shapes::GeometryError& error) {
            context.report(*vertices, r.path("vertices"),
                           describe(*vertices) + ": " + error.what());
        }
    });
    for (std::size_t i = 0; i < read_shapes.size(); ++i) {
        const Inline& shape = read_shapes[i];
        if (shape.shape == nullptr || !shape.named) continue;
        const std::string path = rock.path("shapes") + "[" + std::to_string(i) + "].name";
        const auto same_name = [&](const ShapePtr& other) {
            return other->name == shape.shape->name;
        };
        if (std::any_of(named.inline_shapes.begin(), named.inline_shapes.end(), same_name)) {
            context.report(*shape.name_node, path,
                           toml_string(shape.shape->name) +
                               ": another shape has this name; names must differ");
            continue;
        }
        named.inline_shapes.push_back(shape.shape);
        named.inline_nodes.push_back(shape.name_node);
        named.inline_indices.push_back(i);
    }
}

// A name of a kind choice: a family, "custom", a shape given inline or a catalogue entry
// (loaded here). Reports what is wrong with it at `path`.
std::optional<ShapeChoice> choice_of(const toml::node& item, const std::string& path,
                                     NamedShapes& named, Context& context) {
    const auto* text = item.as_string();
    const std::string name = text != nullptr ? text->get() : std::string();
    if (text != nullptr) {
        for (const shapes::RockKind kind : sweep_rock_kinds) {
            if (shapes::to_string(kind) == name) return ShapeChoice{kind, nullptr, false};
        }
        if (name == generated_name) return ShapeChoice{shapes::RockKind::custom, nullptr, true};
        const auto named_so = [&](const ShapePtr& shape) { return shape->name == name; };
        for (const std::vector<ShapePtr>* list : {&named.inline_shapes, &named.loaded}) {
            const auto found = std::find_if(list->begin(), list->end(), named_so);
            if (found != list->end()) return ShapeChoice{shapes::RockKind::custom, *found, false};
        }
        if (named.catalogue) {
            const auto& entries = named.catalogue->entries;
            const auto entry =
                std::find_if(entries.begin(), entries.end(),
                             [&](const shapes::CatalogueEntry& e) { return e.name == name; });
            if (entry != entries.end()) {
                try {
                    named.loaded.push_back(
                        std::make_shared<const shapes::CustomShape>(shapes::load_entry(*entry)));
                    return ShapeChoice{shapes::RockKind::custom, named.loaded.back(), false};
                } catch (const shapes::GeometryError& error) {
                    context.report(item, path, describe(item) + ": " + error.what());
                    return std::nullopt;
                }
            }
        }
    }
    const std::string names = named.names();
    std::string sources;
    if (!named.inline_shapes.empty()) sources = "sweep.rock.shapes";
    if (named.catalogue) {
        sources += (sources.empty() ? "" : " and ") + named.catalogue->source.string();
    }
    std::string message = describe(item) + ": must be one of " + family_names() +
                          " (custom: the base rock's own shape; generated: rocks of the target "
                          "sphericity)";
    if (!names.empty()) {
        message += " or a named shape of " + sources + ": " + names;
    } else {
        message += "; to draw catalogue entries, give sweep.rock.catalogue";
    }
    context.report(item, path, message);
    return std::nullopt;
}

// Drops every shape the spec draws (families, named shapes, generated rocks), such as those a
// base file gave, before this file's own choice replaces them.
void clear_shape_draw(risk::SweepSpec& spec) {
    spec.kinds.clear();
    spec.kind_weights.clear();
    spec.entries.clear();
    spec.entry_weights.clear();
    spec.generated_weight = 0.0;
}

// kind = "name", or kind = { choice = ["sphere", "cube"], weights = [2, 1] }.
void read_kind_key(TableReader& rock, NamedShapes& named, risk::SweepSpec& spec) {
    const toml::node* node = rock.get("kind");
    if (node == nullptr) return;
    Context& context = rock.context();
    const std::string path = rock.path("kind");
    const auto resolve = [&](const toml::node& item, const std::string& item_path) {
        return choice_of(item, item_path, named, context);
    };
    std::vector<ShapeChoice> choices;
    std::vector<double> weights;
    const std::size_t problems_before = context.problems.size();
    if (node->is_string()) {
        if (std::optional<ShapeChoice> choice = resolve(*node, path)) choices = {*choice};
        weights = {1.0};
    } else if (const auto* table = node->as_table()) {
        TableReader r(*table, path, context);
        if (!table->contains("choice")) {
            context.report(*node, path,
                           describe(*node) + ": must list the shapes to draw: { choice = [" +
                               family_names() +
                               " or named shapes], weights = [...] } (weights optional: equal "
                               "by default)");
        }
        read_list(r, "choice", choices, "shape names", resolve);
        const bool weighted = table->contains("weights");
        read_list(
            r, "weights", weights, "numbers (relative weights, >= 0)",
            [&](const toml::node& item, const std::string& item_path) -> std::optional<double> {
                if (std::optional<double> value = number_of(item)) return value;
                context.report(item, item_path, describe(item) + ": must be a number (>= 0)");
                return std::nullopt;
            });
        r.finish();
        if (!weighted) weights.assign(choices.size(), 1.0);
    } else {
        context.report(*node, path,
                       describe(*node) + ": must be a shape name (" + family_names() +
                           " or a named shape) or { choice = [names], weights = [numbers] }");
    }
    if (context.problems.size() != problems_before) return;
    clear_shape_draw(spec);
    if (weights.size() != choices.size()) {
        // Kept with the kinds, so that risk::find_problems reports the mismatch in numbers.
        for (const ShapeChoice& choice : choices) spec.kinds.push_back(choice.kind);
        spec.kind_weights = std::move(weights);
        return;
    }
    for (std::size_t i = 0; i < choices.size(); ++i) {
        if (choices[i].generated) {
            spec.generated_weight += weights[i];
        } else if (choices[i].entry != nullptr) {
            spec.entries.push_back(choices[i].entry);
            spec.entry_weights.push_back(weights[i]);
        } else {
            spec.kinds.push_back(choices[i].kind);
            spec.kind_weights.push_back(weights[i]);
        }
    }
    if (std::count_if(choices.begin(), choices.end(),
                      [](const ShapeChoice& c) { return c.generated; }) > 1) {
        context.report(*node, path,
                       describe(*node) + ": \"generated\" is listed twice: list each shape once");
    }
}

// Shapes given but never drawn are mistakes: say which.
void check_drawn(TableReader& rock, const NamedShapes& named, const risk::SweepSpec& spec) {
    Context& context = rock.context();
    const auto drawn = [&](const ShapePtr& shape) {
        return std::find(spec.entries.begin(), spec.entries.end(), shape) != spec.entries.end();
    };
    for (std::size_t i = 0; i < named.inline_shapes.size(); ++i) {
        if (drawn(named.inline_shapes[i])) continue;
        context.report(
            *named.inline_nodes[i],
            rock.path("shapes") + "[" + std::to_string(named.inline_indices[i]) + "].name",
            toml_string(named.inline_shapes[i]->name) +
                ": is never drawn: name it in kind = { choice = [...] }");
    }
    if (named.catalogue && named.loaded.empty()) {
        const toml::node* node = rock.get("catalogue");
        context.report(*node, rock.path("catalogue"),
                       describe(*node) +
                           ": none of its entries is drawn: name them in kind = { choice = "
                           "[...] } (entries: " +
                           named.names() + ")");
    }
}

// The target sphericity distribution, when given and readable.
std::optional<risk::Distribution> read_sphericity(TableReader& rock) {
    if (!rock.contains("sphericity")) return std::nullopt;
    Context& context = rock.context();
    const std::size_t problems_before = context.problems.size();
    risk::Distribution d;
    read_distribution(rock, "sphericity", d, "");
    if (context.problems.size() != problems_before) return std::nullopt;
    return d;
}

// Whether the key is written in the file being read (not inherited through extends).
bool own_key(TableReader& rock, std::string_view key) {
    const toml::node* node = rock.get(key);
    Context& context = rock.context();
    return node != nullptr && node_location(*node, context.file).file == context.file;
}

}  // namespace

void read_sweep_shapes(TableReader& rock, risk::SweepSpec& spec) {
    Context& context = rock.context();
    NamedShapes named;
    read_catalogue_key(rock, named);
    read_inline_shapes(rock, named);
    const std::size_t problems_before = context.problems.size();
    read_kind_key(rock, named, spec);
    const bool kind_read = context.problems.size() == problems_before;
    if (kind_read) check_drawn(rock, named, spec);
    const std::optional<risk::Distribution> sphericity = read_sphericity(rock);
    // Whether kind draws generated rocks is unknown when kind could not be read.
    if (!sphericity || !kind_read) return;
    if (spec.generated_weight > 0.0) {
        spec.sphericity = sphericity;
        return;
    }
    // Without "generated" in kind: sphericity alone replaces the kind draw, and so does a
    // file's own sphericity over a kind inherited from its base (extends merges [sweep.rock]
    // key by key), while a file's own kind replaces an inherited sphericity. Both written
    // side by side contradict each other.
    const std::array<std::string_view, 3> kind_keys = {"kind", "catalogue", "shapes"};
    const bool any_kind = std::any_of(kind_keys.begin(), kind_keys.end(),
                                      [&](std::string_view key) { return rock.contains(key); });
    const bool own_kind = std::any_of(kind_keys.begin(), kind_keys.end(),
                                      [&](std::string_view key) { return own_key(rock, key); });
    const bool own_sphericity = own_key(rock, "sphericity");
    if (any_kind && own_kind == own_sphericity) {
        const toml::node* node = rock.get("sphericity");
        context.report(*node, rock.path("sphericity"),
                       risk::describe(*sphericity) +
                           ": kind draws no generated rock: add \"generated\" to kind's choice, "
                           "or leave kind out to draw generated rocks only");
        return;
    }
    if (own_kind) return;
    clear_shape_draw(spec);
    spec.generated_weight = 1.0;
    spec.sphericity = sphericity;
}

}  // namespace rockfall::scenario::detail
