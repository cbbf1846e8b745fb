// The `rockfall` program: parses the command line and dispatches to a subcommand.

#include "commands.hpp"
#include "integer_option.hpp"
#include "scenario/scenario_file.hpp"

#include "db/results_db.hpp"
#include "shapes/polyhedron.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <stdexcept>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{
        "rockfall: how far rocks and soil released from a slope travel, and how hard "
        "they hit a wall (Bullet rigid bodies, MPM soil flow)"};
    app.set_version_flag("--version", std::string("rockfall ") + ROCKFALL_VERSION);
    app.require_subcommand(1);
    app.set_help_all_flag("--help-all", "Print help for every subcommand");
    rockfall::app::register_sweep(app);
    rockfall::app::register_merge(app);
    rockfall::app::register_simulate(app);
    rockfall::app::register_soil(app);
    rockfall::app::register_formula(app);
    rockfall::app::register_fit(app);
    rockfall::app::register_envelope(app);
    rockfall::app::register_shape(app);
    rockfall::app::register_terrain(app);
    rockfall::app::register_query(app);
    rockfall::app::register_report(app);
    rockfall::app::register_calibrate(app);
    rockfall::app::register_validate(app);
    rockfall::app::check_seed_options(app);
    rockfall::app::register_help_files(app);
    // CLI11 reads an unknown first word as a stray positional and answers "A subcommand is
    // required"; name what was typed and list the commands instead.
    if (argc > 1 && argv[1][0] != '-') {
        const std::string typed = argv[1];
        std::string names;
        bool known = false;
        for (const CLI::App* command : app.get_subcommands([](CLI::App*) { return true; })) {
            known = known || command->get_name() == typed;
            names += (names.empty() ? "" : ", ") + command->get_name();
        }
        if (!known) {
            std::cerr << "rockfall: unknown command '" << typed << "'; the commands are " << names
                      << " (rockfall COMMAND --help for each)\n";
            return rockfall::app::exit_bad_input;
        }
    }
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& e) {
        // A subcommand's own exit code (an interrupted sweep), its message already printed.
        return e.get_exit_code();
    } catch (const CLI::ParseError& e) {
        const int code = app.exit(e);
        return code == 0 ? 0 : rockfall::app::exit_bad_input;
    } catch (const rockfall::scenario::ScenarioError& e) {
        std::cerr << "rockfall: " << e.what() << '\n';
        return rockfall::app::exit_bad_input;
    } catch (const rockfall::shapes::GeometryError& e) {
        std::cerr << "rockfall: " << e.what() << '\n';
        return rockfall::app::exit_bad_input;
    } catch (const std::invalid_argument& e) {
        std::cerr << "rockfall: " << e.what() << '\n';
        return rockfall::app::exit_bad_input;
    } catch (const rockfall::db::DatabaseError& e) {
        // A missing, foreign, corrupt, newer or read-only file is bad input; a full disk is not.
        std::cerr << "rockfall: " << e.what() << '\n';
        return e.kind() == rockfall::db::DatabaseError::Kind::bad_file
                   ? rockfall::app::exit_bad_input
                   : rockfall::app::exit_failure;
    } catch (const std::exception& e) {
        std::cerr << "rockfall: " << e.what() << '\n';
        return rockfall::app::exit_failure;
    }
    return 0;
}
