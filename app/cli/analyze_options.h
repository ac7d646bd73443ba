#pragma once
// The optical bench's options (--wavelength, --stop, --epd, --fields, --spots, ...), made from
// their declarations (analysis/report/analyze_request_spec.h), for `lenslab analyze` and
// `lenslab sweep --analyze` alike.

#include <CLI/CLI.hpp>

#include "analysis/report/analyze_request.h"

namespace lenslab::cli {

// Adds the options to `cmd`; their values go into `request`, which must outlive the parse.
void add_analyze_options(CLI::App& cmd, AnalyzeRequest& request);

}  // namespace lenslab::cli
