#pragma once
/// Progress of long work on standard error: a redrawn bar with rate and time remaining on a
/// terminal, a plain line every `line_interval` otherwise (logs, CI), nothing when quiet.

#include <chrono>
#include <cstdint>
#include <ostream>
#include <string>

namespace rockfall::app {

/// How progress is shown.
enum class ProgressMode {
    bar,    ///< one line redrawn in place (a terminal)
    lines,  ///< a new line every line_interval (not a terminal)
    quiet,  ///< nothing
};

/// bar when standard error is a terminal, otherwise lines; quiet when `quiet`.
ProgressMode progress_mode_for_stderr(bool quiet);

/// A progress display for `total` units of work named `unit` ("samples").
class Progress {
  public:
    Progress(std::ostream& out, ProgressMode mode, std::int64_t total, std::string unit,
             std::chrono::seconds line_interval = std::chrono::seconds(10));

    /// Reports `done` units finished in this run (after `already` done before it) and a short
    /// note shown after the rate (may be empty); redraws at most every 0.2 s.
    void update(std::int64_t done, const std::string& note = "");
    /// Draws the final state and ends the line.
    void finish(std::int64_t done, const std::string& note = "");
    /// Units already done when this run started (resumed work); excluded from the rate.
    void set_already(std::int64_t already) { already_ = already; }

  private:
    void draw(std::int64_t done, const std::string& note, bool final);

    std::ostream& out_;
    ProgressMode mode_;
    std::int64_t total_;
    std::string unit_;
    std::chrono::seconds line_interval_;
    std::int64_t already_ = 0;
    std::chrono::steady_clock::time_point start_;
    std::chrono::steady_clock::time_point last_draw_;
};

/// A duration as h:mm:ss (or m:ss below an hour).
std::string format_duration(double seconds);

}  // namespace rockfall::app
