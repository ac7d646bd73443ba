#pragma once
// The job lenslab runs in. Created once, first thing in main(): when mpirun or srun started
// the process (and lenslab was built with MPI) it initialises MPI and the world communicator
// is every rank; otherwise MPI is never touched and the world is this process alone, so
// `lenslab render` on a laptop behaves as it always did. MPI is finalised when it goes.
//
// Ranks other than 0 send their stdout and stderr to /dev/null: rank 0 prints the job's
// progress and results. An error on any rank is still printed (report_error restores that
// rank's stderr first) and ends the whole job.

#include <memory>
#include <string>

#include "cluster/communicator.h"

namespace lenslab {

// True when a launcher's variables say this process is one rank of a parallel job
// (Open MPI's mpirun, a PMI or PMIx launcher, Slurm's srun).
bool launched_as_parallel_job();

// Whether this lenslab was built with MPI (-DLENSLAB_MPI).
bool built_with_mpi();

class ClusterSession {
public:
    ClusterSession();
    ~ClusterSession();
    ClusterSession(const ClusterSession&) = delete;
    ClusterSession& operator=(const ClusterSession&) = delete;

    Communicator& world() { return *m_world; }

    // Prints "lenslab: KIND: MESSAGE" on this rank's real stderr ("lenslab: KIND (rank R of
    // N): MESSAGE" in a job of several ranks, which it then ends at once with `exit_code`);
    // alone, it returns and the caller exits as usual.
    void report_error(const std::string& kind, const std::string& message, int exit_code);

private:
    std::unique_ptr<Communicator> m_world_owned;
    Communicator* m_world = nullptr;
    [[maybe_unused]] bool m_mpi = false;  // MPI was initialised (only with MPI built in)
    int m_saved_stderr = -1;              // rank > 0: the stderr it had before /dev/null
};

// The world of the live ClusterSession, or this process alone when there is none (the
// library used from the editor, Python or a test).
Communicator& world_communicator();

}  // namespace lenslab
