// Typed formulas: muparser's syntax errors with their positions, unknown variables, the
// constructs refused, and evaluation from many threads at once.

#include <gtest/gtest.h>
#include <oneapi/tbb/parallel_for.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "math/formula.h"

namespace lenslab {
namespace {

const std::vector<std::string> kR{"r"};
const std::vector<std::string> kXyz{"x", "y", "z"};

// The message a refused formula gives.
std::string refusal(const std::string& text, const std::vector<std::string>& vars = kR) {
    try {
        Formula f(text, vars, "(use r)");
    } catch (const FormulaError& e) {
        return e.message();
    }
    return "";
}

TEST(Formula, EvaluatesWithConstants) {
    const Formula f("r^2/(2*50)", kR, "(use r)");
    EXPECT_DOUBLE_EQ(f({10.0}), 1.0);
    EXPECT_DOUBLE_EQ(Formula("pi*r", kR, "")({2.0}), 2.0 * std::numbers::pi);
    EXPECT_DOUBLE_EQ(Formula("e", kR, "")({0.0}), std::numbers::e);
    EXPECT_TRUE(f.uses("r"));
    const Formula g("x^2 + y^2 + z^2 - 1", kXyz, "");
    EXPECT_DOUBLE_EQ(g({1.0, 2.0, 3.0}), 13.0);
    EXPECT_FALSE(Formula("x + 1", kXyz, "").uses("y"));
}

// Everything docs/scene-format.md ("Formulas") lists parses.
TEST(Formula, TheDocumentedFunctionsAndOperatorsParse) {
    for (const char* f :
         {"sqrt", "exp",  "ln",   "log",  "log2",  "log10", "sin",   "cos", "tan",  "asin", "acos",
          "atan", "sinh", "cosh", "tanh", "asinh", "acosh", "atanh", "abs", "sign", "rint"}) {
        EXPECT_EQ(refusal(std::string(f) + "(r + 2)"), "") << f;
    }
    for (const char* f : {"min(r, 1, 2)", "max(r, 1)", "sum(r, 1)", "avg(r, 1)", "-r^2 + 1e-3",
                          "(r < 1) && (r >= 0) || (r != 2) ? r : 0", "r == 1"}) {
        EXPECT_EQ(refusal(f), "") << f;
    }
    EXPECT_DOUBLE_EQ(Formula("-r^2", kR, "")({3.0}), -9.0);  // unary minus after ^
}

TEST(Formula, SyntaxErrorsNameThePositionCountingFromOne) {
    // The '*' is the fifth character.
    EXPECT_EQ(refusal("r^2/*2"), "cannot parse at position 5: Unexpected operator \"*\"");
    EXPECT_EQ(refusal("2r"), "cannot parse at position 2: Unexpected variable \"r\"");
    // At the end of the text: just after its last character.
    EXPECT_EQ(refusal("r^2/(2*50"), "cannot parse at position 10: Missing parenthesis");
    EXPECT_EQ(refusal("r +"), "cannot parse at position 4: Unexpected end of expression");
}

TEST(Formula, UnknownVariablesAndRefusedConstructs) {
    EXPECT_EQ(refusal("r^2 + q"), "unknown variable 'q' (use r)");
    EXPECT_EQ(refusal("R^2"), "unknown variable 'R' (use r)");  // names are case-sensitive
    EXPECT_EQ(refusal(""), "must not be empty");
    EXPECT_EQ(refusal("   "), "must not be empty");
    // muparser's '=' would assign to the variable it was given.
    EXPECT_EQ(refusal("r=2").rfind("cannot parse at position 2: '=' assigns", 0), 0u);
    EXPECT_EQ(refusal("r==2"), "");
    EXPECT_EQ(refusal("r<=2"), "");
    EXPECT_EQ(refusal("r, 2"), "must be one expression, not a list separated by ','");
}

TEST(Formula, NumberPastDoublesRangeIsOutOfRangeNotAVariable) {
    // muparser read "1e999" as 1 followed by a variable "e999".
    EXPECT_EQ(refusal("r + 1e999"), "cannot parse at position 5: number out of range '1e999'");
    EXPECT_EQ(refusal("2.5E+400*r"), "cannot parse at position 1: number out of range '2.5E+400'");
    EXPECT_EQ(refusal("r*1e300"), "");
    EXPECT_EQ(refusal("x1e999 + r", {"r", "x1e999"}), "");  // part of a name
}

TEST(Formula, NamesWhyAValueIsNotFinite) {
    const Formula f("10 - sqrt(100 - r^2)", kR, "");
    EXPECT_TRUE(std::isnan(f({11.0})));
    EXPECT_EQ(f.why_not_finite({11.0}), "sqrt of a negative number");
    EXPECT_EQ(f.why_not_finite({5.0}), "");
    EXPECT_EQ(Formula("log(r)", kR, "").why_not_finite({-1.0}), "log of a number <= 0");
    EXPECT_EQ(Formula("asin(r)", kR, "").why_not_finite({2.0}), "asin of a number outside [-1, 1]");
    EXPECT_EQ(Formula("1/r", kR, "").why_not_finite({0.0}),
              "the formula is infinite there (a division by zero?)");
}

// Every thread gets its own parser: evaluating from many threads at once gives exactly the
// serial results (and, under the asan preset, no data race reports).
TEST(Formula, ManyThreadsEvaluateTheSameValues) {
    const Formula f("sin(x) * cos(y) + z^3 - sqrt(abs(x*y*z))", kXyz, "");
    constexpr int n = 200000;
    std::vector<double> serial(n), parallel(n);
    auto point = [](int i) {
        return Formula::Values{i * 1e-3, i * 2e-3 - 50, std::sin(i * 1.0), 0.0};
    };
    for (int i = 0; i < n; ++i) serial[i] = f(point(i));
    tbb::parallel_for(0, n, [&](int i) { parallel[i] = f.local()(point(i)); });
    for (int i = 0; i < n; ++i) ASSERT_EQ(serial[i], parallel[i]) << i;
}

}  // namespace
}  // namespace lenslab
