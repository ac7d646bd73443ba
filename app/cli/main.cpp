// lenslab: render scenes and trace rays through lenses from the command line.

#include <iostream>

#include "cli_parse.h"
#include "util/error.h"

int main(int argc, char** argv) {
    lenslab::cli::CommandLine cli;
    try {
        cli.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        if (e.get_exit_code() == 0) return cli.exit(e);  // --help, --version
        std::cerr << "lenslab: error: " << e.what() << "\nRun 'lenslab --help' for usage.\n";
        return 2;
    }
    try {
        if (const lenslab::cli::Action* action = cli.chosen()) return (*action)();
    } catch (const lenslab::Error& e) {  // the user's to fix: bad input, a full disk, ...
        std::cerr << "lenslab: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "lenslab: internal error: " << e.what() << "\n";
        return 3;
    }
    return 2;
}
