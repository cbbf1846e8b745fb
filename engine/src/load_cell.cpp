// The wall load cell: groups the per-step wall forces into hit events.

#include "engine/wall_contact.hpp"

#include <algorithm>
#include <cassert>
#include <utility>

namespace rockfall::engine {
namespace {

double kinetic_energy(const RockState& state) {
    return state.translational_energy + state.rotational_energy;
}

}  // namespace

void LoadCell::record(double dt, const std::optional<WallForce>& force, const RockState& before,
                      const RockState& after, bool holding) {
    assert(dt > 0.0);
    if (!force || force->normal <= 0.0) {
        if (open_ && holding) {
            open_->history.push_back(ForceSample{after.time - dt, 0.0, 0.0, dt, Vec3::Zero()});
            open_->end_time = after.time;
        } else if (open_) {
            close();
        }
        return;
    }
    // The force was evaluated from the state at the start of the step and held during it.
    const double time = after.time - dt;
    if (!open_) {
        WallHit& hit = open_.emplace();
        hit.start_time = time;
        hit.velocity_before = before.velocity;
        hit.angular_velocity_before = before.angular_velocity;
        hit.energy_before = kinetic_energy(before);
        hit.normal_speed = std::max(0.0, -before.velocity.dot(force->normal_direction));
    }
    WallHit& hit = *open_;
    const Vec3 tangential_force = force->force - force->normal * force->normal_direction;
    // Impulses on the wall: the reaction to the force on the rock.
    hit.normal_impulse += force->normal * dt;
    hit.tangential_impulse -= tangential_force * dt;
    // Accumulates sum(F_n dt p); divided by the normal impulse when the event closes.
    hit.point += force->normal * dt * force->point;
    if (force->normal > hit.peak_normal_force) {
        hit.peak_normal_force = force->normal;
        hit.peak_time = time;
    }
    hit.history.push_back(ForceSample{time, force->normal, force->tangential, dt, force->point});
    hit.end_time = after.time;
    hit.velocity_after = after.velocity;
    hit.angular_velocity_after = after.angular_velocity;
    hit.energy_after = kinetic_energy(after);
}

void LoadCell::finish(const RockState& state) {
    if (!open_) {
        return;
    }
    open_->end_time = state.time;
    open_->velocity_after = state.velocity;
    open_->angular_velocity_after = state.angular_velocity;
    open_->energy_after = kinetic_energy(state);
    close();
}

void LoadCell::close() {
    assert(open_ && open_->normal_impulse > 0.0);
    open_->point /= open_->normal_impulse;
    hits_.push_back(std::move(*open_));
    open_.reset();
}

}  // namespace rockfall::engine
