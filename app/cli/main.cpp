// lenslab: render scenes and trace rays through lenses from the command line.

#include <iostream>

#include "cli_parse.h"
#include "cluster/cluster_session.h"
#include "util/error.h"

int main(int argc, char** argv) {
    // First: under mpirun or srun this makes the process one rank of the job (docs/cluster.md).
    lenslab::ClusterSession cluster;
    lenslab::cli::CommandLine cli;
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        std::cerr << "lenslab: error: " << e.what() << "\nRun 'lenslab --help' for usage.\n";
        return 2;
    }
    // An error on one rank of a job ends them all (report_error), with its message.
    try {
        if (const lenslab::cli::Action* action = cli.chosen()) return (*action)();
    } catch (const lenslab::Error& e) {  // the user's to fix: bad input, a full disk, ...
        cluster.report_error("error", e.what(), 1);
        return 1;
    } catch (const std::exception& e) {
        cluster.report_error("internal error", e.what(), 3);
        return 3;
    }
    return 2;
}
