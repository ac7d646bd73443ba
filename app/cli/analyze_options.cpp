#include "analyze_options.h"

#include <map>

#include "analysis/report/analyze_request_spec.h"
#include "commands.h"

namespace lenslab::cli {

namespace {

// One declared option as a CLI11 option writing into `request`.
CLI::Option* add_declared(CLI::App& cmd, const RequestOption& o, AnalyzeRequest& request) {
    const std::string names =
        (o.short_name.empty() ? "" : "-" + o.short_name + ",") + "--" + o.name;
    auto store = [&request, &o](const auto& value) { o.set(request, nlohmann::json(value)); };
    switch (o.value) {
        case RequestValue::Flag:
            return cmd.add_flag_callback(
                names, [store] { store(true); }, o.help);
        case RequestValue::Number:
            return cmd.add_option_function<double>(names, store, o.help);
        case RequestValue::PositiveNumber:
            return cmd.add_option_function<double>(names, store, o.help)
                ->check(CLI::PositiveNumber);
        case RequestValue::Whole:
            return cmd.add_option_function<int>(names, store, o.help)
                ->check(whole_number<int>())
                ->check(CLI::Range(o.low, o.high));
        case RequestValue::Numbers:
            return cmd.add_option_function<std::vector<double>>(names, store, o.help)
                ->delimiter(',');
        case RequestValue::PositiveNumbers:
            return cmd.add_option_function<std::vector<double>>(names, store, o.help)
                ->delimiter(',')
                ->check(CLI::PositiveNumber);
        case RequestValue::Text:
            return cmd.add_option_function<std::string>(names, store, o.help);
        case RequestValue::Texts:
            return cmd.add_option_function<std::vector<std::string>>(names, store, o.help)
                ->delimiter(',');
        case RequestValue::Choice:
            return cmd.add_option_function<std::string>(names, store, o.help)
                ->check(CLI::IsMember(o.choices));
    }
    return nullptr;
}

}  // namespace

void add_analyze_options(CLI::App& cmd, AnalyzeRequest& request) {
    std::map<std::string, CLI::Option*> added;
    for (const RequestOption& o : analyze_request_options())
        if (o.where != RequestWhere::Python) added[o.name] = add_declared(cmd, o, request);
    for (const RequestOption& o : analyze_request_options()) {
        if (o.where == RequestWhere::Python) continue;
        for (const std::string& other : o.excludes) added.at(o.name)->excludes(added.at(other));
        if (!o.needs.empty()) added.at(o.name)->needs(added.at(o.needs));
    }
}

}  // namespace lenslab::cli
