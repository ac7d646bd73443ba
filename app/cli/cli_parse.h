#pragma once
// The whole command line of `lenslab`: every command with its options, and the checks every
// option shares (check_every_option). Apart from main() so the argument fuzzer
// (fuzz/fuzz_argv.cpp) can parse and validate a command line without running it.

#include <CLI/CLI.hpp>
#include <string>
#include <utility>
#include <vector>

#include "commands.h"

namespace lenslab::cli {

class CommandLine {
public:
    CommandLine();
    CommandLine(const CommandLine&) = delete;
    CommandLine& operator=(const CommandLine&) = delete;

    // Parses and validates `argv` (argv[0] the program); throws CLI::ParseError, whose exit
    // code is 0 for --help and --version.
    void parse(int argc, const char* const* argv);
    // The chosen command's action after a parse, or nullptr when there is none.
    const Action* chosen() const;
    // Prints --help or --version, or the error, and returns the exit code (CLI::App::exit).
    int exit(const CLI::ParseError& e) { return m_app.exit(e); }

private:
    CLI::App m_app;
    std::vector<std::pair<std::string, Action>> m_commands;  // by subcommand name
    std::vector<std::string> m_catalogues;                   // --catalogue FILE, loaded first
};

}  // namespace lenslab::cli
