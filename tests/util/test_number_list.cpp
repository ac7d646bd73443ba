#include <gtest/gtest.h>

#include <stdexcept>

#include "util/number_list.h"

using lenslab::parse_number_list;

TEST(NumberList, ReadsWhatPeopleType) {
    EXPECT_EQ(parse_number_list("0, 10.5,14"), (std::vector<double>{0, 10.5, 14}));
    EXPECT_EQ(parse_number_list(" 486.1327 , 587.5618 "),
              (std::vector<double>{486.1327, 587.5618}));
    EXPECT_TRUE(parse_number_list("").empty());
    EXPECT_TRUE(parse_number_list("  ").empty());
    EXPECT_EQ(parse_number_list("400:700:10", ':'), (std::vector<double>{400, 700, 10}));
    EXPECT_EQ(parse_number_list("-1e-3"), (std::vector<double>{-1e-3}));
}

TEST(NumberList, NamesThePartThatIsNotANumber) {
    const auto message = [](const std::string& text) {
        try {
            parse_number_list(text);
        } catch (const std::invalid_argument& e) {
            return std::string(e.what());
        }
        return std::string("accepted");
    };
    EXPECT_EQ(message("0, 5x, 10"), "'0, 5x, 10': '5x' is not a number");
    EXPECT_EQ(message("1, nan"), "'1, nan': 'nan' is not a number");  // finite numbers only
    EXPECT_EQ(message("inf"), "'inf': 'inf' is not a number");
    EXPECT_EQ(message("1 2"), "'1 2': '1 2' is not a number");
    EXPECT_EQ(message("1,,2"), "'1,,2': a number is missing (an empty part)");
    EXPECT_EQ(message("0, 5,"), "'0, 5,': a number is missing (an empty part)");
}
