#include "mpm/vtk.hpp"

#include <bit>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

namespace rockfall::mpm {
namespace {

// Legacy VTK binary data is big-endian.
template <typename T>
void put_big_endian(std::ofstream& out, T value) {
    unsigned char bytes[sizeof(T)];
    std::memcpy(bytes, &value, sizeof(T));
    if constexpr (std::endian::native == std::endian::little) {
        for (std::size_t i = 0; i < sizeof(T) / 2; ++i) {
            std::swap(bytes[i], bytes[sizeof(T) - 1 - i]);
        }
    }
    out.write(reinterpret_cast<const char*>(bytes), sizeof(T));
}

void put_scalars(std::ofstream& out, const char* name, const std::vector<double>& values) {
    out << "SCALARS " << name << " double 1\nLOOKUP_TABLE default\n";
    for (const double v : values) {
        put_big_endian(out, v);
    }
    out << '\n';
}

}  // namespace

void write_vtk(const std::filesystem::path& file, const ParticleFrame& frame) {
    std::ofstream out(file, std::ios::binary);
    if (!out) {
        throw std::runtime_error("cannot open " + file.string() + " for writing");
    }
    const std::size_t n = frame.position.size();
    out << "# vtk DataFile Version 3.0\nrockfall soil particles, t = " << frame.time
        << " s\nBINARY\nDATASET POLYDATA\nPOINTS " << n << " double\n";
    for (const Vec3& p : frame.position) {
        for (int d = 0; d < 3; ++d) {
            put_big_endian(out, p[d]);
        }
    }
    out << "\nVERTICES " << n << ' ' << 2 * n << '\n';
    for (std::size_t i = 0; i < n; ++i) {
        put_big_endian(out, std::int32_t{1});
        put_big_endian(out, static_cast<std::int32_t>(i));
    }
    out << "\nPOINT_DATA " << n << "\nVECTORS velocity double\n";
    for (const Vec3& v : frame.velocity) {
        for (int d = 0; d < 3; ++d) {
            put_big_endian(out, v[d]);
        }
    }
    out << '\n';
    put_scalars(out, "mass", frame.mass);
    put_scalars(out, "mean_stress", frame.mean_stress);
    put_scalars(out, "deviatoric_stress", frame.deviatoric_stress);
    put_scalars(out, "plastic_shear_strain", frame.plastic_shear_strain);
    if (!out) {
        throw std::runtime_error("failed writing " + file.string());
    }
}

}  // namespace rockfall::mpm
