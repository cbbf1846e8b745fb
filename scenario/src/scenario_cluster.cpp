// [cluster] in scenario files (see scenario_cluster.hpp).

#include "scenario_cluster.hpp"

#include <optional>
#include <stdexcept>

namespace rockfall::scenario::detail {

void read_cluster(TableReader& root, engine::Scenario& scenario, bool has_rocks) {
    with_table(root, "cluster", [&](TableReader& r) {
        engine::Cluster cluster;
        std::array<std::string_view, cluster_kinds.size()> names;
        for (std::size_t i = 0; i < names.size(); ++i)
            names[i] = shapes::to_string(cluster_kinds[i]);
        if (const auto index = read_choice(r, "kind", names)) {
            cluster.rock.kind = cluster_kinds[*index];
        }
        read(r, "density", cluster.rock.density, "kg/m3", closed(500.0, 10000.0));
        read_fields(r, cluster.grading, grading_fields);
        read_fields(r, cluster, cluster_fields);
        with_table(r, "material",
                   [&](TableReader& m) { read_fields(m, cluster.rock.material, material_fields); });
        with_table(r, "box",
                   [&](TableReader& b) { read_fields(b, cluster.box, release_box_fields); });
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
    c.check_fields(cluster.rock.material, "cluster.material", material_fields);
    if (!ok) return;
    try {
        shapes::grading_model(cluster.grading);
    } catch (const std::invalid_argument& error) {
        c.fail("cluster", "[cluster]", error.what());
    }
    if (!profile_ok) return;
    try {
        shapes::release_box_region(shapes::Slope(profile_only(s.slope)), cluster.box);
    } catch (const std::exception& error) {
        c.fail("cluster.box", "[cluster.box]", error.what());
    }
}

}  // namespace rockfall::scenario::detail
