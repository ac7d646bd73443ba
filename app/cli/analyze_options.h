#pragma once
// The optical bench's options (--wavelength, --stop, --epd, --fields, --spots, ...), for
// `lenslab analyze` and `lenslab sweep --analyze` alike, so both read them the same way.

#include <CLI/CLI.hpp>

#include "analysis/report/analyze_request.h"

namespace lenslab::cli {

// Adds the options to `cmd`; their values go into `request`, which must outlive the parse.
void add_analyze_options(CLI::App& cmd, AnalyzeRequest& request);

}  // namespace lenslab::cli
