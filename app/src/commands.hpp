#pragma once
/// The subcommands of the `rockfall` program; each registers itself on the CLI11 app.

#include <CLI/CLI.hpp>

namespace rockfall::app {

/// Exit code for bad input (files, values, command line).
inline constexpr int exit_bad_input = 2;
/// Exit code for a failure while running (I/O, numerics).
inline constexpr int exit_failure = 1;
/// Exit code of a run stopped by SIGINT or SIGTERM (128 + SIGINT, the shell's convention).
inline constexpr int exit_interrupted = 130;

/// `rockfall simulate SCENARIO`: one release with a readable summary or JSON.
void register_simulate(CLI::App& app);

/// `rockfall soil SCENARIO`: one soil flow (MPM) with the wall load history, runout and deposit.
void register_soil(CLI::App& app);

/// `rockfall formula NAME`: one impact design formula (Japan Road Association, seed 000's
/// proposal, Labiouse et al. 1996, ASTRA 2008) evaluated for a mass and an impact velocity or
/// fall height, or UNI 11211-4 design values from a sample of speeds and heights.
void register_formula(CLI::App& app);

/// `rockfall fit CSV|DB`: identifies the impact formula's lambda, beta and alpha from impacts
/// (seed 000's procedure) with the fit's quality and range, and optionally its figure.
void register_fit(CLI::App& app);

/// `rockfall envelope DB`: every wall impact against the design formula for its rock, the
/// share above the envelope with its interval and the worst impacts with their seeds.
void register_envelope(CLI::App& app);

/// `rockfall shape --kind K`: the shape measures of one rock (volume, inertia, axis lengths,
/// sphericities) and optionally its simulated hull as an OBJ file.
void register_shape(CLI::App& app);

/// `rockfall terrain SCENARIO`: a scenario's terrain mesh (size, extent, height above the
/// reference profile), written as OBJ; or its profile triangulated as a mesh.
void register_terrain(CLI::App& app);

/// `rockfall query DB WHAT`: summary, percentiles, exceedance probabilities and the worst
/// samples of a results database, as text, CSV or JSON.
void register_query(CLI::App& app);

/// `rockfall report DB --html FILE`: one self-contained HTML report of a results database.
void register_report(CLI::App& app);

/// `rockfall sweep SCENARIO --db FILE`: a Monte Carlo sweep into a results database.
void register_sweep(CLI::App& app);

/// `rockfall calibrate drop`: virtual drop tests and the surface restitution for a measured COR.
void register_calibrate(CLI::App& app);
/// `rockfall validate`: published results reproduced (seed 001's Table 2 and speeds).
void register_validate(CLI::App& app);
/// `rockfall merge OUT.db SHARD.db...`: shards of one sweep into one database.
void register_merge(CLI::App& app);
/// Hidden `--man-page` and `--bash-completion`: rockfall(1) and the bash completion, written
/// from every command registered on `app` by the time it parses (cmd_help_man.cpp).
void register_help_files(CLI::App& app);

}  // namespace rockfall::app
