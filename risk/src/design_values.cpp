// UNI 11211-4 style design values from a sample of speeds and heights (see design_values.hpp).

#include "risk/design_values.hpp"

#include "validation.hpp"

#include "risk/statistics.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rockfall::risk {
namespace {

// The sample sorted, after checking that it is not empty and every value is finite and >= 0.
std::vector<double> sorted_sample(const char* name, const char* unit, std::vector<double> values) {
    if (values.empty()) {
        throw std::invalid_argument(std::string(name) + ": the sample is empty");
    }
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (!(std::isfinite(values[i]) && values[i] >= 0.0)) {
            std::ostringstream message;
            message << name << '[' << i << "] = " << values[i] << ' ' << unit
                    << ": must be finite and >= 0";
            throw std::invalid_argument(message.str());
        }
    }
    std::sort(values.begin(), values.end());
    return values;
}

void require_factor(const char* name, double value) {
    detail::require_at_least(name, value, "(dimensionless)", 1.0);
}

}  // namespace

DesignValues uni_design_values(const std::vector<double>& speeds,
                               const std::vector<double>& heights, double mass, double percentile,
                               const PartialFactors& factors) {
    detail::require_positive("mass", mass, "kg");
    detail::require_range("percentile", percentile, "(fraction)", 0.0, 1.0, true, true);
    require_factor("gamma_Tr", factors.trajectory);
    require_factor("gamma_Dp", factors.survey);
    require_factor("gamma_VolF1", factors.volume);
    require_factor("gamma_gamma", factors.unit_weight);

    DesignValues d;
    d.percentile = percentile;
    d.speed_count = speeds.size();
    d.height_count = heights.size();
    d.characteristic_speed = quantile(sorted_sample("speeds", "m/s", speeds), percentile);
    d.characteristic_height = quantile(sorted_sample("heights", "m", heights), percentile);
    const double kinematic_factor = factors.trajectory * factors.survey;
    d.design_speed = d.characteristic_speed * kinematic_factor;
    d.design_height = d.characteristic_height * kinematic_factor;
    d.design_mass = mass * factors.volume * factors.unit_weight;
    d.design_energy = 0.5 * d.design_mass * d.design_speed * d.design_speed;
    return d;
}

}  // namespace rockfall::risk
