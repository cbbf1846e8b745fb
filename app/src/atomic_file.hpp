#pragma once
/// Output files that appear under their name only when complete.

#include "report/svg_plot.hpp"

#include <filesystem>
#include <fstream>

namespace rockfall::app {

/// Writes to `NAME.part` and renames it to NAME on commit(), so that an interrupted or failed
/// run never leaves a half-written file under the requested name; an uncommitted part file is
/// removed when the object is destroyed.
class AtomicFile {
  public:
    /// Opens `path.part`; throws std::runtime_error naming the file when it cannot.
    explicit AtomicFile(std::filesystem::path path);
    AtomicFile(const AtomicFile&) = delete;
    AtomicFile& operator=(const AtomicFile&) = delete;
    ~AtomicFile();

    /// The stream to write to.
    std::ofstream& stream() { return out_; }
    /// Flushes, checks for write errors and renames the part file; throws on failure.
    void commit();

  private:
    std::filesystem::path path_;
    std::filesystem::path part_;
    std::ofstream out_;
    bool committed_ = false;
};

/// Writes report::render_svg(plot) to a file, which appears only when complete.
void write_svg(const std::filesystem::path& path, const report::Plot& plot);

}  // namespace rockfall::app
