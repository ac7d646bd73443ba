// The one memory check every large allocation of a render goes through.

#include <gtest/gtest.h>

#include <cstdint>
#include <regex>
#include <string>

#include "render/memory_budget.h"

namespace lenslab {
namespace {

TEST(MemoryBudget, SomeMemoryIsAvailable) { EXPECT_GT(available_memory_bytes(), uint64_t{0}); }

TEST(MemoryBudget, LetsASmallNeedThrough) {
    EXPECT_NO_THROW(
        check_memory_budget(1024, "image: 16 x 16 needs", "", "render a smaller image"));
}

TEST(MemoryBudget, RefusesWhatCannotFitWithTheCallersWords) {
    try {
        check_memory_budget(uint64_t{1} << 60, "pass_photons: 5 photons per light need up to",
                            " per pass", "use fewer");
        FAIL() << "no error";
    } catch (const ResourceError& e) {
        const std::regex expected(
            "pass_photons: 5 photons per light need up to 1099511627776 MiB per pass, but only "
            "[0-9]+ MiB of "
            "memory is available; use fewer");
        EXPECT_TRUE(std::regex_match(std::string(e.what()), expected)) << e.what();
    }
}

}  // namespace
}  // namespace lenslab
