// The engine's analytic checks of the verification report: the motion scenes at two step sizes
// and the pure normal wall impacts (the set-ups of tests/engine/test_motion.cpp and
// test_wall_hits.cpp, engine/verification_scenes.hpp).

#include "report/text_format.hpp"
#include "validate_sections.hpp"

#include "engine/simulation.hpp"
#include "engine/verification_scenes.hpp"
#include "engine/wall_contact.hpp"

#include <cmath>
#include <numbers>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

namespace scenes = engine::scenes;
using report::fmt;
using report::VvCheck;
using shapes::RockKind;

constexpr double g = scenes::gravity;
constexpr double step_sizes[] = {1e-3, 5e-4};  // s: the default step and half of it

// "dt1ms", "dt0.5ms" for ids; "dt 1 ms" for labels.
std::string dt_id(double dt) { return fmt("dt%gms", dt * 1e3); }
std::string dt_text(double dt) { return fmt("dt %g ms", dt * 1e3); }

report::VvTable motion_table() {
    report::VvTable table{"Free fall, sliding and rolling on a straight plane (0.2 m rock)", {}};
    for (const double dt : step_sizes) {
        engine::Scenario fall = scenes::plane_scenario(0.0, RockKind::sphere, {}, dt);
        fall.rocks.front().release.height = 10.0;
        fall.numerics.max_time = 1.0;  // 4.9 m of fall: it never lands
        const std::vector<engine::RockState> states = scenes::trajectory(fall, 0.1);
        const engine::RockState& end = scenes::state_at(states, 1.0);
        const double t = end.time;
        // Symplectic Euler: the velocity is exact, the position lags by g t dt / 2.
        table.checks.push_back(report::make_check(
            "free_fall.drop." + dt_id(dt),
            "free fall: drop in " + fmt("%.3g s", t) + ", " + dt_text(dt), "m", 0.5 * g * t * t,
            "g t^2 / 2", states.front().position.z() - end.position.z(), 0.002));
        table.checks.push_back(
            report::make_check("free_fall.speed." + dt_id(dt),
                               "free fall: speed at " + fmt("%.3g s", t) + ", " + dt_text(dt),
                               "m/s", g * t, "g t", -end.velocity.z(), 1e-6));
    }
    const double angle = 30.0;
    const double sin_t = std::sin(scenes::radians(angle));
    const double cos_t = std::cos(scenes::radians(angle));
    // A block slides at g (sin t - mu cos t); a sphere rolls at 5/7 g (sin t - mu_r cos t) from
    // the torque balance with the resisting moment mu_r r N.
    struct Case {
        std::string id;
        std::string label;
        RockKind kind;
        engine::Material material;
    };
    const Case cases[] = {
        {"slide.mu0.3", "block sliding on 30 deg, mu 0.3", RockKind::massive, {0.3, 0.0, 0.0}},
        {"slide.mu0.45", "block sliding on 30 deg, mu 0.45", RockKind::massive, {0.45, 0.0, 0.0}},
        {"roll", "sphere rolling without slip on 30 deg", RockKind::sphere, {1.0, 0.0, 0.0}},
        {"roll.resistance0.05",
         "sphere rolling on 30 deg, rolling resistance 0.05",
         RockKind::sphere,
         {1.0, 0.0, 0.05}},
    };
    for (const Case& c : cases) {
        const bool slides = c.kind == RockKind::massive;
        const double expected =
            slides ? g * (sin_t - c.material.friction * cos_t)
                   : 5.0 / 7.0 * g * (sin_t - c.material.rolling_resistance * cos_t);
        const std::string source = slides ? "g (sin t - mu cos t)"
                                   : c.material.rolling_resistance > 0.0
                                       ? "5/7 g (sin t - mu_r cos t)"
                                       : "5/7 g sin t";
        for (const double dt : step_sizes) {
            const std::vector<engine::RockState> states =
                scenes::trajectory(scenes::plane_scenario(angle, c.kind, c.material, dt), 0.01);
            table.checks.push_back(report::make_check(
                c.id + "." + dt_id(dt), c.label + ": mean acceleration 0.5-2 s, " + dt_text(dt),
                "m/s2", expected, source,
                scenes::mean_acceleration(states, scenes::downslope(angle), 0.5, 2.0), 0.02));
        }
    }
    return table;
}

struct BounceCase {
    RockKind kind;
    double angle_deg;
    double restitution;
};

std::string bounce_label(const BounceCase& c) {
    return std::string(c.kind == RockKind::sphere ? "sphere" : "block (face down)") +
           (c.angle_deg == 0.0 ? " on the flat" : fmt(" on %g deg", c.angle_deg)) +
           fmt(", e %g", c.restitution);
}

std::optional<scenes::Bounce> bounce_of(const BounceCase& c, double dt) {
    try {
        return scenes::first_bounce(c.angle_deg, c.kind, c.restitution, dt, 1.0);
    } catch (const std::runtime_error&) {
        return std::nullopt;  // no rebound: the check is a MISS
    }
}

report::VvTable bounce_table(report::VvSection& section) {
    const std::vector<BounceCase> cases = {
        {RockKind::sphere, 0.0, 0.3},  {RockKind::sphere, 0.0, 0.5},  {RockKind::sphere, 0.0, 0.8},
        {RockKind::sphere, 29.0, 0.3}, {RockKind::sphere, 43.0, 0.8}, {RockKind::massive, 0.0, 0.3},
        {RockKind::massive, 0.0, 0.8}};
    report::VvTable table{"First bounce after a 1 m drop (gap along the normal)", {}};
    report::Series line = report::line_series("e^2 h (analytic)", "#444444");
    for (int i = 0; i <= 20; ++i) {
        line.x.push_back(0.05 * i);
        line.y.push_back(0.05 * i * 0.05 * i);
    }
    report::Series spheres =
        report::point_series("sphere (flat, inclined), dt 1 ms", "#1f77b4", report::Marker::circle);
    spheres.marker_size = 7.0;  // larger, under the blocks' squares where they coincide
    report::Series blocks =
        report::point_series("block, dt 1 ms", "#d62728", report::Marker::square);
    for (const BounceCase& c : cases) {
        for (const double dt : step_sizes) {
            const std::optional<scenes::Bounce> b = bounce_of(c, dt);
            const std::string id =
                std::string(c.kind == RockKind::sphere ? "bounce.sphere" : "bounce.block") +
                fmt(".%gdeg", c.angle_deg) + fmt(".e%g.", c.restitution) + dt_id(dt);
            const double nan = std::nan("");
            VvCheck height = report::make_check(
                id + ".height", bounce_label(c) + ": rebound, " + dt_text(dt), "m",
                c.restitution * c.restitution, "e^2 h", b ? b->rebound_height : nan, 0.05);
            VvCheck ratio = report::make_check(
                id + ".ratio", bounce_label(c) + ": speed ratio, " + dt_text(dt), "", c.restitution,
                "e (Newton)", b ? b->velocity_ratio : nan, 0.025);
            if (!b) height.note = ratio.note = "no rebound within 1.5 s";
            table.checks.push_back(height);
            table.checks.push_back(ratio);
            if (b && dt == step_sizes[0]) {
                report::Series& s = c.kind == RockKind::sphere ? spheres : blocks;
                s.x.push_back(c.restitution);
                s.y.push_back(b->rebound_height);
            }
        }
    }
    report::Plot plot = report::vv_plot("Rebound height after a 1 m drop", "restitution e",
                                        "rebound height (m)", {line, spheres, blocks});
    plot.x_max = 1.0;
    section.figures.push_back(
        {plot,
         "Rise of the centre after the first bounce along the plane's normal against the "
         "restitution, flat and inclined planes at dt 1 ms, and the analytic e^2 h."});
    return table;
}

// The wall scenes: a 0.2 m sphere of 2600 kg/m3 at 8 m/s, a pure normal impact.
constexpr double radius = 0.1;
constexpr double density = 2600.0;
constexpr double speed = 8.0;
const double mass = density * 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;

engine::WallContact linear_contact(double stiffness, int steps = 0) {
    engine::WallContact contact;
    contact.model = engine::WallContact::Model::linear;
    contact.linear_stiffness = stiffness;
    if (steps > 0) contact.steps_per_contact = steps;
    return contact;
}

// The only hit of the run, or none when there were none or several.
std::optional<engine::WallHit> single_hit(const engine::WallContact& contact, double e) {
    const engine::Outcome outcome =
        engine::simulate(scenes::wall_scenario(contact, e, 2.0 * radius, speed, density), 1);
    if (outcome.rocks.size() != 1 || outcome.rocks[0].wall_hits.size() != 1) return std::nullopt;
    return outcome.rocks[0].wall_hits[0];
}

double effective_modulus_of(const engine::WallContact& c) {
    return engine::effective_modulus(c.rock_youngs_modulus, c.rock_poisson_ratio,
                                     c.wall_youngs_modulus, c.wall_poisson_ratio);
}

report::Series force_history(const std::string& label, const char* color,
                             const engine::WallHit& hit) {
    report::Series s = report::line_series(label, color);
    for (const engine::ForceSample& f : hit.history) {
        s.x.push_back(1e3 * (f.time - hit.start_time));
        s.y.push_back(1e-3 * f.normal);
    }
    return s;
}

report::VvTable wall_table(report::VvSection& section) {
    report::VvTable table{"Normal wall impact: 0.2 m sphere, 2600 kg/m3, 8 m/s, no friction", {}};
    const double nan = std::nan("");
    const auto value = [](const std::optional<engine::WallHit>& h, double engine::WallHit::*field) {
        return h ? (*h).*field : std::nan("");
    };
    const double e = 0.3;
    for (const auto& [name, contact] : {std::pair{"Hertz-Tsuji", engine::WallContact{}},
                                        std::pair{"linear", linear_contact(2e8)}}) {
        const std::optional<engine::WallHit> hit = single_hit(contact, e);
        const std::string model = name == std::string("linear") ? "linear" : "hertz";
        const double vn = value(hit, &engine::WallHit::normal_speed);
        table.checks.push_back(report::make_check(
            "wall_impulse." + model, std::string("impulse, ") + name + " law, e 0.3", "N s",
            mass * (1.0 + e) * vn, "m (1 + e) v_n (v_n as recorded)",
            value(hit, &engine::WallHit::normal_impulse), 0.02));
        const double momentum = hit ? mass * (hit->velocity_before - hit->velocity_after).x() : nan;
        table.checks.push_back(
            report::make_check("wall_impulse." + model + ".momentum",
                               std::string("impulse against momentum change, ") + name, "N s",
                               momentum, "m (v_before - v_after) of the rock",
                               value(hit, &engine::WallHit::normal_impulse), 0.02));
    }
    const engine::WallContact hertz_contact;
    const double e_star = effective_modulus_of(hertz_contact);
    const double kn = 4.0 / 3.0 * e_star * std::sqrt(radius);
    std::optional<engine::WallHit> elastic;
    for (const double restitution : {0.95, 0.3}) {
        const std::optional<engine::WallHit> hit = single_hit(hertz_contact, restitution);
        const double vn = hit ? hit->normal_speed : speed;
        const double peak = value(hit, &engine::WallHit::peak_normal_force);
        if (restitution > 0.9) {
            elastic = hit;
            table.checks.push_back(report::make_check(
                "hertz.peak.e0.95", "Hertz-Tsuji peak force, e 0.95 (nearly elastic)", "N",
                engine::hertz_impact(e_star, radius, mass, vn).peak_force,
                "Hertz's elastic impact (Johnson 1985)", peak, 0.10));
        }
        const double overlap_unit = std::pow(mass * vn * vn / kn, 0.4);
        table.checks.push_back(
            report::make_check(fmt("hertz.tsuji.e%g", restitution),
                               fmt("Hertz-Tsuji peak force, e %g", restitution), "N",
                               engine::tsuji_impact_for_restitution(restitution).peak_force * kn *
                                   std::pow(overlap_unit, 1.5),
                               "nondimensional Hertz-Tsuji solution", peak, 0.05));
    }
    {
        const std::optional<engine::WallHit> hit = single_hit(linear_contact(0.0), 0.3);
        const double vn = hit ? hit->normal_speed : speed;
        table.checks.push_back(report::make_check(
            "hertz.linear_equivalent", "linear law, Hertz-equivalent stiffness: peak force, e 0.3",
            "N", engine::hertz_impact(e_star, radius, mass, vn).peak_force,
            "Hertz's elastic impact", value(hit, &engine::WallHit::peak_normal_force), 0.10));
    }
    const double k = 2e8;
    std::optional<engine::WallHit> damped;
    for (const auto& [restitution, steps] : {std::pair{0.5, 40}, std::pair{0.3, 80}}) {
        const std::optional<engine::WallHit> hit =
            single_hit(linear_contact(k, steps), restitution);
        if (restitution == 0.5) damped = hit;
        const engine::LinearImpact unit =
            engine::linear_impact(engine::clamped_damping_ratio(restitution));
        const double vn = hit ? hit->normal_speed : speed;
        const std::string id = fmt("spring_dashpot.e%g", restitution);
        const std::string label = fmt("spring-dashpot k 2e8 N/m, e %g", restitution) + ", " +
                                  std::to_string(steps) + " steps per contact";
        table.checks.push_back(report::make_check(
            id + ".peak", label + ": peak force", "N", unit.peak_force * vn * std::sqrt(mass * k),
            "closed form (Schwager and Poeschel 2007)",
            value(hit, &engine::WallHit::peak_normal_force), 0.05));
        table.checks.push_back(report::make_check(
            id + ".duration", label + ": duration", "s", unit.duration * std::sqrt(mass / k),
            "closed form (Schwager and Poeschel 2007)", hit ? hit->end_time - hit->start_time : nan,
            0.05));
    }
    if (elastic && damped) {
        report::Plot plot =
            report::vv_plot("Wall force of one normal impact at 8 m/s",
                            "time from first touch (ms)", "normal force (kN)",
                            {force_history("Hertz-Tsuji, e 0.95", "#1f77b4", *elastic),
                             force_history("linear k 2e8 N/m, e 0.5", "#d62728", *damped)});
        const double t_end = 1e3 * std::max(elastic->end_time - elastic->start_time,
                                            damped->end_time - damped->start_time);
        const double hertz_peak =
            1e-3 * engine::hertz_impact(e_star, radius, mass, elastic->normal_speed).peak_force;
        report::Series peak = report::line_series("Hertz's elastic peak", "#1f77b4", {0.0, t_end},
                                                  {hertz_peak, hertz_peak});
        peak.dash = "6 4";
        peak.line_width = 1.0;
        plot.series.push_back(peak);
        section.figures.push_back(
            {plot,
             "The load cell's normal force during the impact (every fine step), with Hertz's "
             "elastic peak for the nearly elastic hit (dashed)."});
    }
    return table;
}

}  // namespace

report::VvSection engine_section(const VvOptions&) {
    report::VvSection section = report::vv_section(
        "engine", "Rigid-body engine: analytic motion and wall impacts",
        {"One rock on one long straight plane (engine/verification_scenes.hpp, the set-ups of "
         "tests/engine/test_motion.cpp), gravity 9.81 m/s2, at the default step of 1 ms and at "
         "half of it. Tolerances: free fall 0.2 % (symplectic Euler lags by g t dt / 2, 0.1 % at "
         "1 ms and 1 s); the speed is exact; accelerations 2 % (the landing transient within "
         "the 0.5-2 s window); rebound heights 5 % and speed ratios 2.5 % (the contact's "
         "position error of a step at 4.4 m/s).",
         "The wall impacts (tests/engine/test_wall_hits.cpp) run the wall contact's own fine "
         "steps. Impulse within 2 %; peak forces within 5 % of the Hertz-Tsuji and "
         "spring-dashpot solutions: Bullet evaluates the force at the start of each fine step, "
         "and over all phases of the first touch a one-degree-of-freedom replica of that scheme "
         "at 40 steps per contact errs by up to +3.3 % (Hertz-Tsuji) and +6.1 % (linear at e "
         "0.3, hence its 80 steps). Hertz's elastic solution is the reference only for the "
         "nearly elastic hit and the Hertz-equivalent linear law, within 10 % (Tsuji damping "
         "lowers the peak by 3 % at e 0.95)."});
    section.tables.push_back(motion_table());
    section.tables.push_back(bounce_table(section));
    section.tables.push_back(wall_table(section));
    return section;
}

}  // namespace rockfall::app
