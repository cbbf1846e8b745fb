// Shape catalogues (shapes::read_catalogue), with the first entries loaded. The scratch folder
// links samples/rocks/obj and stl, so that the sample catalogue's entries find their meshes.

#include "fuzz_support.hpp"

#include "shapes/catalogue.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

namespace {

void link_sample_meshes() {
    namespace fs = std::filesystem;
    for (const char* folder : {"obj", "stl"}) {
        std::error_code ignored;
        fs::create_directory_symlink(fs::path(ROCKFALL_SAMPLES_DIR) / "rocks" / folder,
                                     rockfall::fuzz::scratch_folder() / folder, ignored);
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace rockfall;
    static const bool linked = (link_sample_meshes(), true);
    (void)linked;
    const std::filesystem::path file =
        fuzz::write_scratch("catalogue.toml", fuzz::text_of(data, size));
    fuzz::expect_clear_refusal([&] {
        const shapes::ShapeCatalogue catalogue = shapes::read_catalogue(file);
        fuzz::require(!catalogue.entries.empty(), "a catalogue without entries was accepted");
        const std::size_t loads = std::min<std::size_t>(catalogue.entries.size(), 2);
        for (std::size_t i = 0; i < loads; ++i) {
            fuzz::expect_clear_refusal([&] { shapes::load_entry(catalogue.entries[i]); });
        }
    });
    return 0;
}
