#include "math/formula.h"

#include <muParser.h>
#include <oneapi/tbb/enumerable_thread_specific.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <string_view>

namespace lenslab {

namespace {

std::string describe(int position, const std::string& message) {
    if (position <= 0) return "cannot parse: " + message;
    return "cannot parse at position " + std::to_string(position) + ": " + message;
}

// muparser appends " found at position 4" (counting from 0) to its messages; the position
// is reported separately, counting from 1 as editors do.
// Scanned from the end by hand: std::regex backtracks for seconds over a long message (a
// fuzzed formula's text is part of it).
std::string strip_position(std::string msg) {
    const auto space_before = [&](size_t i) {
        while (i > 0 && std::isspace(static_cast<unsigned char>(msg[i - 1]))) --i;
        return i;
    };
    const auto ends_with_at = [&](size_t i, std::string_view word) {
        return i >= word.size() &&
               std::string_view(msg).substr(i - word.size(), word.size()) == word;
    };
    size_t end = msg.size();
    if (end > 0 && msg[end - 1] == '.') --end;
    size_t digits = end;
    while (digits > 0 && std::isdigit(static_cast<unsigned char>(msg[digits - 1]))) --digits;
    constexpr std::string_view kAt = "at position ";
    if (digits < end && ends_with_at(digits, kAt)) {
        const size_t at = digits - kAt.size();
        size_t cut = space_before(at);
        if (cut < at) {
            if (ends_with_at(cut, "found")) {
                const size_t before_found = space_before(cut - 5);
                if (before_found < cut - 5) cut = before_found;
            }
            msg.erase(cut);
        }
    }
    while (!msg.empty() && (msg.back() == '.' || msg.back() == ' ')) msg.pop_back();
    return msg;
}

// muparser counts from 0 and places end-of-text errors one or two past the end; users count
// from 1, and "just after the last character" is the end.
FormulaError syntax_error(const mu::Parser::exception_type& e, const std::string& text) {
    const int position = e.GetPos() >= 0 ? std::min(e.GetPos() + 1, int(text.size()) + 1) : 0;
    return FormulaError(position, describe(position, strip_position(e.GetMsg())));
}

// Built-in constants users expect to type by name (muparser spells them _pi and _e).
void define_constants(mu::Parser& p) {
    p.DefineConst("pi", std::numbers::pi);
    p.DefineConst("e", std::numbers::e);
}

// The first function that received an argument outside its domain during a checked
// evaluation; thread-local because the callbacks below are plain functions.
thread_local const char* t_domain_error = nullptr;

void note(bool bad, const char* what) {
    if (bad && !t_domain_error) t_domain_error = what;
}
double checked_sqrt(double v) {
    note(v < 0, "sqrt of a negative number");
    return std::sqrt(v);
}
double checked_log(double v) {
    note(v <= 0, "log of a number <= 0");
    return std::log(v);
}
double checked_log2(double v) {
    note(v <= 0, "log2 of a number <= 0");
    return std::log2(v);
}
double checked_log10(double v) {
    note(v <= 0, "log10 of a number <= 0");
    return std::log10(v);
}
double checked_asin(double v) {
    note(std::abs(v) > 1, "asin of a number outside [-1, 1]");
    return std::asin(v);
}
double checked_acos(double v) {
    note(std::abs(v) > 1, "acos of a number outside [-1, 1]");
    return std::acos(v);
}
double checked_acosh(double v) {
    note(v < 1, "acosh of a number < 1");
    return std::acosh(v);
}
double checked_atanh(double v) {
    note(std::abs(v) >= 1, "atanh of a number outside (-1, 1)");
    return std::atanh(v);
}

}  // namespace

FormulaError::FormulaError(int position, const std::string& message)
    : Error(message), m_position(position), m_message(message) {}

// One thread's parser, with its own variable storage bound by address.
class ParserEvaluator final : public Formula::Evaluator {
public:
    ParserEvaluator(const std::string& text, const std::vector<std::string>& names, bool checked) {
        define_constants(m_parser);
        if (checked) {
            m_parser.DefineFun("sqrt", checked_sqrt);
            m_parser.DefineFun("log", checked_log);
            m_parser.DefineFun("ln", checked_log);
            m_parser.DefineFun("log2", checked_log2);
            m_parser.DefineFun("log10", checked_log10);
            m_parser.DefineFun("asin", checked_asin);
            m_parser.DefineFun("acos", checked_acos);
            m_parser.DefineFun("acosh", checked_acosh);
            m_parser.DefineFun("atanh", checked_atanh);
        }
        for (size_t i = 0; i < names.size(); ++i) m_parser.DefineVar(names[i], &m_values[i]);
        m_parser.SetExpr(text);
    }
    double operator()(const Formula::Values& values) override {
        m_values = values;
        try {
            return m_parser.Eval();
        } catch (const mu::Parser::exception_type&) {
            // Validated at construction; a run-time refusal (none known) reads as undefined.
            return std::numeric_limits<double>::quiet_NaN();
        }
    }

private:
    mu::Parser m_parser;
    Formula::Values m_values{};
};

struct Formula::Impl {
    tbb::enumerable_thread_specific<std::unique_ptr<ParserEvaluator>> local;
};

Formula::Formula(std::string text, std::vector<std::string> names, const std::string& variable_hint)
    : m_text(std::move(text)), m_names(std::move(names)) {
    if (m_names.size() > kMaxVariables) throw std::logic_error("Formula: too many variables");
    if (m_text.find_first_not_of(" \t\r\n") == std::string::npos) {
        throw FormulaError(0, "must not be empty");
    }
    if (m_text.size() > kMaxLength) {
        throw FormulaError(0, "is " + std::to_string(m_text.size()) +
                                  " characters long, more than the " + std::to_string(kMaxLength) +
                                  " allowed");
    }
    // muparser's `=` assigns to a variable, which would change the inputs it was given.
    for (size_t i = 0; i < m_text.size(); ++i) {
        if (m_text[i] != '=') continue;
        const char before = i > 0 ? m_text[i - 1] : ' ';
        const char after = i + 1 < m_text.size() ? m_text[i + 1] : ' ';
        if (std::string("<>!=").find(before) == std::string::npos && after != '=') {
            throw FormulaError(
                int(i) + 1,
                describe(int(i) + 1,
                         "'=' assigns; a formula cannot (for a comparison write '==')"));
        }
    }
    // A literal past double's range (1e999) would reach muparser as "1" and a variable "e999".
    for (size_t i = 0; i < m_text.size(); ++i) {
        const auto is_name_char = [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
        };
        const bool starts_number = std::isdigit(static_cast<unsigned char>(m_text[i])) ||
                                   (m_text[i] == '.' && i + 1 < m_text.size() &&
                                    std::isdigit(static_cast<unsigned char>(m_text[i + 1])));
        if (!starts_number || (i > 0 && is_name_char(m_text[i - 1]))) continue;
        const char* begin = m_text.c_str() + i;
        char* end = nullptr;
        const double v = std::strtod(begin, &end);
        if (std::isinf(v)) {
            throw FormulaError(
                int(i) + 1,
                describe(int(i) + 1, "number out of range '" +
                                         std::string(begin, static_cast<size_t>(end - begin)) +
                                         "'"));
        }
        i += static_cast<size_t>(end - begin);
    }
    mu::Parser parser;
    define_constants(parser);
    try {
        parser.SetExpr(m_text);
        // Lists the variables, defined or not, without evaluating.
        for (const auto& [name, address] : parser.GetUsedVar()) m_used.push_back(name);
    } catch (const mu::Parser::exception_type& e) {
        throw syntax_error(e, m_text);
    }
    for (const std::string& name : m_used) {
        if (std::find(m_names.begin(), m_names.end(), name) == m_names.end()) {
            throw FormulaError(0, "unknown variable '" + name + "' " + variable_hint);
        }
    }
    // Compile and run once here, so that every error surfaces now and not on a render thread.
    try {
        Values storage{};
        mu::Parser check;
        define_constants(check);
        for (size_t i = 0; i < m_names.size(); ++i) check.DefineVar(m_names[i], &storage[i]);
        check.SetExpr(m_text);
        (void)check.Eval();
        if (check.GetNumResults() != 1) {
            throw FormulaError(0, "must be one expression, not a list separated by ','");
        }
    } catch (const mu::Parser::exception_type& e) {
        throw syntax_error(e, m_text);
    }
    m_impl = std::make_unique<Impl>();
}

Formula::~Formula() = default;

bool Formula::uses(const std::string& name) const {
    return std::find(m_used.begin(), m_used.end(), name) != m_used.end();
}

Formula::Evaluator& Formula::local() const {
    bool exists = false;
    std::unique_ptr<ParserEvaluator>& e = m_impl->local.local(exists);
    if (!e) e = std::make_unique<ParserEvaluator>(m_text, m_names, false);
    return *e;
}

std::string Formula::why_not_finite(const Values& values) const {
    ParserEvaluator checked(m_text, m_names, true);
    t_domain_error = nullptr;
    const double v = checked(values);
    const char* why = t_domain_error;
    t_domain_error = nullptr;
    if (why) return why;
    if (std::isinf(v)) return "the formula is infinite there (a division by zero?)";
    if (std::isnan(v)) return "the formula gives NaN there";
    return "";
}

UndefinedFormulaError::UndefinedFormulaError(const std::string& owner, const Formula& formula,
                                             const std::string& point,
                                             const std::array<double, 4>& values)
    : Error([&] {
          const std::string why = formula.why_not_finite(values);
          return (owner.empty() ? std::string() : owner + ": ") + "the formula '" + formula.text() +
                 "' is not a number at " + point + (why.empty() ? "" : " (" + why + ")") +
                 ", where a ray met it (the scene reader checks formulas only on a grid of "
                 "sample points, so make it defined everywhere between them)";
      }()) {}

}  // namespace lenslab
