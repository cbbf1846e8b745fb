// `rockfall merge OUT.db SHARD.db...`: the shards of one sweep (`rockfall sweep --shard K/N`)
// into one results database, checked to be the same run, with disjoint samples and no gaps.

#include "commands.hpp"
#include "report/query_report.hpp"
#include "sweep_record.hpp"

#include "db/merge.hpp"
#include "db/queries.hpp"
#include "db/results_db.hpp"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

struct MergeArgs {
    std::string out;
    std::vector<std::string> shards;
    bool allow_gaps = false;
    bool quiet = false;
};

// One input file as read: its run, settings, shard and stored sample indices (ascending).
struct ShardFile {
    fs::path path;
    db::RunRecord run;
    nlohmann::json settings;
    std::optional<Shard> shard;
    std::vector<std::int64_t> samples;
};

ShardFile read_shard(const fs::path& path) {
    ShardFile file;
    file.path = path;
    const db::ResultsDb results = db::ResultsDb::open(path, false);
    file.run = results.run();
    file.settings = stored_settings(file.run, path.string(), "cannot merge: ");
    file.shard = stored_shard(file.settings, path.string());
    file.samples = results.stored_samples();
    return file;
}

// The settings that decide a run's samples: all but the shard and the thread count.
nlohmann::json run_settings(const nlohmann::json& settings) {
    nlohmann::json kept = settings;
    kept.erase("shard");
    kept.erase("threads");
    return kept;
}

// Refuses `file` unless it holds the same run as `first`, naming the first difference.
void check_same_run(const ShardFile& first, const ShardFile& file) {
    const auto refuse = [&](const std::string& what, const std::string& theirs,
                            const std::string& ours) {
        throw std::invalid_argument(file.path.string() + " is not a shard of the run in " +
                                    first.path.string() + ": its " + what + " is " + theirs +
                                    ", not " + ours +
                                    "; merge only shards of one sweep, started with the same "
                                    "scenario, options and rockfall");
    };
    const db::RunRecord& a = first.run;
    const db::RunRecord& b = file.run;
    if (b.seed != a.seed) refuse("seed", std::to_string(b.seed), std::to_string(a.seed));
    if (b.method != a.method) refuse("method", b.method, a.method);
    if (b.samples_planned != a.samples_planned)
        refuse("sample count", std::to_string(b.samples_planned),
               std::to_string(a.samples_planned));
    if (b.stop_rule != a.stop_rule) refuse("stop rule", b.stop_rule, a.stop_rule);
    if (b.tool_version != a.tool_version) refuse("tool version", b.tool_version, a.tool_version);
    if (b.build != a.build) refuse("build", b.build, a.build);
    if (b.scenario_hash != a.scenario_hash)
        refuse("scenario and [sweep] hash", b.scenario_hash, a.scenario_hash);
    if (b.zones != a.zones) refuse("list of release zones", "another", "the same");
    const nlohmann::json theirs = run_settings(file.settings);
    const nlohmann::json ours = run_settings(first.settings);
    if (theirs != ours) refuse("settings", theirs.dump(), ours.dump());
}

std::string shard_name(const ShardFile& file) {
    return file.shard ? "shard " + file.shard->text() : std::string("a whole run");
}

// Marks every file's samples in `present`, refusing one out of the run's range, out of its
// shard, or held by another file too.
void mark_samples(const std::vector<ShardFile>& files, std::vector<bool>& present) {
    const auto planned = static_cast<std::int64_t>(present.size());
    for (std::size_t f = 0; f < files.size(); ++f) {
        const ShardFile& file = files[f];
        for (const std::int64_t sample : file.samples) {
            if (sample >= planned)
                throw std::invalid_argument(file.path.string() + " holds sample " +
                                            std::to_string(sample) + " but its run plans " +
                                            std::to_string(planned) + " samples (0 to " +
                                            std::to_string(planned - 1) + "): the file is damaged");
            if (file.shard && !file.shard->holds(sample))
                throw std::invalid_argument(
                    file.path.string() + " is " + shard_name(file) + " but holds sample " +
                    std::to_string(sample) + ", which is shard " +
                    std::to_string(sample % file.shard->count) + "'s: the file is damaged");
            const auto slot = static_cast<std::size_t>(sample);
            if (present[slot]) {
                const auto other = std::find_if(files.begin(), files.end(), [&](const auto& g) {
                    return std::binary_search(g.samples.begin(), g.samples.end(), sample);
                });
                throw std::invalid_argument(
                    "cannot merge: " + other->path.string() + " (" + shard_name(*other) + ") and " +
                    file.path.string() + " (" + shard_name(file) + ") both hold sample " +
                    std::to_string(sample) +
                    "; give each shard once, and no shards of different --shard N that overlap");
            }
            present[slot] = true;
        }
    }
}

// The message for samples that no file holds: how many, the first ones, and the shards of the
// same N that no file is.
std::string describe_gaps(const std::vector<ShardFile>& files, const std::vector<bool>& present,
                          std::int64_t missing) {
    std::string first;
    int listed = 0;
    for (std::size_t i = 0; i < present.size() && listed < 5; ++i) {
        if (present[i]) continue;
        first += (listed++ == 0 ? "" : ", ") + std::to_string(i);
    }
    std::string message = std::to_string(missing) + " of the run's " +
                          std::to_string(present.size()) + " planned samples are in none of " +
                          "the files (samples " + first + (missing > listed ? ", ..." : "") + ")";
    const std::optional<Shard>& shard = files.front().shard;
    const bool same_count = shard && std::all_of(files.begin(), files.end(), [&](const auto& f) {
                                return f.shard && f.shard->count == shard->count;
                            });
    if (same_count) {
        std::set<std::int64_t> given;
        for (const ShardFile& file : files) given.insert(file.shard->index);
        std::string absent;
        for (std::int64_t k = 0; k < shard->count && absent.size() < 80; ++k)
            if (!given.contains(k))
                absent += (absent.empty() ? "" : ", ") + Shard{k, shard->count}.text();
        if (!absent.empty())
            message += "; no file given is shard " + absent;
        else
            message += "; some shards are incomplete (continue them with --resume)";
    }
    return message;
}

// The merged run: the first file's, without its shard, spanning the shards' times.
db::RunRecord merged_record(const std::vector<ShardFile>& files, bool complete) {
    db::RunRecord run = files.front().run;
    nlohmann::json settings = files.front().settings;
    settings.erase("shard");
    run.settings_json = settings.dump();
    for (const ShardFile& file : files) {
        run.started_at = std::min(run.started_at, file.run.started_at);
        run.finished_at = std::max(run.finished_at, file.run.finished_at);
    }
    if (run.finished_at.empty()) run.finished_at = utc_now();
    run.status = complete ? "complete" : "interrupted";
    return run;
}

int run_merge(const MergeArgs& args) {
    std::vector<ShardFile> files;
    for (const std::string& name : args.shards) {
        for (const ShardFile& seen : files) {
            std::error_code error;
            if (fs::equivalent(seen.path, name, error))
                throw std::invalid_argument(
                    "cannot merge: " + name + " is given twice" +
                    (seen.path == name ? std::string() : " (as " + seen.path.string() + " too)"));
        }
        files.push_back(read_shard(name));
        check_same_run(files.front(), files.back());
    }
    std::vector<bool> present(static_cast<std::size_t>(files.front().run.samples_planned), false);
    mark_samples(files, present);
    const auto missing =
        static_cast<std::int64_t>(std::count(present.begin(), present.end(), false));
    if (missing > 0 && !args.allow_gaps)
        throw std::invalid_argument("cannot merge into " + args.out + ": " +
                                    describe_gaps(files, present, missing) +
                                    "; give every shard, or --allow-gaps to merge what there is "
                                    "and run the rest later with `rockfall sweep --db " +
                                    args.out + " --resume`");
    std::vector<fs::path> paths;
    for (const ShardFile& file : files) paths.push_back(file.path);
    db::merge_runs(args.out, merged_record(files, missing == 0), paths);

    if (args.quiet) return 0;
    const std::int64_t merged = files.front().run.samples_planned - missing;
    std::cerr << "merged " << files.size() << " file" << (files.size() == 1 ? "" : "s") << " ("
              << merged << " of " << present.size() << " samples) into " << args.out << ": ";
    if (missing == 0) {
        std::cerr << "complete\n";
    } else {
        std::cerr << missing << " samples missing; run them with `rockfall sweep --db " << args.out
                  << " --resume`\n";
    }
    const db::ResultsDb results = db::ResultsDb::open(args.out, false);
    report::write_summary(std::cout, report::QueryFormat::text, args.out, db::summarize(results));
    return 0;
}

}  // namespace

void register_merge(CLI::App& app) {
    auto args = std::make_shared<MergeArgs>();
    CLI::App* cmd = app.add_subcommand(
        "merge", "Merge the shards of one sweep (rockfall sweep --shard K/N) into one database");
    cmd->add_option("out", args->out, "Results database to create (never replaced)")->required();
    cmd->add_option("shards", args->shards, "The shards' databases")
        ->required()
        ->check(CLI::ExistingFile);
    cmd->add_flag("--allow-gaps", args->allow_gaps,
                  "Merge even when samples are missing; the result's status is interrupted and "
                  "`rockfall sweep --db OUT --resume` runs the rest");
    cmd->add_flag("--quiet", args->quiet,
                  "Print nothing: no note on stderr, no summary of the merged run (which reads "
                  "every sample)");
    cmd->callback([args] {
        const int code = run_merge(*args);
        if (code != 0) throw CLI::RuntimeError(code);
    });
}

}  // namespace rockfall::app
