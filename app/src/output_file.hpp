#pragma once
/// The one rule for every file rockfall writes (trajectories, CSV tables, SVG figures, OBJ and
/// STL meshes, VTK frames): a file appears whole or not at all, and nothing that is not a
/// regular file is ever replaced.
///
/// - Absent, or a regular file (also behind symbolic links, which are kept): written beside it
///   as `NAME.part` and renamed over it when complete; an interrupted or failed run leaves the
///   old file, or none, and removes the part file.
/// - A character device or a FIFO (/dev/null, a terminal, a named pipe), or a path that names
///   an open file descriptor through /proc (/dev/stdout, /dev/fd/N, whatever they lead to):
///   written directly, appending to what the descriptor already holds.
/// - A directory, block device, socket or anything else: refused, nothing written.
///
/// The results databases follow their own rule (db::ResultsDb: a new regular file only).

#include "report/svg_plot.hpp"

#include <filesystem>
#include <fstream>
#include <functional>

namespace rockfall::app {

/// How an output path is written.
struct OutputTarget {
    /// The file written: the path itself, or the file its symbolic links lead to.
    std::filesystem::path file;
    /// Whether it is written directly (device, FIFO, descriptor) instead of part file + rename.
    bool direct = false;
};

/// Applies the rule to `path` (what it is now); throws std::invalid_argument naming the path
/// and what it is when it may not be written. Call it before a long run whose outputs are
/// written at the end, so that a bad path is refused before the work.
OutputTarget output_target(const std::filesystem::path& path);

/// An output file written by the rule: open at construction (refused paths throw), written
/// through stream(), published by commit(); without commit() the part file is removed.
class OutputFile {
  public:
    /// Applies output_target() and opens the part file or the target; throws naming the file.
    explicit OutputFile(const std::filesystem::path& path);
    OutputFile(const OutputFile&) = delete;
    OutputFile& operator=(const OutputFile&) = delete;
    ~OutputFile();

    /// The stream to write to.
    std::ofstream& stream() { return out_; }
    /// The file the bytes go to: the part file, or the target when written directly.
    const std::filesystem::path& written() const { return target_.direct ? target_.file : part_; }
    /// Flushes, checks for write errors and renames the part file; throws on failure.
    void commit();

  private:
    std::filesystem::path path_;
    OutputTarget target_;
    std::filesystem::path part_;
    std::ofstream out_;
    bool committed_ = false;
};

/// The rule for a writer that takes a path (mpm::write_vtk): `write` is called with the part
/// file's path or the target's, and the part file is renamed or removed after it.
void write_output_file(const std::filesystem::path& path,
                       const std::function<void(const std::filesystem::path&)>& write);

/// Writes report::render_svg(plot) to `path` by the rule.
void write_svg(const std::filesystem::path& path, const report::Plot& plot);

}  // namespace rockfall::app
