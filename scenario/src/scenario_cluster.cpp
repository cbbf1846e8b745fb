// [cluster] in scenario files (see scenario_cluster.hpp).

#include "scenario_cluster.hpp"

#include <optional>
#include <stdexcept>

namespace rockfall::scenario::detail {

void read_cluster(TableReader& root, engine::Scenario& scenario, bool has_rocks,
                  RockShapeCache& shape_cache) {
    with_table(root, "cluster", [&](TableReader& r) {
        engine::Cluster cluster;
        std::array<std::string_view, cluster_kinds.size()> names;
        for (std::size_t i = 0; i < names.size(); ++i)
            names[i] = shapes::to_string(cluster_kinds[i]);
        if (const auto index = read_choice(r, "kind", names)) {
            cluster.rock.kind = cluster_kinds[*index];
        }
        read(r, "density", cluster.rock.density, "kg/m3", closed(500.0, 10000.0));
        // A catalogue entry, mesh or vertices: every drawn rock is that hull at its size.
        if (const toml::node* node = r.get("long_axis")) {
            r.context().report(*node, r.path("long_axis"),
                               "not for a cluster: its rocks' sizes are drawn from the grading");
        }
        read_rock_shape(r, cluster.rock, shape_cache);
        read_fields(r, cluster.grading, grading_fields);
        read_fields(r, cluster, cluster_fields);
        with_table(r, "material",
                   [&](TableReader& m) { read_fields(m, cluster.rock.material, material_fields); });
        with_table(r, "box", [&](TableReader& b) {
            read_fields(b, cluster.box, release_box_fields);
            read_enum(b, "packing", packing_names, cluster.box.packing);
        });
        with_table_array(r, "marked", cluster.marked,
                         [&](TableReader& m, engine::MarkedRock& marked) {
                             // Defaults: a rock of the cluster's family at its d50.
                             marked.rock = cluster.rock;
                             marked.rock.size = cluster.grading.d50;
                             read(m, "name", marked.name);
                             read_rock_spec(m, marked.rock, shape_cache);
                             read_fields(m, marked, marked_rock_fields);
                             if (m.contains("orientation_deg")) {
                                 read(m, "orientation_deg", marked.orientation_deg.emplace(), "deg",
                                      any_finite());
                             }
                         });
        scenario.cluster = cluster;
        if (!has_rocks) scenario.rocks.clear();
    });
}

void check_cluster(Checker& c, const engine::Scenario& s, bool profile_ok) {
    if (!s.cluster) return;
    const engine::Cluster& cluster = *s.cluster;
    bool ok = c.check_fields(cluster.grading, "cluster", grading_fields);
    ok = c.check_fields(cluster, "cluster", cluster_fields) && ok;
    ok = c.check_fields(cluster.box, "cluster.box", release_box_fields) && ok;
    ok = c.check("cluster.density", cluster.rock.density, "kg/m3", closed(500.0, 10000.0)) && ok;
    if (cluster.sphericity > 0.0 && cluster.sphericity < 0.5) {
        c.fail("cluster.sphericity", format_number(cluster.sphericity),
               "must be 0 (off) or in [0.5, 0.95]");
        ok = false;
    }
    if (cluster.sphericity > 0.0 && cluster.rock.shape) {
        c.fail("cluster.sphericity", format_number(cluster.sphericity),
               "give either a sphericity or a shape (catalogue, mesh or vertices), not both");
        ok = false;
    }
    c.check_fields(cluster.rock.material, "cluster.material", material_fields);
    if (!ok) return;
    try {
        shapes::grading_model(cluster.grading);
    } catch (const std::invalid_argument& error) {
        c.fail("cluster", "[cluster]", error.what());
    }
    bool box_ok = profile_ok;
    if (profile_ok) {
        try {
            shapes::release_box_region(shapes::Slope(profile_only(s.slope)), cluster.box);
        } catch (const std::exception& error) {
            c.fail("cluster.box", "[cluster.box]", error.what());
            box_ok = false;
        }
    }
    for (std::size_t i = 0; i < cluster.marked.size(); ++i) {
        const engine::MarkedRock& marked = cluster.marked[i];
        const std::string path = indexed("cluster.marked", i);
        if (marked.name.empty()) {
            c.fail(path + ".name", "(none)", "a marked rock needs a name (it is reported by it)");
        }
        const bool geometry_ok = check_rock_spec(c, s, marked.rock, path);
        if (marked.orientation_deg && cluster.box.packing == shapes::Packing::flat) {
            c.fail(path + ".orientation_deg", format_vector(*marked.orientation_deg) + " deg",
                   "not with cluster.box.packing = \"flat\" (the packing lays every rock flat)");
        }
        if (!c.check_fields(marked, path, marked_rock_fields) || !geometry_ok || !box_ok) {
            continue;
        }
        try {
            shapes::check_release_spot(cluster.box, shapes::Vec2(marked.along, marked.across),
                                       marked.rock.geometry().bounding_radius);
        } catch (const std::exception& error) {
            c.fail(
                path + ".along",
                format_number(marked.along) + " m, across " + format_number(marked.across) + " m",
                error.what());
        }
    }
}

}  // namespace rockfall::scenario::detail
