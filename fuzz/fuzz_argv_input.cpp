// The argument fuzzer's entry point, apart from fuzz_inputs.cpp: it needs the command line's
// library (app/cli), which the other targets do not link.

#include <string>
#include <vector>

#include "cli_parse.h"
#include "fuzz_inputs.h"

namespace lenslab::fuzz {

void parse_argv_input(std::string_view data) {
    std::vector<std::string> args{"lenslab"};
    std::string arg;
    for (const char c : data) {
        if (c == '\0' || c == '\n') {
            args.push_back(std::move(arg));
            arg.clear();
        } else {
            arg += c;
        }
    }
    if (!arg.empty()) args.push_back(std::move(arg));
    std::vector<const char*> argv;
    for (const std::string& a : args) argv.push_back(a.c_str());

    cli::CommandLine command_line;
    try {
        command_line.parse(static_cast<int>(argv.size()), argv.data());
    } catch (const CLI::ParseError&) {
        return;  // refused (or --help, --version): what a bad command line must get
    }
    (void)command_line.chosen();
}

}  // namespace lenslab::fuzz
