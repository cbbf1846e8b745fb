// A build without MPI (CMake found none): started as one of several ranks, a sweep says so
// and ends; nothing else here is reachable, since no Session is ever made.

#include "sweep_mpi.hpp"

#include <cstdlib>
#include <stdexcept>

namespace rockfall::app::mpi {

Session::Session() {
    throw std::runtime_error(
        "this process is one of several MPI ranks (mpirun or srun), but this rockfall was built "
        "without MPI: install Open MPI (apt-get install libopenmpi-dev openmpi-bin) and build "
        "again, or run without mpirun (one process uses every core; --shard K/N splits a sweep "
        "over machines without MPI, see docs/cluster.md)");
}

Session::~Session() = default;

void Session::send_setup(const Setup&) { std::abort(); }

std::optional<Setup> Session::receive_setup() { std::abort(); }

std::unique_ptr<SampleSource> Session::owner_source(const risk::SweepSpec&, const engine::Scenario&,
                                                    std::vector<std::int64_t>,
                                                    const risk::RunnerOptions&, std::atomic<int>&) {
    std::abort();
}

int Session::serve(const risk::SweepSpec&, const engine::Scenario&, const risk::RunnerOptions&,
                   const std::atomic<int>&) {
    std::abort();
}

bool Session::others_running() const { return false; }

void Session::abort(int) { std::abort(); }

}  // namespace rockfall::app::mpi
