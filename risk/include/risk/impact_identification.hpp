#pragma once
/// Seed 000's identification over the shape classes of a set of impacts: lambda identified on
/// the spheres (beta = 1), then held fixed while beta is identified for the other shapes;
/// alpha on the mean + 1 sigma line of each (risk/impact_fit.hpp does one shape).

#include "risk/impact_fit.hpp"

#include <cstddef>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rockfall::risk {

/// Fewest rows a shape needs: the scatter has n - 2 degrees of freedom.
inline constexpr std::size_t kMinFitRows = 3;

/// Where a shape's lambda comes from.
enum class LambdaSource {
    /// Identified on the shape's own mean line, beta = 1.
    identified,
    /// Given, and beta identified on the mean line.
    given,
    /// Identified on the same impacts' spheres, and beta identified on the mean line.
    spheres,
};

/// One shape's rows and the coefficients identified from them.
struct ShapeFit {
    /// The shape class.
    ImpactShape shape = ImpactShape::sphere;
    /// Its rows (SI units).
    std::vector<ImpactRow> rows;
    /// The identification.
    ImpactFit fit;
    LambdaSource lambda_source = LambdaSource::identified;
};

/// What to identify.
struct IdentificationOptions {
    /// Only this shape (its name: sphere, massive or planar); all shapes with enough rows
    /// without one.
    std::optional<std::string> shape;
    /// A Lame constant (Pa) held fixed for every shape.
    std::optional<double> lambda;
    /// Regression form and reference mass of each fit (impact_fit.hpp).
    RegressionForm form = RegressionForm::power;
    std::optional<double> reference_mass;
};

/// The fits, and the shapes present with fewer than kMinFitRows rows, not fitted.
struct Identification {
    std::vector<ShapeFit> fits;
    std::vector<std::pair<ImpactShape, std::size_t>> too_few;
};

/// The rows of one shape, in order.
std::vector<ImpactRow> rows_of_shape(const std::vector<ImpactRow>& rows, ImpactShape shape);

/// Every shape with enough rows (or only options.shape). Throws std::invalid_argument, naming
/// `source` and the row count of each shape, when no shape (or the asked one) has enough.
Identification identify_shapes(const std::vector<ImpactRow>& rows,
                               const IdentificationOptions& options, const std::string& source);

/// The row count of each shape present: "sphere 4, planar 2".
std::string shape_counts(const std::vector<ImpactRow>& rows);

}  // namespace rockfall::risk
