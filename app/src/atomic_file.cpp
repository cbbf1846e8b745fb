#include "atomic_file.hpp"

#include <stdexcept>
#include <system_error>

namespace rockfall::app {

AtomicFile::AtomicFile(std::filesystem::path path)
    : path_(std::move(path)), part_(path_.string() + ".part"), out_(part_) {
    if (!out_) throw std::runtime_error("cannot write the file '" + part_.string() + "'");
}

AtomicFile::~AtomicFile() {
    if (committed_) return;
    out_.close();
    std::error_code ignored;
    std::filesystem::remove(part_, ignored);
}

void AtomicFile::commit() {
    out_.close();
    if (!out_) throw std::runtime_error("writing the file '" + part_.string() + "' failed");
    std::filesystem::rename(part_, path_);
    committed_ = true;
}

void write_svg(const std::filesystem::path& path, const report::Plot& plot) {
    AtomicFile file(path);
    file.stream() << report::render_svg(plot);
    file.commit();
}

}  // namespace rockfall::app
