// Numbers as text (util/format_number.h): format_number's round trip, and printf_text's
// lines of any length (the reports' helpers it replaced cut lines at 64 to 256 characters).

#include <gtest/gtest.h>

#include <cstdlib>
#include <string>

#include "util/format_number.h"

namespace lenslab {
namespace {

TEST(FormatNumber, ReadsBackAsTheSameNumber) {
    EXPECT_EQ(format_number(5), "5");
    EXPECT_EQ(format_number(-0.25), "-0.25");
    EXPECT_EQ(format_number(1e-5), "1e-05");
    const double third = 1.0 / 3.0;
    EXPECT_NEAR(std::strtod(format_number(third).c_str(), nullptr), third, 1e-10);
}

TEST(FormatNumber, PrintfTextFormatsAWholeLineOfAnyLength) {
    EXPECT_EQ(printf_text("%-8s|%6.2f|%d", "EFL", 50.0, 3), "EFL     | 50.00|3");
    EXPECT_EQ(printf_text("no numbers"), "no numbers");
    const std::string wide = printf_text("%300.1f", 2.5);
    ASSERT_EQ(wide.size(), 300u);
    EXPECT_EQ(wide.substr(297), "2.5");
    EXPECT_EQ(printf_text("%s", ""), "");
}

}  // namespace
}  // namespace lenslab
