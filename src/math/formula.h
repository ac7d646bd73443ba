#pragma once
// A formula typed by a user (a lens sag z(r), an implicit solid f(x, y, z)), parsed with
// muparser and evaluated from many render threads at once.
//
// muparser's Parser is not safe for concurrent Eval on one instance: it reads its variables
// through pointers and keeps a stack per instance. So a Formula keeps the validated text and
// hands every thread its own compiled parser (`local()`), created on first use and owned by
// the Formula (tbb::enumerable_thread_specific): no locks, no data races, and the same
// bytecode, hence the same results, on every thread.

#include <array>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "util/error.h"

namespace lenslab {

// Why a formula was refused. `position` counts characters from 1 (0 when the problem has
// no single position), `message` is for people, e.g. `Unexpected operator "*"`.
class FormulaError : public Error {
public:
    FormulaError(int position, const std::string& message);
    int position() const { return m_position; }
    // "cannot parse at position 5: Unexpected operator "*"", or the message alone.
    const std::string& message() const { return m_message; }

private:
    int m_position;
    std::string m_message;
};

class Formula;

// A formula that gave no number (NaN) at a point a ray met while rendering or tracing. The
// scene reader checks formulas only on a grid of sample points, so one may be undefined
// between them; that is an error in the scene, never empty space. Stops the render or trace.
class UndefinedFormulaError : public Error {
public:
    // `owner` names the formula's place in the scene (its JSON path), `point` the
    // coordinates, e.g. "(x, y, z) = (1, 2, 3)".
    UndefinedFormulaError(const std::string& owner, const Formula& formula,
                          const std::string& point, const std::array<double, 4>& values);
};

class Formula {
public:
    // At most this many variables; their values are passed in the order they were declared.
    static constexpr int kMaxVariables = 4;
    // Longest formula text accepted: far beyond any lens or solid, and it keeps a runaway
    // paste from costing every intersection thousands of operations.
    static constexpr size_t kMaxLength = 4096;
    using Values = std::array<double, kMaxVariables>;

    // Parses `text` over the variables `names` (e.g. {"x", "y", "z"}). Besides muparser's
    // functions and operators, the constants `pi` and `e` are known. Throws FormulaError:
    // a syntax error (with muparser's message and position), a variable not in `names`
    // ("unknown variable 'q' " + `variable_hint`), an assignment, a list of expressions, an
    // empty text, or one longer than kMaxLength characters.
    Formula(std::string text, std::vector<std::string> names, const std::string& variable_hint);
    ~Formula();
    Formula(const Formula&) = delete;
    Formula& operator=(const Formula&) = delete;

    const std::string& text() const { return m_text; }
    // True when the formula mentions the variable `name`.
    bool uses(const std::string& name) const;

    // One thread's compiled copy of the formula. Not to be shared between threads.
    class Evaluator {
    public:
        virtual ~Evaluator() = default;
        virtual double operator()(const Values& values) = 0;
    };
    // The calling thread's evaluator. Look it up once per task (an intersection), then call
    // it as often as needed: the lookup costs more than a short formula.
    Evaluator& local() const;
    // Convenience for one-off evaluations (load-time checks, tests).
    double operator()(const Values& values) const { return local()(values); }

    // Evaluated once more with checked functions: the first function that got an argument
    // outside its domain ("sqrt of a negative number", "log of a number <= 0", ...),
    // "division by zero" for an infinite result, or "" when nothing could be named.
    std::string why_not_finite(const Values& values) const;

private:
    struct Impl;
    std::string m_text;
    std::vector<std::string> m_names;
    std::vector<std::string> m_used;
    std::unique_ptr<Impl> m_impl;
};

}  // namespace lenslab
