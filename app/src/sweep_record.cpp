#include "sweep_record.hpp"

#include <cstdio>
#include <ctime>
#include <stdexcept>

namespace rockfall::app {
namespace {

// A decimal whole number in [0, max] with digits only; none for anything else.
std::optional<std::int64_t> whole_number(const std::string& text, std::int64_t max) {
    if (text.empty() || text.size() > 18) return std::nullopt;
    std::int64_t value = 0;
    for (const char c : text) {
        if (c < '0' || c > '9') return std::nullopt;
        value = value * 10 + (c - '0');
    }
    if (value > max) return std::nullopt;
    return value;
}

}  // namespace

Shard parse_shard(const std::string& text, const std::string& option) {
    const std::size_t slash = text.find('/');
    const auto bad = [&](const std::string& why) {
        return std::invalid_argument(option + " " + text + ": " + why);
    };
    if (slash == std::string::npos)
        throw bad("must be K/N, shard K of N (K in [0, N - 1], N in [1, " +
                  std::to_string(risk::max_samples) + "]), e.g. 0/4");
    const auto index = whole_number(text.substr(0, slash), risk::max_samples);
    const auto count = whole_number(text.substr(slash + 1), risk::max_samples);
    if (!count || *count < 1)
        throw bad("N (the number of shards) must be a whole number in [1, " +
                  std::to_string(risk::max_samples) + "]");
    if (!index || *index >= *count)
        throw bad("K (this shard's number) must be a whole number in [0, " +
                  std::to_string(*count - 1) + "]");
    return {*index, *count};
}

nlohmann::json stored_settings(const db::RunRecord& run, const std::string& db_path,
                               const std::string& doing) {
    try {
        nlohmann::json settings = nlohmann::json::parse(run.settings_json);
        if (settings.is_object()) return settings;
    } catch (const nlohmann::json::exception&) {
    }
    throw std::invalid_argument(db_path + ": " + doing +
                                "run.settings_json is not a JSON object (the file is damaged)");
}

std::optional<Shard> stored_shard(const nlohmann::json& settings, const std::string& db_path) {
    if (!settings.contains("shard")) return std::nullopt;
    const nlohmann::json& value = settings.at("shard");
    try {
        if (value.is_string()) return parse_shard(value.get<std::string>(), "shard");
    } catch (const std::invalid_argument&) {
    }
    throw std::invalid_argument(db_path + ": run.settings_json shard = " + value.dump() +
                                " is not a shard K/N (the file is damaged)");
}

std::string identity_hash(const SweepIdentity& identity) {
    // FNV-1a 64-bit: offset basis and prime from the FNV specification.
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    const auto feed = [&hash](const std::string& text) {
        for (const char c : text) {
            hash ^= static_cast<unsigned char>(c);
            hash *= 0x100000001b3ULL;
        }
        hash ^= 0xff;  // a separator, so that moving text between parts changes the hash
        hash *= 0x100000001b3ULL;
    };
    feed(identity.scenario_text);
    feed(identity.overrides.dump());
    feed(identity.stop_rule);
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
    return text;
}

std::string utc_now() {
    const std::time_t now = std::time(nullptr);
    std::tm utc{};
    gmtime_r(&now, &utc);
    char text[32];
    std::strftime(text, sizeof text, "%Y-%m-%dT%H:%M:%SZ", &utc);
    return text;
}

db::RunRecord make_run_record(const scenario::ScenarioFile& file, const risk::SweepSpec& spec,
                              const std::string& stop_rule, const nlohmann::json& settings) {
    db::RunRecord run;
    run.tool_version = ROCKFALL_VERSION;
    run.build = ROCKFALL_BUILD;
    run.scenario_name = file.scenario.name;
    run.scenario_text = file.text;
    // The text holds the [sweep] table as the file gives it; the command line may override
    // the run's seed, sample count and method.
    const nlohmann::json overrides = {
        {"seed", spec.seed}, {"samples", spec.samples}, {"method", risk::to_string(spec.method)}};
    run.scenario_hash = identity_hash({file.text, overrides, stop_rule});
    run.seed = spec.seed;
    run.method = risk::to_string(spec.method);
    run.samples_planned = spec.samples;
    run.stop_rule = stop_rule;
    nlohmann::json all = settings;
    all.update(overrides);
    run.settings_json = all.dump();
    run.started_at = utc_now();
    run.status = "running";
    for (const risk::ReleaseZone& zone : spec.zones) run.zones.push_back(zone.name);
    return run;
}

void check_resumable(const db::RunRecord& run, const db::RunRecord& wanted,
                     const std::string& db_path) {
    const auto refuse = [&](const std::string& what, const std::string& stored,
                            const std::string& given) {
        throw std::invalid_argument(db_path + ": cannot resume: the database's " + what + " is " +
                                    stored + " but this command gives " + given +
                                    "; leave the option or the SCENARIO file out to take "
                                    "the stored one, or start a new database");
    };
    if (run.seed != wanted.seed)
        refuse("seed", std::to_string(run.seed), std::to_string(wanted.seed));
    if (run.method != wanted.method) refuse("method", run.method, wanted.method);
    if (run.samples_planned != wanted.samples_planned)
        refuse("sample count", std::to_string(run.samples_planned),
               std::to_string(wanted.samples_planned));
    if (run.stop_rule != wanted.stop_rule)
        refuse("stop rule", "\"" + run.stop_rule + "\"", "\"" + wanted.stop_rule + "\"");
    if (run.scenario_hash != wanted.scenario_hash)
        refuse("scenario and [sweep] hash", run.scenario_hash,
               wanted.scenario_hash + " (the scenario file or its [sweep] table changed)");
}

}  // namespace rockfall::app
