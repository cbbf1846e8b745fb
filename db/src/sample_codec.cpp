#include "db/sample_codec.hpp"

#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <type_traits>

namespace rockfall::db {
namespace {

// One field list (visit_* below) serves both directions: Writer appends each field's bytes,
// Reader fills it from them, so that the two can never disagree on the order.
class Writer {
  public:
    explicit Writer(std::string& bytes) : bytes_(bytes) {}
    template <class T>
    void value(const T& field) {
        static_assert(std::is_trivially_copyable_v<T>);
        bytes_.append(reinterpret_cast<const char*>(&field), sizeof field);
    }
    void value(const std::string& field) {
        value(static_cast<std::uint64_t>(field.size()));
        bytes_.append(field);
    }
    void value(const engine::Vec3& field) {
        for (int i = 0; i < 3; ++i) value(field[i]);
    }
    void value(const Eigen::Quaterniond& field) {
        value(field.w());
        value(field.x());
        value(field.y());
        value(field.z());
    }
    template <class T, class Visit>
    void list(const std::vector<T>& items, Visit visit) {
        value(static_cast<std::uint64_t>(items.size()));
        for (const T& item : items) visit(item);
    }

  private:
    std::string& bytes_;
};

class Reader {
  public:
    explicit Reader(std::string_view bytes) : bytes_(bytes) {}
    bool done() const { return at_ == bytes_.size(); }
    template <class T>
    void value(T& field) {
        static_assert(std::is_trivially_copyable_v<T>);
        std::memcpy(&field, take(sizeof field), sizeof field);
    }
    void value(std::string& field) {
        const std::uint64_t size = count();
        field.assign(take(size), size);
    }
    void value(engine::Vec3& field) {
        for (int i = 0; i < 3; ++i) value(field[i]);
    }
    void value(Eigen::Quaterniond& field) {
        double w = 0, x = 0, y = 0, z = 0;
        value(w);
        value(x);
        value(y);
        value(z);
        field = Eigen::Quaterniond(w, x, y, z);
    }
    template <class T, class Visit>
    void list(std::vector<T>& items, Visit visit) {
        items.resize(count());
        for (T& item : items) visit(item);
    }

  private:
    // A count no longer than the bytes left (each item takes at least one byte).
    std::uint64_t count() {
        std::uint64_t size = 0;
        value(size);
        if (size > bytes_.size() - at_)
            throw std::runtime_error("sample bytes: a count of " + std::to_string(size) +
                                     " exceeds the " + std::to_string(bytes_.size() - at_) +
                                     " bytes left");
        return size;
    }
    const char* take(std::size_t size) {
        if (size > bytes_.size() - at_)
            throw std::runtime_error("sample bytes: a record is cut short (" +
                                     std::to_string(bytes_.size() - at_) + " bytes left, " +
                                     std::to_string(size) + " needed)");
        const char* start = bytes_.data() + at_;
        at_ += size;
        return start;
    }
    std::string_view bytes_;
    std::size_t at_ = 0;
};

template <class Io, class Material>
void visit_material(Io& io, Material& m) {
    io.value(m.friction);
    io.value(m.restitution);
    io.value(m.rolling_resistance);
}

template <class Io, class State>
void visit_state(Io& io, State& s) {
    io.value(s.time);
    io.value(s.position);
    io.value(s.orientation);
    io.value(s.velocity);
    io.value(s.angular_velocity);
    io.value(s.translational_energy);
    io.value(s.rotational_energy);
}

template <class Io, class Station>
void visit_station(Io& io, Station& s) {
    io.value(s.distance_from_toe);
    io.value(s.reached);
    io.value(s.time);
    io.value(s.speed);
    io.value(s.parallel_speed);
    io.value(s.angular_speed);
    io.value(s.bounce_height);
    io.value(s.rolling_coefficient);
    io.value(s.translational_energy);
    io.value(s.rotational_energy);
}

template <class Io, class Hit>
void visit_hit(Io& io, Hit& h) {
    io.value(h.start_time);
    io.value(h.end_time);
    io.value(h.point);
    io.value(h.normal_impulse);
    io.value(h.tangential_impulse);
    io.value(h.velocity_before);
    io.value(h.velocity_after);
    io.value(h.angular_velocity_before);
    io.value(h.angular_velocity_after);
    io.value(h.energy_before);
    io.value(h.energy_after);
    io.value(h.normal_speed);
    io.value(h.peak_normal_force);
    io.value(h.peak_time);
}

template <class Io, class Rock>
void visit_rock(Io& io, Rock& rock) {
    auto& in = rock.inputs;
    io.value(in.cluster);
    io.value(in.kind);
    io.value(in.shape);
    io.value(in.size);
    io.value(in.density);
    io.value(in.mass);
    visit_material(io, in.material);
    auto& out = rock.outcome;
    io.value(out.name);
    io.value(out.size);
    io.value(out.stop);
    io.value(out.stop_time);
    io.value(out.reach);
    visit_state(io, out.final_state);
    io.value(out.max_speed);
    io.value(out.max_kinetic_energy);
    io.value(out.max_bounce_height);
    io.list(out.stations, [&](auto& s) { visit_station(io, s); });
    io.value(out.velocity_change);
    io.list(out.wall_hits, [&](auto& h) { visit_hit(io, h); });
    io.list(rock.trajectory, [&](auto& s) { visit_state(io, s); });
}

template <class Io, class Record>
void visit_sample(Io& io, Record& record) {
    auto& in = record.inputs;
    io.value(in.index);
    io.value(in.seed);
    io.value(in.zone);
    io.value(in.kind);
    io.value(in.shape);
    io.value(in.target_sphericity);
    io.value(in.shape_seed);
    io.value(in.sphericity);
    io.value(in.size);
    io.value(in.density);
    visit_material(io, in.material);
    io.value(in.release_distance);
    io.value(in.release_lateral);
    io.value(in.speed);
    io.value(in.spin);
    io.value(in.orientation_deg);
    io.value(in.mass);
    io.list(record.rocks, [&](auto& rock) { visit_rock(io, rock); });
}

}  // namespace

void encode_sample(const SampleRecord& record, std::string& bytes) {
    Writer writer(bytes);
    visit_sample(writer, record);
}

std::vector<SampleRecord> decode_samples(std::string_view bytes) {
    Reader reader(bytes);
    std::vector<SampleRecord> records;
    while (!reader.done()) visit_sample(reader, records.emplace_back());
    return records;
}

}  // namespace rockfall::db
