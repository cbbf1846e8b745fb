#pragma once
/// Independent jobs on worker threads, with progress reported from the calling thread: the drop
/// tests' orientations, the seed reproductions' runs.

#include <cstdint>
#include <functional>

namespace rockfall::risk {

/// Progress of parallel work: `done` of `total` units finished.
using ParallelProgress = std::function<void(std::int64_t done, std::int64_t total)>;

/// Runs job(i) for every i in [0, count) on min(threads, count) workers (threads >= 1; fewer is
/// taken as 1) taking indices in order; the calling thread waits and calls `progress` (when
/// set) about every 0.2 s with done_before plus the jobs finished, of `total`. Each job writes
/// its result to its own index, so results do not depend on the threads. The first exception
/// a job throws stops the handing out of new indices and is rethrown once the workers end.
void run_parallel(std::int64_t count, int threads, const std::function<void(std::int64_t)>& job,
                  std::int64_t done_before = 0, std::int64_t total = 0,
                  const ParallelProgress& progress = {});

}  // namespace rockfall::risk
