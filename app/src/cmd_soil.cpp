// `rockfall soil`: one soil flow (scenario C, MPM), summary or JSON, optional wall-load CSV
// and particle frames for ParaView.

#include "atomic_file.hpp"
#include "commands.hpp"
#include "text_format.hpp"

#include "app/soil_file.hpp"
#include "mpm/soil.hpp"
#include "mpm/vtk.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <unistd.h>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

struct SoilArgs {
    std::string scenario;
    bool json = false;
    std::string vtk_dir;
    std::string csv;
};

// Units of the outcome's extensive quantities: a 2D run is a plane-strain section, so its
// forces, impulses, masses and energies are per metre of width.
struct Units {
    const char* force;
    const char* impulse;
    const char* mass;
    // A JSON key or CSV column with a unit suffix: "wall_force_N", or "wall_force_N_per_m" in 2D.
    std::string key(const char* base) const {
        return per_metre ? base + std::string("_per_m") : base;
    }
    bool per_metre;
};

Units units_of(const mpm::SoilOutcome& outcome) {
    if (outcome.dimension == 2) return {"N/m", "N s/m", "kg/m", true};
    return {"N", "N s", "kg", false};
}

const char* to_string(mpm::SoilStatus status) {
    switch (status) {
        case mpm::SoilStatus::completed:
            return "completed";
        case mpm::SoilStatus::left_domain:
            return "left_domain";
        case mpm::SoilStatus::non_finite:
            return "non_finite";
    }
    return "unknown";
}

double peak_step_force(const mpm::SoilOutcome& outcome) {
    double peak = 0.0;
    for (const double f : outcome.step_wall_force) peak = std::max(peak, f);
    return peak;
}

// The highest bin of the deposit's height profile, if any soil rests on the slope.
std::optional<std::size_t> highest_bin(const mpm::SoilDeposit& deposit) {
    const auto& h = deposit.profile_height;
    if (h.empty()) return std::nullopt;
    return static_cast<std::size_t>(std::max_element(h.begin(), h.end()) - h.begin());
}

// Writes particle frames as DIR/frame_NNNNN.vtk. The solver's callback must not throw, so the
// first write error is kept and rethrown after the run.
class VtkFrames {
  public:
    explicit VtkFrames(fs::path dir) : dir_(std::move(dir)) {
        std::error_code error;
        fs::create_directories(dir_, error);
        if (error || !fs::is_directory(dir_)) {
            throw std::runtime_error("cannot create the VTK directory '" + dir_.string() +
                                     "': " + (error ? error.message() : "not a directory"));
        }
    }
    void write(const mpm::ParticleFrame& frame) {
        if (!error_.empty()) return;
        char name[32];
        std::snprintf(name, sizeof name, "frame_%05d.vtk", count_);
        try {
            mpm::write_vtk(dir_ / name, frame);
            ++count_;
        } catch (const std::exception& e) {
            error_ = e.what();
        }
    }
    void finish() const {
        if (!error_.empty()) throw std::runtime_error(error_);
    }
    int count() const { return count_; }

  private:
    fs::path dir_;
    int count_ = 0;
    std::string error_;
};

// Writes the sampled wall-load history (committed only when complete).
void write_csv(const fs::path& path, const mpm::SoilOutcome& o) {
    const Units u = units_of(o);
    AtomicFile file(path);
    std::ofstream& out = file.stream();
    out << "time_s," << u.key("wall_force_N") << ',' << u.key("wall_force_filtered_N")
        << ",centre_of_mass_x_m,centre_of_mass_z_m,front_x_m," << u.key("kinetic_energy_J") << '\n'
        << std::setprecision(9);
    for (std::size_t k = 0; k < o.sample_time.size(); ++k) {
        out << o.sample_time[k] << ',' << o.wall_force[k] << ',' << o.wall_force_filtered[k] << ','
            << o.centre_of_mass[k].x() << ',' << o.centre_of_mass[k].z() << ',' << o.front_x[k]
            << ',' << o.kinetic_energy[k] << '\n';
    }
    file.commit();
}

struct RunInfo {
    std::string path;
    double runtime = 0.0;
};

void print_summary(std::ostream& out, const SoilFile& file, const mpm::SoilOutcome& o,
                   const RunInfo& info) {
    const mpm::SoilScenario& s = file.scenario;
    const Units u = units_of(o);
    out << "soil scenario " << file.name << " (" << info.path << ")\n";
    out << "  "
        << (o.dimension == 2 ? "2D plane strain: forces, impulses and masses per metre "
                               "of width"
                             : "3D")
        << ", cell " << fmt("%.3f m", s.numerics.cell_size) << ", " << o.particles
        << " particles, soil mass " << fmt("%.1f ", o.mass) << u.mass << '\n';
    out << "status: " << to_string(o.status);
    if (!o.message.empty()) out << " (" << o.message << ")";
    out << '\n';
    out << "simulated " << fmt("%.3f s", o.step_time.empty() ? 0.0 : o.step_time.back()) << " in "
        << o.steps << " steps; runtime " << fmt("%.2f s", info.runtime) << '\n';
    if (s.slope.wall.enabled) {
        out << "wall load (normal to the wall, " << fmt("%.2f m", s.slope.wall.distance_from_toe)
            << " past the toe), " << u.force << ":\n";
        out << "  peak " << fmt("%.1f ", o.peak_wall_force) << u.force << " at "
            << fmt("%.3f s", o.peak_wall_force_time) << " (mean over each "
            << fmt("%g s", s.output.sample_interval) << " sample)\n";
        out << "  peak filtered " << fmt("%.1f ", o.peak_wall_force_filtered) << u.force
            << " (centred moving average over " << fmt("%g s", s.output.filter_window) << ")\n";
        out << "  peak raw " << fmt("%.1f ", peak_step_force(o)) << u.force << " (single step)\n";
        out << "  total impulse " << fmt("%.1f ", o.wall_impulse) << u.impulse << '\n';
    } else {
        out << "wall: none in this scenario\n";
    }
    const mpm::SoilDeposit& d = o.deposit;
    out << "deposit:\n";
    out << "  runout " << fmt("%.2f m", d.runout_past_toe) << " past the toe (x "
        << fmt("%.2f m", d.runout_x) << ")\n";
    if (!o.front_x.empty()) {
        const mpm::Vec3& c = o.centre_of_mass.back();
        out << "  final front x " << fmt("%.2f m", o.front_x.back()) << ", centre of mass x "
            << fmt("%.2f m", c.x()) << ", z " << fmt("%.2f m", c.z()) << '\n';
    }
    if (const auto top = highest_bin(d)) {
        out << "  max height " << fmt("%.2f m", d.profile_height[*top]) << " above the slope at x "
            << fmt("%.2f m", d.profile_x[*top]) << " (profile of " << d.profile_x.size()
            << " bins from x " << fmt("%.2f m", d.profile_x.front()) << " to "
            << fmt("%.2f m", d.profile_x.back()) << ")\n";
    }
}

nlohmann::json history_json(const mpm::SoilOutcome& o, const Units& u) {
    nlohmann::json rows = nlohmann::json::array();
    for (std::size_t k = 0; k < o.sample_time.size(); ++k) {
        rows.push_back({o.sample_time[k], o.wall_force[k], o.wall_force_filtered[k],
                        o.centre_of_mass[k].x(), o.centre_of_mass[k].z(), o.front_x[k],
                        o.kinetic_energy[k]});
    }
    return {{"columns",
             {"time_s", u.key("wall_force_N"), u.key("wall_force_filtered_N"), "centre_of_mass_x_m",
              "centre_of_mass_z_m", "front_x_m", u.key("kinetic_energy_J")}},
            {"rows", std::move(rows)}};
}

nlohmann::json outcome_json(const SoilFile& file, const mpm::SoilOutcome& o, const RunInfo& info) {
    const mpm::SoilScenario& s = file.scenario;
    const Units u = units_of(o);
    nlohmann::json profile = nlohmann::json::array();
    for (std::size_t b = 0; b < o.deposit.profile_x.size(); ++b) {
        profile.push_back({o.deposit.profile_x[b], o.deposit.profile_height[b]});
    }
    nlohmann::json deposit = {
        {"runout_x_m", o.deposit.runout_x},
        {"runout_past_toe_m", o.deposit.runout_past_toe},
        {"height_profile", {{"columns", {"x_m", "height_m"}}, {"rows", std::move(profile)}}}};
    if (const auto top = highest_bin(o.deposit)) {
        deposit["max_height_m"] = o.deposit.profile_height[*top];
        deposit["max_height_x_m"] = o.deposit.profile_x[*top];
    }
    nlohmann::json result = {{"scenario", file.name},
                             {"scenario_file", info.path},
                             {"dimension", o.dimension},
                             {"per_metre_of_width", u.per_metre},
                             {"status", to_string(o.status)},
                             {"message", o.message},
                             {"particles", o.particles},
                             {u.key("mass_kg"), o.mass},
                             {"steps", o.steps},
                             {"simulated_time_s", o.step_time.empty() ? 0.0 : o.step_time.back()},
                             {"runtime_s", info.runtime},
                             {"wall_enabled", s.slope.wall.enabled},
                             {"wall_distance_from_toe_m", s.slope.wall.distance_from_toe},
                             {"sample_interval_s", s.output.sample_interval},
                             {"filter_window_s", s.output.filter_window},
                             {u.key("peak_wall_force_N"), o.peak_wall_force},
                             {"peak_wall_force_time_s", o.peak_wall_force_time},
                             {u.key("peak_wall_force_filtered_N"), o.peak_wall_force_filtered},
                             {u.key("peak_wall_force_step_N"), peak_step_force(o)},
                             {u.key("wall_impulse_N_s"), o.wall_impulse},
                             {"deposit", std::move(deposit)},
                             {"history", history_json(o, u)}};
    if (!o.front_x.empty()) {
        result["final_front_x_m"] = o.front_x.back();
        const mpm::Vec3& c = o.centre_of_mass.back();
        result["final_centre_of_mass_m"] = {c.x(), c.y(), c.z()};
    }
    return result;
}

void run_soil_command(const SoilArgs& args) {
    const SoilFile file = load_soil_scenario(args.scenario);
    std::unique_ptr<VtkFrames> frames;
    if (!args.vtk_dir.empty()) frames = std::make_unique<VtkFrames>(args.vtk_dir);
    const bool progress = isatty(STDERR_FILENO) != 0;
    const double duration = file.scenario.output.duration;
    const mpm::FrameCallback on_frame = [&](const mpm::ParticleFrame& frame) {
        if (frames) frames->write(frame);
        if (progress) std::fprintf(stderr, "\rsoil flow: t = %.2f / %.2f s", frame.time, duration);
    };

    const auto start = std::chrono::steady_clock::now();
    const mpm::SoilOutcome outcome = mpm::run_soil(file.scenario, on_frame);
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start;
    if (progress) std::fprintf(stderr, "\r%40s\r", "");
    if (frames) frames->finish();
    if (!args.csv.empty()) write_csv(args.csv, outcome);

    const RunInfo info{args.scenario, elapsed.count()};
    if (args.json) {
        std::cout << outcome_json(file, outcome, info).dump(2) << '\n';
        return;
    }
    print_summary(std::cout, file, outcome, info);
    if (frames) std::cout << frames->count() << " VTK frames written to " << args.vtk_dir << '\n';
    if (!args.csv.empty()) std::cout << "wall-load history written to " << args.csv << '\n';
}

}  // namespace

void register_soil(CLI::App& app) {
    auto args = std::make_shared<SoilArgs>();
    CLI::App* cmd = app.add_subcommand(
        "soil", "Run a soil flow (MPM) and print the wall load history, runout and deposit");
    cmd->add_option("scenario", args->scenario, "Soil scenario file (TOML)")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("--json", args->json, "Print one JSON document instead of the summary");
    cmd->add_option("--vtk", args->vtk_dir,
                    "Write particle frames (legacy VTK) to this directory at the scenario's "
                    "output.frame_interval");
    cmd->add_option("--csv", args->csv,
                    "Write the sampled wall-load, centre-of-mass and front history to this CSV "
                    "file");
    cmd->callback([args] { run_soil_command(*args); });
}

}  // namespace rockfall::app
