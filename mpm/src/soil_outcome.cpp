#include "soil_model.hpp"

#include "mpm/load_window.hpp"
#include "mpm/soil.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rockfall::mpm {
namespace {

template <int Dim>
ParticleFrame make_frame(const Particles<Dim>& p, double time) {
    ParticleFrame frame;
    frame.time = time;
    const std::size_t n = p.size();
    frame.position.reserve(n);
    frame.velocity.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
        frame.position.push_back(to_scene<Dim>(p.position[i]));
        frame.velocity.push_back(to_scene<Dim>(p.velocity[i]));
        const double mean = p.stress[i].trace() / 3.0;
        const Mat3 deviator = p.stress[i] - mean * Mat3::Identity();
        frame.mean_stress.push_back(mean);
        frame.deviatoric_stress.push_back(std::sqrt(0.5 * deviator.squaredNorm()));
    }
    frame.mass = p.mass;
    frame.plastic_shear_strain = p.plastic_shear_strain;
    return frame;
}

template <int Dim>
SoilDeposit deposit_of(const Particles<Dim>& p, const shapes::Slope& slope, double cell,
                       double half_spacing) {
    SoilDeposit deposit;
    double x_min = std::numeric_limits<double>::infinity();
    double x_max = -std::numeric_limits<double>::infinity();
    for (const Vec<Dim>& position : p.position) {
        x_min = std::min(x_min, position[0]);
        x_max = std::max(x_max, position[0]);
    }
    deposit.runout_x = x_max + half_spacing;
    deposit.runout_past_toe = deposit.runout_x - slope.toe_x();
    const int bins = static_cast<int>(std::floor((x_max - x_min) / cell)) + 1;
    deposit.profile_height.assign(static_cast<std::size_t>(bins), 0.0);
    for (int b = 0; b < bins; ++b) {
        deposit.profile_x.push_back(x_min + (b + 0.5) * cell);
    }
    for (const Vec<Dim>& position : p.position) {
        const Vec3 x = to_scene<Dim>(position);
        const auto b = static_cast<std::size_t>(
            std::clamp(static_cast<int>((x.x() - x_min) / cell), 0, bins - 1));
        const double height = x.z() + half_spacing - slope.surface_height(x.x());
        deposit.profile_height[b] = std::max(deposit.profile_height[b], height);
    }
    return deposit;
}

template <int Dim>
SoilOutcome run(const SoilScenario& scenario, const FrameCallback& on_frame) {
    detail::SoilModel<Dim> model = detail::build_soil_model<Dim>(scenario);
    Solver<Dim>& solver = *model.solver;
    const SoilOutput& output = scenario.output;
    const bool spring =
        scenario.boundaries.wall_support == WallSupport::spring && model.slope.wall();
    SoilOutcome outcome;
    outcome.dimension = Dim;
    outcome.particles = static_cast<long>(solver.particles().size());
    outcome.mass = solver.particles().total_mass();

    const double duration = output.duration;
    const double ds = output.sample_interval;
    const int samples = std::max(1, static_cast<int>(std::ceil(duration / ds - 1e-9)));
    int next_sample = 1;
    double next_frame = 0.0;
    auto emit_frames = [&] {
        while (on_frame && next_frame <= solver.time() + 1e-12) {
            on_frame(make_frame(solver.particles(), solver.time()));
            next_frame += output.frame_interval;
        }
    };
    emit_frames();

    while (solver.time() < duration - 1e-12) {
        const double t0 = solver.time();
        const double dt = std::min(solver.stable_time_step(), duration - t0);
        // A non-finite particle speed or density makes the stable step NaN: stop with a status
        // rather than step.
        if (!(dt > 0.0 && std::isfinite(dt))) {
            outcome.status = SoilStatus::non_finite;
            outcome.message = "non-finite stable time step at t = " + std::to_string(t0) + " s";
            break;
        }
        const StepReport& report = solver.step(dt);
        const double t1 = solver.time();
        // A spring-backed wall's load is the force in its spring and dashpot (the load cell);
        // its guides take the components along the face.
        Vec3 impulse = report.impulse[detail::kWallGroup];
        if (spring) {
            impulse.x() = report.spring_impulse;
            outcome.max_wall_displacement =
                std::max(outcome.max_wall_displacement, solver.spring_displacement());
        }
        outcome.step_time.push_back(t1);
        outcome.step_wall_load.push_back(impulse / dt);
        outcome.step_wall_force.push_back(impulse.x() / dt);
        outcome.wall_impulse += impulse.x();
        if (report.clamped_particles > 0 && outcome.status == SoilStatus::completed) {
            outcome.status = SoilStatus::left_domain;
            outcome.message = "particles reached the grid's edge at t = " + std::to_string(t1) +
                              " s and were held there";
        }
        while (next_sample <= samples && next_sample * ds <= t1 + 1e-9) {
            const Vec3 com = to_scene<Dim>(solver.particles().centre_of_mass());
            outcome.sample_time.push_back(next_sample * ds);
            outcome.centre_of_mass.push_back(com);
            outcome.front_x.push_back(solver.particles().front() + 0.5 * model.particle_spacing);
            outcome.kinetic_energy.push_back(solver.particles().kinetic_energy());
            ++next_sample;
            if (!com.allFinite() || !std::isfinite(outcome.kinetic_energy.back())) {
                outcome.status = SoilStatus::non_finite;
                outcome.message = "non-finite particle state at t = " + std::to_string(t1) + " s";
            }
        }
        if (outcome.status == SoilStatus::non_finite) {
            break;
        }
        emit_frames();
    }
    outcome.steps = solver.step_count();
    outcome.final_wall_displacement = solver.spring_displacement();

    // Sampled and filtered histories and their peaks, all from the step history
    // (mpm/load_window.hpp): sample k is the mean over its interval; the filtered history is the
    // mean over exactly filter_window centred on each sample's middle; the peaks try every
    // window position.
    const std::size_t recorded = outcome.sample_time.size();
    const StepHistory<Vec3> load(outcome.step_time, outcome.step_wall_load, Vec3::Zero());
    for (std::size_t k = 0; k < recorded; ++k) {
        const double middle = outcome.sample_time[k] - 0.5 * ds;
        outcome.wall_load.push_back(load.window_mean(middle, ds));
        outcome.wall_force.push_back(outcome.wall_load.back().x());
        outcome.wall_load_filtered.push_back(output.filter_window > 0.0
                                                 ? load.window_mean(middle, output.filter_window)
                                                 : outcome.wall_load.back());
        outcome.wall_force_filtered.push_back(outcome.wall_load_filtered.back().x());
    }
    const StepHistory<double> force(outcome.step_time, outcome.step_wall_force, 0.0);
    const WindowPeak sampled = peak_window_mean(force, ds);
    outcome.peak_wall_force = sampled.value;
    outcome.peak_wall_force_time = sampled.centre;
    outcome.peak_wall_force_filtered = output.filter_window > 0.0
                                           ? peak_window_mean(force, output.filter_window).value
                                           : sampled.value;
    if (outcome.status == SoilStatus::non_finite) {
        // Positions that blew up have no deposit.
        outcome.deposit.runout_x = std::numeric_limits<double>::quiet_NaN();
        outcome.deposit.runout_past_toe = outcome.deposit.runout_x;
    } else {
        outcome.deposit = deposit_of(solver.particles(), model.slope, scenario.numerics.cell_size,
                                     0.5 * model.particle_spacing);
    }
    return outcome;
}

}  // namespace

const char* status_name(SoilStatus status) {
    switch (status) {
        case SoilStatus::completed:
            return "completed";
        case SoilStatus::left_domain:
            return "left_domain";
        case SoilStatus::non_finite:
            return "non_finite";
    }
    return "unknown";
}

SoilOutcome run_soil(const SoilScenario& scenario, const FrameCallback& on_frame) {
    validate(scenario);
    return scenario.numerics.dimension == 2 ? run<2>(scenario, on_frame)
                                            : run<3>(scenario, on_frame);
}

}  // namespace rockfall::mpm
