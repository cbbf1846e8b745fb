#include "progress.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unistd.h>

namespace rockfall::app {

ProgressMode progress_mode_for_stderr(bool quiet) {
    if (quiet) return ProgressMode::quiet;
    return isatty(STDERR_FILENO) != 0 ? ProgressMode::bar : ProgressMode::lines;
}

Progress::Progress(std::ostream& out, ProgressMode mode, std::int64_t total, std::string unit,
                   std::chrono::seconds line_interval)
    : out_(out),
      mode_(mode),
      total_(std::max<std::int64_t>(total, 1)),
      unit_(std::move(unit)),
      line_interval_(line_interval),
      start_(std::chrono::steady_clock::now()),
      last_draw_(start_) {}

std::string format_duration(double seconds) {
    if (!std::isfinite(seconds) || seconds < 0.0) return "--:--";
    const auto total = static_cast<long long>(std::llround(seconds));
    char text[32];
    if (total >= 3600) {
        std::snprintf(text, sizeof text, "%lld:%02lld:%02lld", total / 3600, total / 60 % 60,
                      total % 60);
    } else {
        std::snprintf(text, sizeof text, "%lld:%02lld", total / 60, total % 60);
    }
    return text;
}

void Progress::update(std::int64_t done, const std::string& note) {
    if (mode_ == ProgressMode::quiet) return;
    const auto now = std::chrono::steady_clock::now();
    const auto interval =
        mode_ == ProgressMode::bar
            ? std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                  std::chrono::milliseconds(200))
            : std::chrono::duration_cast<std::chrono::steady_clock::duration>(line_interval_);
    if (now - last_draw_ < interval) return;
    last_draw_ = now;
    draw(done, note, false);
}

void Progress::finish(std::int64_t done, const std::string& note) {
    if (mode_ == ProgressMode::quiet) return;
    draw(done, note, true);
}

void Progress::draw(std::int64_t done, const std::string& note, bool final) {
    const double elapsed =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
    const auto fresh = static_cast<double>(done - already_);
    const double rate = elapsed > 0.0 ? fresh / elapsed : 0.0;
    const double left = rate > 0.0 ? static_cast<double>(total_ - done) / rate : NAN;
    const double share =
        std::clamp(static_cast<double>(done) / static_cast<double>(total_), 0.0, 1.0);
    char numbers[160];
    std::snprintf(numbers, sizeof numbers, "%lld/%lld %s %3.0f%%  %.1f %s/s  %s %s",
                  static_cast<long long>(done), static_cast<long long>(total_), unit_.c_str(),
                  100.0 * share, rate, unit_.c_str(), final ? "elapsed" : "left",
                  format_duration(final ? elapsed : left).c_str());
    std::string line = numbers;
    if (!note.empty()) line += "  " + note;
    if (mode_ == ProgressMode::bar) {
        constexpr int width = 30;
        const int filled = static_cast<int>(share * width);
        const std::string bar = "[" + std::string(static_cast<std::size_t>(filled), '#') +
                                std::string(static_cast<std::size_t>(width - filled), '.') + "] ";
        // \r and a clear-to-end-of-line escape redraw the line in place.
        out_ << '\r' << bar << line << "\x1b[K";
        if (final) out_ << '\n';
    } else {
        out_ << line << '\n';
    }
    out_.flush();
}

}  // namespace rockfall::app
