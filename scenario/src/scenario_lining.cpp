// [slope.lining] in scenario files (see scenario_lining.hpp).

#include "scenario_lining.hpp"

#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>

namespace rockfall::scenario::detail {
namespace {

// One lining kind: its table, fields and segments.
template <class Spec, std::size_t N>
void read_kind(TableReader& lining, std::string_view key, std::optional<Spec>& out,
               const Fields<Spec, N>& fields) {
    with_table(lining, key, [&](TableReader& r) {
        Spec spec;
        read_fields(r, spec, fields);
        read_segment_list(r, "segments", spec.segments);
        out = spec;
    });
}

template <class Spec, std::size_t N, class Build>
void check_kind(Checker& c, const std::optional<Spec>& spec, const std::string& path,
                const Fields<Spec, N>& fields, const shapes::Slope* slope, Build build) {
    if (!spec) return;
    if (!c.check_fields(*spec, path, fields) || slope == nullptr) return;
    try {
        build(*slope, *spec);
    } catch (const std::invalid_argument& error) {
        c.fail(path, "[" + path + "]", error.what());
    }
}

}  // namespace

void read_segment_list(TableReader& reader, std::string_view key, std::vector<int>& out) {
    read_list(reader, key, out, "segment indices",
              [&](const toml::node& item, const std::string& path) -> std::optional<int> {
                  const auto* index = item.as_integer();
                  if (index != nullptr && index->get() >= std::numeric_limits<int>::min() &&
                      index->get() <= std::numeric_limits<int>::max()) {
                      return static_cast<int>(index->get());
                  }
                  reader.context().report(item, path,
                                          describe(item) + ": must be an integer segment index");
                  return std::nullopt;
              });
}

void read_lining(TableReader& slope_reader, shapes::SlopeSpec& slope) {
    with_table(slope_reader, "lining", [&](TableReader& r) {
        shapes::Lining lining;
        read_kind(r, "spheres", lining.spheres, sphere_layer_fields);
        read_kind(r, "bumps", lining.bumps, bump_fields);
        read_kind(r, "sheet", lining.sheet, sheet_fields);
        if (lining.spheres || lining.bumps || lining.sheet) {
            slope.lining = std::make_shared<const shapes::Lining>(lining);
        }
    });
}

void check_lining(Checker& c, const shapes::SlopeSpec& spec, bool profile_ok) {
    if (!spec.lining) return;
    const std::optional<shapes::Slope> slope =
        profile_ok ? std::optional<shapes::Slope>(std::in_place, profile_only(spec)) : std::nullopt;
    const shapes::Slope* built = slope ? &*slope : nullptr;
    const shapes::Lining& lining = *spec.lining;
    check_kind(
        c, lining.spheres, "slope.lining.spheres", sphere_layer_fields, built,
        [](const shapes::Slope& s, const shapes::SphereLayer& l) { shapes::sphere_layer(s, l); });
    check_kind(c, lining.bumps, "slope.lining.bumps", bump_fields, built,
               [](const shapes::Slope& s, const shapes::Bumps& b) { shapes::bump_spheres(s, b); });
    check_kind(c, lining.sheet, "slope.lining.sheet", sheet_fields, built,
               [](const shapes::Slope& s, const shapes::PerforatedSheet& p) {
                   shapes::perforated_sheet(s, p);
               });
}

}  // namespace rockfall::scenario::detail
