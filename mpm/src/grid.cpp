#include "grid.hpp"

#include <cassert>

namespace rockfall::mpm::detail {

template <int Dim>
BlockGrid<Dim>::BlockGrid(const Vec<Dim>& domain_min, double cell, const IVec<Dim>& node_count,
                          double reach)
    : origin(domain_min), h(cell), nodes(node_count), boundary_reach(reach) {
    long total = 1;
    for (int d = 0; d < Dim; ++d) {
        blocks[d] = (nodes[d] + kBlockEdge - 1) / kBlockEdge + 1;
        total *= blocks[d];
    }
    slot_of_block.assign(static_cast<std::size_t>(total), -1);
}

template <int Dim>
int BlockGrid<Dim>::ensure_slot(int id, const std::vector<StaticBoundary>& statics,
                                const std::vector<Bounds>& bounds) {
    assert(id >= 0 && id < block_count());
    std::int32_t& slot = slot_of_block[static_cast<std::size_t>(id)];
    if (slot >= 0) {
        return slot;
    }
    slot = static_cast<std::int32_t>(block_of_slot.size());
    IVec<Dim> b;
    int rest = id;
    for (int d = 0; d < Dim; ++d) {
        b[d] = rest % blocks[d];
        rest /= blocks[d];
    }
    block_of_slot.push_back(b);
    data.resize(data.size() + kBlockNodes<Dim>, Node<Dim>::Zero());
    if (keep_old_velocity) {
        old_velocity.resize(data.size(), Node<Dim>::Zero());
    }
    rule_of_node.resize(rule_of_node.size() + kBlockNodes<Dim>, -1);
    const std::size_t first = static_cast<std::size_t>(slot) * kBlockNodes<Dim>;
    for (int local = 0; local < kBlockNodes<Dim>; ++local) {
        IVec<Dim> node;
        int r = local;
        for (int d = Dim - 1; d >= 0; --d) {
            node[d] = kBlockEdge * b[d] + r % kBlockEdge;
            r /= kBlockEdge;
        }
        const NodeRule<Dim> rule =
            classify_node<Dim>(to_scene<Dim>(node_position(node)), statics, bounds, boundary_reach);
        if (rule.count > 0) {
            rule_of_node[first + static_cast<std::size_t>(local)] =
                static_cast<std::int32_t>(rules.size());
            rules.push_back(rule);
        }
    }
    return slot;
}

template struct BlockGrid<2>;
template struct BlockGrid<3>;

}  // namespace rockfall::mpm::detail
