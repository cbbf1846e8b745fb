// The worker threads a command runs on.

#include "threads.hpp"

#include <algorithm>
#include <sched.h>
#include <thread>

namespace rockfall::app {

int thread_count(int requested) {
    if (requested > 0) return requested;
    cpu_set_t allowed;
    CPU_ZERO(&allowed);
    if (sched_getaffinity(0, sizeof allowed, &allowed) == 0)
        return std::max(1, CPU_COUNT(&allowed));
    return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace rockfall::app
