#include "sample_shapes.hpp"

#include "risk/number_text.hpp"
#include "shapes/generators.hpp"
#include "shapes/random.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>

namespace rockfall::risk {
namespace {

const std::string kind_key = "sweep.rock.kind";
const std::string sphericity_key = "sweep.rock.sphericity";
const std::string generated_name = "generated";

// Reference rocks for the checks of generated rocks, and the allowance for the spread of
// their width between seeds (drawable_shapes states the measurement).
constexpr std::uint64_t reference_seeds = 16;
constexpr double generated_radius_allowance = 1.10;
// Seeds of a chain tried before a sample gives up; at the largest target none of 5000 seeds
// needed a second.
constexpr int max_shape_attempts = 32;

std::string short_number(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.4g", value);
    return text;
}

std::shared_ptr<const shapes::CustomShape> generated_shape(double target, std::uint64_t seed,
                                                           shapes::ConvexPolyhedron hull) {
    return std::make_shared<const shapes::CustomShape>(
        shapes::CustomShape{"generated rock of sphericity " + short_number(target) + " (seed " +
                                std::to_string(seed) + ")",
                            std::move(hull)});
}

struct Generated {
    std::uint64_t seed = 0;
    shapes::SphericityRock rock;
};

// The rock of the first seed of the chain whose point cloud reaches the target. With the
// default options rock_with_sphericity throws only for a target its cloud cannot reach; the
// chain's next seed is a SplitMix64 step (Steele, Lea and Flood 2014) of the last.
Generated generate(double target, std::uint64_t first_seed) {
    std::uint64_t seed = first_seed;
    for (int attempt = 1;; ++attempt) {
        try {
            return {seed, shapes::rock_with_sphericity(target, seed)};
        } catch (const shapes::GeometryError& error) {
            if (attempt == max_shape_attempts) {
                throw std::runtime_error("no generated rock reaches the target sphericity " +
                                         number_text(target) + " after " +
                                         std::to_string(max_shape_attempts) +
                                         " seeds; the last said: " + error.what());
            }
        }
        seed = shapes::splitmix64(seed + 0x9e3779b97f4a7c15ULL);
    }
}

bool sphericity_support_ok(const Distribution& d) {
    if (!find_problems(d).empty()) return false;
    const Interval range = support(d);
    return range.lower >= min_target_sphericity && range.upper <= max_target_sphericity;
}

void check_weight(std::vector<SweepProblem>& problems, const std::string& name, double weight,
                  double& total) {
    if (!(weight >= 0.0 && std::isfinite(weight))) {
        problems.push_back({kind_key, "weight " + number_text(weight) + " of \"" + name +
                                          "\": must be >= 0 and finite"});
    } else {
        total += weight;
    }
}

bool lacks_shape(const engine::Scenario& base, shapes::RockKind kind) {
    return kind == shapes::RockKind::custom && base.rocks.front().rock.shape == nullptr;
}

void check_kind_list(std::vector<SweepProblem>& problems, const SweepSpec& spec,
                     const engine::Scenario& base, double& total) {
    for (std::size_t i = 0; i < spec.kinds.size(); ++i) {
        const std::string name(shapes::to_string(spec.kinds[i]));
        if (std::count(spec.kinds.begin(), spec.kinds.begin() + static_cast<std::ptrdiff_t>(i),
                       spec.kinds[i]) > 0) {
            problems.push_back(
                {kind_key, "\"" + name + "\" is listed twice: list each shape once"});
        }
        if (lacks_shape(base, spec.kinds[i])) {
            problems.push_back({kind_key,
                                "\"custom\": stands for the base rock's custom shape (mesh, "
                                "catalogue entry or vertices), and rocks[0] has none"});
        }
        check_weight(problems, name, spec.kind_weights[i], total);
    }
}

void check_entry_list(std::vector<SweepProblem>& problems, const SweepSpec& spec, double& total) {
    for (std::size_t i = 0; i < spec.entries.size(); ++i) {
        const std::shared_ptr<const shapes::CustomShape>& entry = spec.entries[i];
        if (entry == nullptr) {
            problems.push_back(
                {kind_key, "entry " + std::to_string(i) + " has no shape: give it a hull"});
            continue;
        }
        const std::string quoted = "\"" + entry->name + "\"";
        if (entry->name.empty()) {
            problems.push_back(
                {kind_key, "entry " + std::to_string(i) + " has no name: name each entry"});
        } else if (is_reserved_shape_name(entry->name)) {
            problems.push_back({kind_key, "entry " + quoted +
                                              ": sphere, massive, planar, custom and generated "
                                              "name other shapes; rename the entry"});
        }
        for (std::size_t j = 0; j < i; ++j) {
            if (spec.entries[j] != nullptr && spec.entries[j]->name == entry->name) {
                problems.push_back({kind_key, quoted + " is listed twice: list each shape once"});
                break;
            }
        }
        check_weight(problems, entry->name, spec.entry_weights[i], total);
    }
}

}  // namespace

namespace detail {

bool check_shapes(std::vector<SweepProblem>& problems, const SweepSpec& spec,
                  const engine::Scenario& base) {
    const std::size_t before = problems.size();
    if (spec.kinds.empty() && spec.entries.empty() && spec.generated_weight == 0.0) {
        problems.push_back({kind_key, "[]: must name at least one shape"});
        return false;
    }
    if (spec.kinds.size() != spec.kind_weights.size() ||
        spec.entries.size() != spec.entry_weights.size()) {
        const std::size_t shapes = spec.kinds.size() + spec.entries.size();
        const std::size_t weights = spec.kind_weights.size() + spec.entry_weights.size();
        problems.push_back({kind_key, std::to_string(shapes) + " shapes and " +
                                          std::to_string(weights) +
                                          " weights: must give one weight per shape"});
        return false;
    }
    double total = 0.0;
    check_kind_list(problems, spec, base, total);
    check_entry_list(problems, spec, total);
    check_weight(problems, generated_name, spec.generated_weight, total);
    if (!(total > 0.0))
        problems.push_back({kind_key, "every weight is 0: at least one must be > 0"});
    const bool generated = spec.generated_weight > 0.0;
    if (generated && !spec.sphericity) {
        problems.push_back({kind_key,
                            "\"generated\": needs sweep.rock.sphericity, the "
                            "distribution of the generated rocks' target sphericity"});
    }
    if (spec.sphericity && !generated) {
        problems.push_back({sphericity_key, describe(*spec.sphericity) +
                                                ": no generated rock is drawn: give "
                                                "\"generated\" a weight in sweep.rock.kind"});
    }
    // find_problems reports the distribution's own parameters; here only its support.
    if (spec.sphericity && find_problems(*spec.sphericity).empty() &&
        !sphericity_support_ok(*spec.sphericity)) {
        const Distribution& d = *spec.sphericity;
        const Interval range = support(d);
        problems.push_back(
            {sphericity_key,
             describe(d) + ": every target must lie in [" + number_text(min_target_sphericity) +
                 ", " + number_text(max_target_sphericity) +
                 "] (Wadell sphericity; generated rocks reach it for every seed, without "
                 "slivers)" +
                 (std::isinf(range.lower) || std::isinf(range.upper)
                      ? "; truncate the distribution with min and max"
                      : "")});
    }
    return problems.size() == before;
}

void draw_shape(const SweepSpec& spec, const engine::Scenario& base, double u_shape,
                double u_sphericity, std::uint64_t first_shape_seed, SampleInputs& s) {
    s.shape.clear();
    s.target_sphericity = std::numeric_limits<double>::quiet_NaN();
    s.shape_seed = 0;
    std::vector<double> weights = spec.kind_weights;
    weights.insert(weights.end(), spec.entry_weights.begin(), spec.entry_weights.end());
    weights.push_back(spec.generated_weight);
    const std::size_t choice = choose(weights, u_shape);
    if (choice < spec.kinds.size()) {
        s.kind = spec.kinds[choice];
        s.custom_shape =
            s.kind == shapes::RockKind::custom ? base.rocks.front().rock.shape : nullptr;
        return;
    }
    s.kind = shapes::RockKind::custom;
    if (choice < spec.kinds.size() + spec.entries.size()) {
        const std::shared_ptr<const shapes::CustomShape>& entry =
            spec.entries[choice - spec.kinds.size()];
        assert(entry != nullptr);
        s.shape = entry->name;
        s.custom_shape = entry;
        return;
    }
    assert(spec.sphericity);
    s.shape = generated_name;
    s.target_sphericity = inverse_cdf(*spec.sphericity, u_sphericity);
    Generated generated = generate(s.target_sphericity, first_shape_seed);
    s.shape_seed = generated.seed;
    s.custom_shape =
        generated_shape(s.target_sphericity, generated.seed, std::move(generated.rock.hull));
}

}  // namespace detail

bool is_reserved_shape_name(std::string_view name) {
    return std::find(reserved_shape_names.begin(), reserved_shape_names.end(), name) !=
           reserved_shape_names.end();
}

std::vector<DrawableShape> drawable_shapes(const SweepSpec& spec, const engine::Scenario& base) {
    std::vector<DrawableShape> drawn;
    const auto add = [&drawn](std::string name, shapes::RockKind kind,
                              std::shared_ptr<const shapes::CustomShape> shape, double allowance) {
        const double radius =
            (shape ? shapes::make_rock(*shape, 1.0) : shapes::make_rock(kind, 1.0)).bounding_radius;
        drawn.push_back({std::move(name), kind, std::move(shape), allowance * radius});
    };
    const std::shared_ptr<const shapes::CustomShape>& base_shape =
        base.rocks.empty() ? nullptr : base.rocks.front().rock.shape;
    for (std::size_t i = 0; i < spec.kinds.size() && i < spec.kind_weights.size(); ++i) {
        const shapes::RockKind kind = spec.kinds[i];
        if (!(spec.kind_weights[i] > 0.0)) continue;
        if (kind != shapes::RockKind::custom) {
            add(std::string(shapes::to_string(kind)), kind, nullptr, 1.0);
        } else if (base_shape != nullptr) {
            add("custom", kind, base_shape, 1.0);
        }
    }
    for (std::size_t i = 0; i < spec.entries.size() && i < spec.entry_weights.size(); ++i) {
        if (spec.entry_weights[i] > 0.0 && spec.entries[i] != nullptr) {
            add(spec.entries[i]->name, shapes::RockKind::custom, spec.entries[i], 1.0);
        }
    }
    if (spec.generated_weight > 0.0 && spec.sphericity && sphericity_support_ok(*spec.sphericity)) {
        // The lowest target gives the most elongated, hence widest for their size, rocks.
        const double lowest = support(*spec.sphericity).lower;
        std::shared_ptr<const shapes::CustomShape> widest;
        double widest_radius = 0.0;
        for (std::uint64_t seed = 0; seed < reference_seeds; ++seed) {
            Generated generated = generate(lowest, seed);
            auto shape = generated_shape(lowest, generated.seed, std::move(generated.rock.hull));
            const double radius = shapes::make_rock(*shape, 1.0).bounding_radius;
            if (radius > widest_radius) {
                widest_radius = radius;
                widest = std::move(shape);
            }
        }
        add("generated rock of sphericity " + short_number(lowest), shapes::RockKind::custom,
            std::move(widest), generated_radius_allowance);
    }
    return drawn;
}

std::shared_ptr<const shapes::CustomShape> sample_shape(const SweepSpec& spec,
                                                        const engine::Scenario& base,
                                                        const SampleInputs& inputs) {
    if (inputs.kind != shapes::RockKind::custom) return nullptr;
    if (inputs.shape.empty()) {
        if (base.rocks.empty() || base.rocks.front().rock.shape == nullptr) {
            throw std::invalid_argument("sample " + std::to_string(inputs.index) +
                                        ": kind custom stands for the base rock's own shape, "
                                        "and the scenario's first rock has none");
        }
        return base.rocks.front().rock.shape;
    }
    if (inputs.shape == generated_name) {
        const double target = inputs.target_sphericity;
        if (!(target >= min_target_sphericity && target <= max_target_sphericity)) {
            throw std::invalid_argument("sample " + std::to_string(inputs.index) +
                                        ": generated rock with target " + "sphericity " +
                                        number_text(target) + ": must be in [" +
                                        number_text(min_target_sphericity) + ", " +
                                        number_text(max_target_sphericity) + "]");
        }
        return generated_shape(target, inputs.shape_seed,
                               shapes::rock_with_sphericity(target, inputs.shape_seed).hull);
    }
    std::string names;
    for (const std::shared_ptr<const shapes::CustomShape>& entry : spec.entries) {
        if (entry == nullptr) continue;
        if (entry->name == inputs.shape) return entry;
        names += (names.empty() ? "" : ", ") + entry->name;
    }
    throw std::invalid_argument(
        "sample " + std::to_string(inputs.index) + ": shape \"" + inputs.shape +
        "\" is not an entry of the sweep (entries: " + (names.empty() ? "none" : names) + ")");
}

}  // namespace rockfall::risk
