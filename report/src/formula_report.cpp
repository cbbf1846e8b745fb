// The evaluation and echo of one impact design formula (see formula_report.hpp).

#include "report/formula_report.hpp"

#include "report/text_format.hpp"

#include "risk/cushion_formulas.hpp"
#include "risk/formulas.hpp"

#include <stdexcept>

namespace rockfall::report {
namespace {

constexpr double kilo = 1.0e3;  // kg per t, N per kN, Pa per kN/m2, J per kJ

// The range the formula was made for, in words.
void add_validity(FormulaReport& r, const std::string& text) {
    r.add("validity", text, {{"validity", text}});
}

template <typename T>
const T& required(const std::optional<T>& value, const char* message) {
    if (!value) throw std::invalid_argument(message);
    return *value;
}

// The impact velocity from --velocity, or from the equivalent fall height v = sqrt(2 g H).
double impact_velocity(const FormulaInputs& args) {
    if (args.velocity) return *args.velocity;
    if (args.height) return risk::jra_impact_velocity(*args.height);
    throw std::invalid_argument("give the impact --velocity (m/s) or the fall --height (m)");
}

void add_formula(FormulaReport& r, const FormulaInputs& args, const std::string& source) {
    r.add("formula", args.name + " (" + source + ")", {{"formula", args.name}, {"source", source}});
}

void add_mass(FormulaReport& r, double mass) {
    r.add("mass", fmt("%.6g kg", mass) + fmt(" (%.6g t)", mass / kilo),
          {{"mass_kg", mass}, {"mass_t", mass / kilo}});
}

void add_kinematics(FormulaReport& r, double velocity) {
    const double height = risk::jra_equivalent_height(velocity);
    r.add("velocity", fmt("%.6g m/s", velocity), {{"velocity_m_s", velocity}});
    r.add("equivalent height", fmt("%.6g m (v^2 / 2g)", height), {{"equivalent_height_m", height}});
}

void add_load(FormulaReport& r, const std::string& label, double load) {
    r.add(label, fmt("%.2f kN", load / kilo) + fmt(" (%.6g N)", load),
          {{"peak_load_kN", load / kilo}, {"peak_load_N", load}});
}

// `jra` is the handbook formula (alpha = beta = 1); its Lame constant depends on the hit
// material and the handbook gives no single value, so it must be given. `seed` starts from
// seed 000's preset for the shape; explicit values replace the preset's.
FormulaReport evaluate_jra(const FormulaInputs& args) {
    FormulaReport r;
    std::string preset;  // the seed preset's shape name, while no factor replaces its own
    risk::ImpactCoefficients c;
    if (args.name == "jra") {
        c = risk::jra_coefficients(required(args.lambda,
                                            "jra needs --lambda (Pa), the Lame constant of the hit "
                                            "material; seed 000 identified 5e8 Pa for concrete"));
        add_formula(r, args, "Japan Road Association, Rock Fall Measures Handbook (2000)");
    } else {
        const risk::ImpactShape shape = risk::parse_impact_shape(args.shape.value_or("sphere"));
        c = risk::seed_coefficients(shape);
        if (!args.alpha && !args.beta) preset = risk::to_string(shape);
        add_formula(r, args, "seed 000 proposal, alpha beta times the handbook formula");
    }
    if (args.lambda) c.lambda = *args.lambda;
    if (args.alpha) c.alpha = *args.alpha;
    if (args.beta) c.beta = *args.beta;
    const double velocity = impact_velocity(args);
    const double load = risk::jra_impact_force(args.mass, velocity, c);

    r.json["shape"] = nullptr;
    if (!preset.empty()) r.add("shape preset", preset, {{"shape", preset}});
    add_mass(r, args.mass);
    add_kinematics(r, velocity);
    r.add("lambda", fmt("%.6g Pa", c.lambda) + fmt(" (%.6g kN/m2)", c.lambda / kilo),
          {{"lambda_Pa", c.lambda}, {"lambda_kN_m2", c.lambda / kilo}});
    r.add("alpha", fmt("%.6g", c.alpha), {{"alpha", c.alpha}});
    r.add("beta", fmt("%.6g", c.beta), {{"beta", c.beta}});
    r.add("g", fmt("%.6g m/s2", risk::jra_gravity), {{"g_m_s2", risk::jra_gravity}});
    add_load(r, "peak load", load);
    add_validity(
        r, args.name == "jra"
               ? "Hertz contact of elastic spheres: compact rocks, elastic impact"
               : "coefficients identified on model rocks of about 20 cm and 10 kg at a few m/s "
                 "on a concrete wall");
    return r;
}

// The rock radius: given, or that of the sphere of the rock's volume at the given density.
double rock_radius(const FormulaInputs& args, FormulaReport& r) {
    if (args.radius && args.density) {
        throw std::invalid_argument("give --radius (m) or --density (kg/m3), not both");
    }
    if (args.density) {
        const double radius = risk::equivalent_radius(args.mass, *args.density);
        r.add("density", fmt("%.6g kg/m3", *args.density), {{"density_kg_m3", *args.density}});
        r.add("radius", fmt("%.6g m (sphere of the rock's volume)", radius),
              {{"radius_m", radius}});
        return radius;
    }
    const double radius =
        required(args.radius,
                 "give the rock --radius (m), or its --density (kg/m3) to use the radius of "
                 "the sphere of its volume");
    r.add("radius", fmt("%.6g m", radius), {{"radius_m", radius}});
    return radius;
}

FormulaReport evaluate_cushion(const FormulaInputs& args) {
    FormulaReport r;
    const bool astra = args.name == "astra";
    add_formula(r, args,
                astra ? "ASTRA 12 006 (2008), rockfall on protection galleries"
                      : "Labiouse, Descoeudres and Montani (1996), rock sheds");
    add_mass(r, args.mass);
    const double velocity = impact_velocity(args);
    add_kinematics(r, velocity);
    const double energy = 0.5 * args.mass * velocity * velocity;
    r.add("kinetic energy", fmt("%.6g J", energy) + fmt(" (%.6g kJ)", energy / kilo),
          {{"kinetic_energy_J", energy}});
    const double radius = rock_radius(args, r);
    const double modulus =
        required(args.modulus, "give --modulus (Pa), the plate-load modulus M_E of the cushion");
    r.add("cushion modulus M_E", fmt("%.6g Pa", modulus) + fmt(" (%.6g kN/m2)", modulus / kilo),
          {{"cushion_modulus_Pa", modulus}, {"cushion_modulus_kN_m2", modulus / kilo}});
    if (!astra) {
        add_load(r, "peak force",
                 risk::labiouse_impact_force({args.mass, velocity, radius, modulus}));
        add_validity(
            r,
            "rigid block on an elastic cushion thick compared with the block; drop tests up "
            "to about 1 t and 10 m on gravel");
        return r;
    }
    const double thickness =
        required(args.thickness, "give the cushion --thickness (m) for the astra formula");
    const double phi = required(args.friction_angle,
                                "give the cushion's --friction-angle (deg) for the astra formula");
    r.add("cushion thickness", fmt("%.6g m", thickness), {{"cushion_thickness_m", thickness}});
    r.add("friction angle", fmt("%.6g deg", phi), {{"friction_angle_deg", phi}});
    add_load(r, "equivalent static force F_k",
             risk::astra_impact_force({args.mass, velocity, radius, modulus, thickness, phi}));
    add_validity(
        r,
        "soil or gravel cushion about a block diameter thick or more; characteristic value, "
        "before the guideline's design factors");
    return r;
}

}  // namespace

void FormulaReport::add(std::string label, std::string text, const nlohmann::json& fields) {
    lines.emplace_back(std::move(label), std::move(text));
    json.update(fields);
}

FormulaReport evaluate_formula(const FormulaInputs& args) {
    if (args.name == "jra" || args.name == "seed") return evaluate_jra(args);
    return evaluate_cushion(args);
}

FormulaReport evaluate_design_values(const FormulaInputs& args, const risk::DesignSample& sample) {
    if (!(args.percentile > 0.0 && args.percentile < 100.0)) {
        throw std::invalid_argument(
            fmt("--percentile = %g %%: must be in (0, 100)", args.percentile));
    }
    const risk::DesignValues d = risk::uni_design_values(sample.speeds, sample.heights, args.mass,
                                                         args.percentile / 100.0, args.factors);
    const risk::PartialFactors& f = args.factors;
    FormulaReport r;
    add_formula(r, args, "design values in the manner of UNI 11211-4:2012");
    r.add("sample", sample.source + " (" + std::to_string(sample.speeds.size()) + " rows)",
          {{"sample", sample.source}, {"rows", sample.speeds.size()}});
    r.add("percentile", fmt("%.6g %%", args.percentile), {{"percentile_percent", args.percentile}});
    add_mass(r, args.mass);
    r.add("characteristic velocity v_t", fmt("%.6g m/s", d.characteristic_speed),
          {{"characteristic_velocity_m_s", d.characteristic_speed}});
    r.add("characteristic height h_t", fmt("%.6g m", d.characteristic_height),
          {{"characteristic_height_m", d.characteristic_height}});
    r.add("partial factors",
          fmt("gamma_Tr %.6g", f.trajectory) + fmt(", gamma_Dp %.6g", f.survey) +
              fmt(", gamma_VolF1 %.6g", f.volume) + fmt(", gamma_gamma %.6g", f.unit_weight),
          {{"gamma_Tr", f.trajectory},
           {"gamma_Dp", f.survey},
           {"gamma_VolF1", f.volume},
           {"gamma_gamma", f.unit_weight}});
    r.add("design velocity v_d", fmt("%.6g m/s", d.design_speed),
          {{"design_velocity_m_s", d.design_speed}});
    r.add("design height h_d", fmt("%.6g m", d.design_height),
          {{"design_height_m", d.design_height}});
    r.add("design mass m_d", fmt("%.6g kg", d.design_mass), {{"design_mass_kg", d.design_mass}});
    r.add("design energy E_d",
          fmt("%.2f kJ", d.design_energy / kilo) + fmt(" (%.6g J)", d.design_energy),
          {{"design_energy_J", d.design_energy}, {"design_energy_kJ", d.design_energy / kilo}});
    add_validity(r,
                 "action side only: compare E_d with the barrier's energy class over gamma_E, and "
                 "h_d plus the free margin with its height");
    return r;
}

void print_formula_report(std::ostream& out, const FormulaReport& report) {
    for (const auto& [label, text] : report.lines) out << label << ": " << text << '\n';
}

}  // namespace rockfall::report
