#include "engine/outcome.hpp"

#include "state_hash.hpp"

#include <bit>

namespace rockfall::engine {

std::string_view to_string(StopReason reason) {
    switch (reason) {
        case StopReason::at_rest:
            return "at_rest";
        case StopReason::left_domain:
            return "left_domain";
        case StopReason::time_limit:
            return "time_limit";
        case StopReason::numerical_failure:
            return "numerical_failure";
    }
    return "unknown";
}

namespace {

// FNV-1a, 64 bit (Fowler, Noll, Vo): every byte of every double, in a fixed order.
class Fnv1a {
  public:
    void add(double value) {
        auto bits = std::bit_cast<std::uint64_t>(value);
        for (int i = 0; i < 8; ++i) {
            hash_ ^= bits & 0xffU;
            hash_ *= 0x100000001b3ULL;
            bits >>= 8;
        }
    }
    void add(const Vec3& v) {
        add(v.x());
        add(v.y());
        add(v.z());
    }
    std::uint64_t value() const { return hash_; }

  private:
    std::uint64_t hash_ = 0xcbf29ce484222325ULL;
};

}  // namespace

std::uint64_t state_hash(const std::vector<RockOutcome>& rocks) {
    Fnv1a hash;
    for (const RockOutcome& rock : rocks) {
        const RockState& s = rock.final_state;
        hash.add(s.time);
        hash.add(s.position);
        hash.add(s.orientation.coeffs().x());
        hash.add(s.orientation.coeffs().y());
        hash.add(s.orientation.coeffs().z());
        hash.add(s.orientation.coeffs().w());
        hash.add(s.velocity);
        hash.add(s.angular_velocity);
    }
    return hash.value();
}

}  // namespace rockfall::engine
