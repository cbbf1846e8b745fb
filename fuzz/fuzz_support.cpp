#include "fuzz_support.hpp"

#include <fstream>
#include <system_error>
#include <unistd.h>

namespace rockfall::fuzz {
namespace {

namespace fs = std::filesystem;

fs::path make_scratch() {
    std::error_code error;
    const fs::path base =
        fs::is_directory("/dev/shm", error) ? fs::path("/dev/shm") : fs::temp_directory_path();
    fs::path folder = base / ("rockfall_fuzz_" + std::to_string(getpid()));
    fs::create_directories(folder);
    std::atexit([] {
        std::error_code ignored;
        fs::remove_all(scratch_folder(), ignored);
    });
    return folder;
}

}  // namespace

const fs::path& scratch_folder() {
    static const fs::path folder = make_scratch();
    return folder;
}

fs::path write_scratch(const std::string& name, std::string_view bytes) {
    const fs::path path = scratch_folder() / name;
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    require(static_cast<bool>(out), "cannot write the scratch file");
    return path;
}

}  // namespace rockfall::fuzz
