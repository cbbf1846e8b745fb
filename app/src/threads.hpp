#pragma once
/// The worker threads a command runs on.

namespace rockfall::app {

/// `requested` when > 0; for 0 the cores this process may run on: its CPU affinity, which a
/// scheduler's allocation (Slurm's cgroups, mpirun's binding) narrows, rather than all of the
/// node's; at least 1.
int thread_count(int requested);

}  // namespace rockfall::app
