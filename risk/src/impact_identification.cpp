// Seed 000's identification over the shape classes (see impact_identification.hpp).

#include "risk/impact_identification.hpp"

#include <algorithm>
#include <iterator>
#include <stdexcept>

namespace rockfall::risk {

std::vector<ImpactRow> rows_of_shape(const std::vector<ImpactRow>& rows, ImpactShape shape) {
    std::vector<ImpactRow> out;
    std::copy_if(rows.begin(), rows.end(), std::back_inserter(out),
                 [&](const ImpactRow& r) { return r.shape == shape; });
    return out;
}

std::string shape_counts(const std::vector<ImpactRow>& rows) {
    std::string out;
    for (const ImpactShape shape : all_impact_shapes) {
        const std::size_t n = rows_of_shape(rows, shape).size();
        if (n > 0) {
            out +=
                (out.empty() ? "" : ", ") + std::string(to_string(shape)) + ' ' + std::to_string(n);
        }
    }
    return out;
}

Identification identify_shapes(const std::vector<ImpactRow>& rows,
                               const IdentificationOptions& args, const std::string& source) {
    FitOptions base;
    base.form = args.form;
    base.reference_mass = args.reference_mass;

    Identification out;
    std::vector<ImpactShape> shapes;
    for (const ImpactShape shape : all_impact_shapes) {
        const std::size_t n = rows_of_shape(rows, shape).size();
        if (n >= kMinFitRows) {
            shapes.push_back(shape);
        } else if (n > 0) {
            out.too_few.emplace_back(shape, n);
        }
    }
    if (args.shape) {
        const ImpactShape wanted = parse_impact_shape(*args.shape);
        const std::size_t n = rows_of_shape(rows, wanted).size();
        if (n < kMinFitRows) {
            throw std::invalid_argument(source + " has " + std::to_string(n) + " rows of shape " +
                                        *args.shape + ": a fit needs " +
                                        std::to_string(kMinFitRows) +
                                        " (it has: " + shape_counts(rows) + ")");
        }
        shapes = {wanted};
        out.too_few.clear();
    }
    if (shapes.empty()) {
        throw std::invalid_argument(source + ": no shape has the " + std::to_string(kMinFitRows) +
                                    " rows a fit needs (it has: " + shape_counts(rows) + ")");
    }

    std::optional<double> sphere_lambda;
    const std::vector<ImpactRow> spheres = rows_of_shape(rows, ImpactShape::sphere);
    if (!args.lambda && spheres.size() >= kMinFitRows) {
        sphere_lambda = fit_impacts(spheres, base).coefficients.lambda;
    }
    std::vector<ShapeFit>& results = out.fits;
    for (const ImpactShape shape : shapes) {
        ShapeFit result;
        FitOptions options = base;
        if (args.lambda) {
            options.lambda = args.lambda;
            result.lambda_source = LambdaSource::given;
        } else if (sphere_lambda && shape != ImpactShape::sphere) {
            options.lambda = sphere_lambda;
            result.lambda_source = LambdaSource::spheres;
        }
        result.shape = shape;
        result.rows = rows_of_shape(rows, shape);
        result.fit = fit_impacts(result.rows, options);
        results.push_back(std::move(result));
    }
    return out;
}

}  // namespace rockfall::risk
