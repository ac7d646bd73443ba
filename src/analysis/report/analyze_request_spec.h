#pragma once
// The analysis request's options, declared once: `lenslab analyze`'s (and `lenslab sweep
// --analyze`'s) command-line options are made from this list, Python's lenslab.analyze checks
// its keywords against it (lenslab.analyze_options()) and the compiled module fills the
// request through it; tests hold the Python signature, the .pyi stub and the docs table of
// docs/optical-bench.md to it.

#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "analysis/report/analyze_request.h"

namespace lenslab {

// What an option takes. Numbers are finite; "positive" ones > 0.
enum class RequestValue {
    Flag,             // on when given
    Number,           // one number
    PositiveNumber,   // one number > 0
    Whole,            // a whole number from `low` to `high`
    Numbers,          // numbers, comma-separated on the command line
    PositiveNumbers,  // numbers > 0, comma-separated
    Text,             // a string
    Texts,            // strings (Python only: a list)
    Choice,           // one of `choices`
};

// Where an option exists: figure files and the output format are the command line's (Python
// asks for figures with Analysis.figure), the report's keys Python's.
enum class RequestWhere { Both, CommandLine, Python };

struct RequestOption {
    std::string name;        // the command line's, without "--" ("field-curve-points")
    std::string short_name;  // a one-letter alias ("w") or ""
    RequestValue value = RequestValue::Flag;
    RequestWhere where = RequestWhere::Both;
    std::string help;
    int low = 0, high = 0;             // Whole: the range
    std::vector<std::string> choices;  // Choice
    // Options that may not be given with this one, and why (one reason for all of them).
    std::vector<std::string> excludes;
    std::string excludes_why;
    // An option that must be given with this one, and why.
    std::string needs;
    std::string needs_why;
    // Stores a value (as JSON: a bool, number, string or list of them, already checked
    // against the declaration) into the request; `get` reads it back, for the defaults.
    std::function<void(AnalyzeRequest&, const nlohmann::json&)> set;
    std::function<nlohmann::json(const AnalyzeRequest&)> get;

    // Python's keyword: the name with "_" for "-".
    std::string python_name() const;
    // The default Python's signature writes: a flag's value in a default AnalyzeRequest, a
    // whole number's where it lies in the range, else null (None: not given).
    nlohmann::json python_default() const;
};

// Every option, in the order `lenslab analyze --help` lists them.
const std::vector<RequestOption>& analyze_request_options();

// The declaration of the option `name` (command-line spelling), nullptr if none.
const RequestOption* find_request_option(const std::string& name);

// Python's view of the declarations, one object per option Python has: name (the keyword),
// option ("--name"), value ("flag", "number", "positive_number", "whole", "numbers",
// "positive_numbers", "text", "texts", "choice"), default, help, and where they apply low,
// high, choices, excludes and excludes_why, needs and needs_why (Python's names).
nlohmann::ordered_json analyze_request_options_json();

// The request from Python's keywords (an object keyed by python_name(), values checked by
// lenslab/_optics.py against analyze_request_options_json()); an unknown key throws
// AnalyzeRequestError.
AnalyzeRequest analyze_request_from_json(const nlohmann::json& values);

}  // namespace lenslab
