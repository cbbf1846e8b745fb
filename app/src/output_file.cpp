#include "output_file.hpp"

#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <string>
#include <system_error>

namespace rockfall::app {
namespace {

namespace fs = std::filesystem;

// What a file system object is, for refusals.
std::string kind_of(fs::file_type type) {
    switch (type) {
        case fs::file_type::directory:
            return "a directory";
        case fs::file_type::block:
            return "a block device";
        case fs::file_type::socket:
            return "a socket";
        default:
            return "not a regular file, character device or FIFO";
    }
}

[[noreturn]] void refuse(const fs::path& path, const std::string& why) {
    throw std::invalid_argument("cannot write the output file '" + path.string() + "': " + why);
}

bool under_proc(const fs::path& absolute) {
    const auto first = std::next(absolute.begin());
    return first != absolute.end() && *first == "proc";
}

// Follows the symbolic links of `path` one at a time (directories resolved on the way), up to
// the file they lead to; `through_proc` says whether the way passed /proc, where a path names
// an open descriptor (/dev/stdout -> /proc/self/fd/1) rather than a file to replace.
fs::path follow_links(const fs::path& path, bool& through_proc) {
    fs::path at = fs::absolute(path).lexically_normal();
    through_proc = false;
    for (int hop = 0; hop < 40; ++hop) {
        std::error_code error;
        const fs::path directory = fs::weakly_canonical(at.parent_path(), error);
        if (!error) at = directory / at.filename();
        through_proc = through_proc || under_proc(at);
        if (!fs::is_symlink(fs::symlink_status(at, error))) return at;
        const fs::path target = fs::read_symlink(at, error);
        if (error) return at;
        at = (target.is_absolute() ? target : at.parent_path() / target).lexically_normal();
    }
    refuse(path, "too many levels of symbolic links");
}

}  // namespace

OutputTarget output_target(const fs::path& path) {
    if (path.empty()) refuse(path, "the path is empty");
    bool through_proc = false;
    OutputTarget target{follow_links(path, through_proc), false};
    std::error_code error;
    // A descriptor's link in /proc may name no path (pipe:[123]); the kernel still opens it.
    if (through_proc && fs::exists(fs::status(path, error))) return {path, true};
    const fs::file_status status = fs::status(target.file, error);
    const fs::file_type type = status.type();
    if (type == fs::file_type::character || type == fs::file_type::fifo) {
        target.direct = true;
    } else if (fs::exists(status) && type != fs::file_type::regular) {
        refuse(path, "it is " + kind_of(type) +
                         "; rockfall writes regular files (replaced whole), character devices "
                         "and FIFOs only");
    }
    return target;
}

OutputFile::OutputFile(const fs::path& path) : path_(path), target_(output_target(path)) {
    if (target_.direct) {
        // Appending: a descriptor's file (stdout redirected with >>) keeps what it holds.
        out_.open(target_.file, std::ios::out | std::ios::app | std::ios::binary);
        if (!out_) refuse(path_, std::strerror(errno));
        return;
    }
    part_ = target_.file.string() + ".part";
    std::error_code error;
    const fs::file_status part_status = fs::symlink_status(part_, error);
    if (fs::exists(part_status) && !fs::is_regular_file(part_status)) {
        refuse(path_, "its temporary file '" + part_.string() +
                          "' exists and is not a regular file; remove it");
    }
    out_.open(part_, std::ios::out | std::ios::trunc | std::ios::binary);
    if (!out_) {
        const std::string reason = std::strerror(errno);
        const fs::path directory = target_.file.parent_path();
        refuse(path_, fs::is_directory(directory, error)
                          ? "cannot create its temporary file '" + part_.string() + "': " + reason
                          : "its directory '" + directory.string() + "' does not exist");
    }
    // A replaced file keeps its permissions.
    const fs::file_status old = fs::status(target_.file, error);
    if (fs::is_regular_file(old)) fs::permissions(part_, old.permissions(), error);
}

OutputFile::~OutputFile() {
    if (committed_ || target_.direct) return;
    out_.close();
    std::error_code ignored;
    fs::remove(part_, ignored);
}

void OutputFile::commit() {
    if (out_.is_open()) out_.close();
    if (out_.fail())
        throw std::runtime_error("writing the file '" + written().string() + "' failed");
    if (!target_.direct) fs::rename(part_, target_.file);
    committed_ = true;
}

void write_output_file(const fs::path& path, const std::function<void(const fs::path&)>& write) {
    OutputFile file(path);
    // The writer opens the file by its path; the stream only showed that it can be opened.
    file.stream().close();
    write(file.written());
    file.commit();
}

void write_svg(const fs::path& path, const report::Plot& plot) {
    OutputFile file(path);
    file.stream() << report::render_svg(plot);
    file.commit();
}

}  // namespace rockfall::app
