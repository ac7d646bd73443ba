#include "cluster/cluster_session.h"

#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <string>

#include "util/error.h"

#ifdef LENSLAB_HAVE_MPI
// The C API only: Open MPI's mpi.h otherwise pulls in its C++ bindings (removed in MPI-3).
#ifndef OMPI_SKIP_MPICXX
#define OMPI_SKIP_MPICXX 1
#endif
#include <mpi.h>

#include "cluster/mpi_communicator.h"
#endif

namespace lenslab {

namespace {

ClusterSession* g_session = nullptr;

bool has_variable(const char* name) {
    const char* v = std::getenv(name);
    return v && *v;
}

#ifdef LENSLAB_HAVE_MPI
// stdout and stderr to /dev/null; returns a copy of the old stderr for errors.
int silence_output() {
    const int null = open("/dev/null", O_WRONLY);
    if (null < 0) return -1;
    std::fflush(stdout);
    std::fflush(stderr);
    const int saved = dup(2);
    dup2(null, 1);
    dup2(null, 2);
    close(null);
    return saved;
}
#endif

}  // namespace

bool launched_as_parallel_job() {
    return has_variable("OMPI_COMM_WORLD_SIZE") || has_variable("PMI_SIZE") ||
           has_variable("PMI_RANK") || has_variable("PMIX_RANK") ||
           (has_variable("SLURM_STEP_ID") && has_variable("SLURM_STEP_NUM_TASKS"));
}

bool built_with_mpi() {
#ifdef LENSLAB_HAVE_MPI
    return true;
#else
    return false;
#endif
}

ClusterSession::ClusterSession() {
    m_world = &this_process_alone();
#ifdef LENSLAB_HAVE_MPI
    if (launched_as_parallel_job()) {
        // Only the main thread calls MPI (the TBB workers never do), one call at a time.
        int provided = 0;
        MPI_Init_thread(nullptr, nullptr, MPI_THREAD_SERIALIZED, &provided);
        m_mpi = true;
        m_world_owned = std::make_unique<MpiCommunicator>();
        m_world = m_world_owned.get();
        if (!m_world->is_root()) m_saved_stderr = silence_output();
    }
#else
    if (launched_as_parallel_job()) {
        std::cerr << "lenslab: warning: started as one rank of a parallel job, but this lenslab "
                     "was built without MPI: every rank does the whole job alone "
                     "(docs/cluster.md)\n";
    }
#endif
    g_session = this;
}

ClusterSession::~ClusterSession() {
    g_session = nullptr;
#ifdef LENSLAB_HAVE_MPI
    if (m_mpi) {
        m_world_owned.reset();
        MPI_Finalize();
    }
#endif
    if (m_saved_stderr >= 0) close(m_saved_stderr);
}

void ClusterSession::report_error(const std::string& kind, const std::string& message,
                                  int exit_code) {
    std::fflush(stderr);
    if (m_saved_stderr >= 0) dup2(m_saved_stderr, 2);
    if (m_world->alone()) {
        std::cerr << "lenslab: " << kind << ": " << message << "\n";
        return;
    }
    // One write: piece by piece, mpirun's own abort notice could land between the pieces
    // (seen under load: "lenslab: " on one line, the rest of the message after the notice).
    const std::string line = "lenslab: " + kind + " (rank " + std::to_string(m_world->rank()) +
                             " of " + std::to_string(m_world->size()) + "): " + message + "\n";
    std::cerr.write(line.data(), static_cast<std::streamsize>(line.size())).flush();
#ifdef LENSLAB_HAVE_MPI
    // The other ranks may be waiting for this one in an exchange: only an abort ends them.
    MPI_Abort(MPI_COMM_WORLD, exit_code);
#endif
    std::_Exit(exit_code);
}

Communicator& world_communicator() { return g_session ? g_session->world() : this_process_alone(); }

}  // namespace lenslab
