// `rockfall --man-page` and `rockfall --bash-completion` (hidden): the man page rockfall(1) and
// the bash completion script, both walked from the CLI11 definition the commands registered and
// worded by the same formatter as --help, so neither can drift from the program. The build
// writes both and `cmake --install` installs them (cmake/RockfallInstall.cmake).

#include "commands.hpp"

#include <CLI/CLI.hpp>

#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace rockfall::app {
namespace {

/// Options and subcommands in the hidden group ("") stay out of both, as out of --help.
std::vector<const CLI::Option*> shown_options(const CLI::App& app, bool positional) {
    return app.get_options([positional](const CLI::Option* option) {
        return !option->get_group().empty() && option->get_positional() == positional;
    });
}

std::vector<const CLI::App*> shown_commands(const CLI::App& app) {
    return app.get_subcommands([](const CLI::App* sub) { return !sub->get_group().empty(); });
}

/// Text as roff: backslashes and dashes escaped (so options copy as ASCII), no line starting
/// with a control character.
std::string roff(std::string_view text) {
    std::string out;
    bool line_start = true;
    for (const char c : text) {
        if (line_start && (c == '.' || c == '\'')) out += "\\&";
        if (c == '\\') {
            out += "\\e";
        } else if (c == '-') {
            out += "\\-";
        } else {
            out += c;
        }
        line_start = c == '\n';
    }
    while (!out.empty() && out.back() == '\n') out.pop_back();
    return out;
}

void man_options(std::ostream& out, const CLI::Formatter& format, const CLI::App& app,
                 bool positional) {
    for (const CLI::Option* option : shown_options(app, positional)) {
        out << ".TP\n\\fB" << roff(format.make_option_name(option, positional)) << "\\fR";
        const std::string opts = format.make_option_opts(option);
        if (!opts.empty()) out << "\\fI" << roff(opts) << "\\fR";
        out << '\n' << roff(format.make_option_desc(option)) << '\n';
    }
}

/// A command's usage line as --help prints it, without "Usage: " and the newline; `invocation`
/// is how it is called (for a subcommand, its parent's usage up to SUBCOMMAND, then its name).
std::string usage(const CLI::Formatter& format, const CLI::App& command,
                  const std::string& invocation) {
    std::string line = format.make_usage(&command, invocation);
    if (line.rfind("Usage: ", 0) == 0) line.erase(0, 7);
    while (!line.empty() && line.back() == '\n') line.pop_back();
    return line;
}

/// One command's section, then its subcommands' (`rockfall query percentiles`).
void man_command(std::ostream& out, const CLI::Formatter& format, const CLI::App& command,
                 const std::string& path, const std::string& invocation) {
    out << ".SS \"" << roff(path) << "\"\n" << roff(command.get_description()) << "\n.PP\n";
    std::string line = usage(format, command, invocation);
    out << "\\fBUsage:\\fR " << roff(line) << '\n';
    if (!shown_options(command, true).empty()) {
        out << ".PP\nPositionals:\n.RS\n";
        man_options(out, format, command, true);
        out << ".RE\n";
    }
    out << ".PP\nOptions:\n.RS\n";
    man_options(out, format, command, false);
    out << ".RE\n";
    if (!command.get_footer().empty()) out << ".PP\n" << roff(command.get_footer()) << '\n';
    const std::string subcommand = " SUBCOMMAND";
    if (line.size() > subcommand.size() &&
        line.compare(line.size() - subcommand.size(), subcommand.size(), subcommand) == 0)
        line.erase(line.size() - subcommand.size());
    for (const CLI::App* sub : shown_commands(command))
        man_command(out, format, *sub, path + " " + sub->get_name(), line + " " + sub->get_name());
}

std::string man_page(const CLI::App& app, const CLI::Formatter& format) {
    std::ostringstream out;
    out << ".TH ROCKFALL 1 \"\" \"rockfall " << ROCKFALL_VERSION << "\" \"User Commands\"\n";
    out << ".\\\" Written by `rockfall --man-page` from the program's command-line definition.\n";
    std::string summary = app.get_description();
    if (summary.rfind("rockfall: ", 0) == 0) summary.erase(0, 10);
    out << ".SH NAME\nrockfall \\- " << roff(summary) << '\n';
    out << ".SH SYNOPSIS\n.B rockfall\n.I COMMAND\n[\\fIOPTIONS\\fR] [\\fIARGUMENTS\\fR]\n";
    out << ".SH DESCRIPTION\nThe commands, their arguments and options as \\fBrockfall COMMAND "
           "\\-\\-help\\fR prints them:\n.RS\n";
    for (const CLI::App* command : shown_commands(app))
        out << ".TP\n\\fB" << roff(command->get_name()) << "\\fR\n"
            << roff(command->get_description()) << '\n';
    out << ".RE\n.SH OPTIONS\n";
    man_options(out, format, app, false);
    out << ".SH COMMANDS\n";
    for (const CLI::App* command : shown_commands(app))
        man_command(out, format, *command, "rockfall " + command->get_name(),
                    "rockfall " + command->get_name());
    out << ".SH EXIT STATUS\n.TP\n0\nsuccess\n.TP\n"
        << exit_failure << "\na failure while running (I/O, numerics)\n.TP\n"
        << exit_bad_input << "\nbad input: a file, a value or the command line\n.TP\n"
        << exit_interrupted << "\na run stopped by SIGINT or SIGTERM\n";
    return out.str();
}

/// A word list as one shell word in single quotes.
std::string shell_quoted(const std::vector<std::string>& words) {
    std::string out = "'";
    for (const std::string& word : words) {
        if (out.size() > 1) out += ' ';
        for (const char c : word) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
    }
    return out + "'";
}

/// The values an option's --help type names, e.g. TEXT:{wilson,clopper-pearson}.
std::vector<std::string> choices(const CLI::Option& option) {
    const std::string type = option.get_type_name();
    const std::size_t open = type.find('{');
    const std::size_t close = type.find('}', open);
    std::vector<std::string> values;
    if (open == std::string::npos || close == std::string::npos) return values;
    std::istringstream list(type.substr(open + 1, close - open - 1));
    for (std::string value; std::getline(list, value, ',');) values.push_back(value);
    return values;
}

struct CompletionCases {
    std::ostringstream commands, options, values;
};

void completion_cases(CompletionCases& cases, const CLI::App& command, const std::string& path) {
    std::vector<std::string> names;
    for (const CLI::App* sub : shown_commands(command)) names.push_back(sub->get_name());
    const bool files = !shown_options(command, true).empty();
    cases.commands << "        " << shell_quoted({path}) << ") echo " << shell_quoted(names)
                   << "; return " << (files ? 1 : 0) << " ;;\n";
    std::vector<std::string> options;
    for (const CLI::Option* option : shown_options(command, false)) {
        std::vector<std::string> spellings;
        for (const std::string& name : option->get_snames()) spellings.push_back("-" + name);
        for (const std::string& name : option->get_lnames()) spellings.push_back("--" + name);
        options.insert(options.end(), spellings.begin(), spellings.end());
        if (option->get_type_size() == 0) continue;
        const std::vector<std::string> values = choices(*option);
        for (const std::string& spelling : spellings)
            cases.values << "        " << shell_quoted({path + " " + spelling}) << ") echo "
                         << shell_quoted(values) << "; return " << (values.empty() ? 1 : 0)
                         << " ;;\n";
    }
    cases.options << "        " << shell_quoted({path}) << ") echo " << shell_quoted(options)
                  << " ;;\n";
    for (const CLI::App* sub : shown_commands(command))
        completion_cases(cases, *sub,
                         path.empty() ? sub->get_name() : path + " " + sub->get_name());
}

std::string bash_completion(const CLI::App& app) {
    CompletionCases cases;
    completion_cases(cases, app, "");
    std::ostringstream out;
    out << "# bash completion for rockfall " << ROCKFALL_VERSION
        << ": its commands and options, written by `rockfall --bash-completion`\n"
           "# from the program's command-line definition.\n\n"
           "# The subcommands of a command path; returns 1 when the command also takes files.\n"
           "_rockfall_commands() {\n    case \"$1\" in\n"
        << cases.commands.str()
        << "    esac\n}\n\n"
           "_rockfall_options() {\n    case \"$1\" in\n"
        << cases.options.str()
        << "    esac\n}\n\n"
           "# The values of an option (return 0), any value such as a file (1), or a flag (2).\n"
           "_rockfall_values() {\n    case \"$1 $2\" in\n"
        << cases.values.str()
        << "    esac\n    return 2\n}\n\n"
           "_rockfall() {\n"
           "    local cur=${COMP_WORDS[COMP_CWORD]} prev=${COMP_WORDS[COMP_CWORD - 1]}\n"
           "    local path='' word i values status takes_files\n"
           "    for ((i = 1; i < COMP_CWORD; i++)); do\n"
           "        word=${COMP_WORDS[i]}\n"
           "        if [[ \" $(_rockfall_commands \"$path\") \" == *\" $word \"* ]]; then\n"
           "            path=${path:+$path }$word\n"
           "        fi\n"
           "    done\n"
           "    if [[ $COMP_CWORD -gt 1 && $prev == -* ]]; then\n"
           "        values=$(_rockfall_values \"$path\" \"$prev\")\n"
           "        status=$?\n"
           "        if [[ $status -eq 0 ]]; then\n"
           "            mapfile -t COMPREPLY < <(compgen -W \"$values\" -- \"$cur\")\n"
           "            return\n"
           "        elif [[ $status -eq 1 ]]; then\n"
           "            compopt -o filenames 2>/dev/null || :\n"
           "            mapfile -t COMPREPLY < <(compgen -f -- \"$cur\")\n"
           "            return\n"
           "        fi\n"
           "    fi\n"
           "    if [[ $cur == -* ]]; then\n"
           "        mapfile -t COMPREPLY < <(compgen -W \"$(_rockfall_options \"$path\")\" -- "
           "\"$cur\")\n"
           "        return\n"
           "    fi\n"
           "    values=$(_rockfall_commands \"$path\")\n"
           "    takes_files=$?\n"
           "    mapfile -t COMPREPLY < <(compgen -W \"$values\" -- \"$cur\")\n"
           "    if [[ $takes_files -eq 1 ]]; then\n"
           "        compopt -o filenames 2>/dev/null || :\n"
           "        mapfile -t -O \"${#COMPREPLY[@]}\" COMPREPLY < <(compgen -f -- \"$cur\")\n"
           "    fi\n"
           "}\n"
           "complete -F _rockfall rockfall\n";
    return out.str();
}

/// A flag whose callback prints `text(app)` and ends the parse with exit code 0.
template <typename Text>
void add_writer(CLI::App& app, const std::string& name, Text text) {
    app.add_flag_callback(
           name,
           [&app, text] {
               std::cout << text(app);
               throw CLI::Success();
           },
           "")
        ->group("");
}

}  // namespace

void register_help_files(CLI::App& app) {
    add_writer(app, "--man-page", [](const CLI::App& top) {
        const auto format = std::dynamic_pointer_cast<CLI::Formatter>(top.get_formatter());
        return man_page(top, format ? *format : CLI::Formatter());
    });
    add_writer(app, "--bash-completion", [](const CLI::App& top) { return bash_completion(top); });
}

}  // namespace rockfall::app
