// Test runner of rrc_demo_tests; `rrc_demo_tests run [demo options]` runs the trivial demo itself
// (for measurements and trying the window by hand).
#include "trivial_demo.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

int main(int argc, char** argv) {
    if (argc > 1 && std::string_view(argv[1]) == "run") return rrc::demo::runDemo(argc - 1, argv + 1, rrc::demo::test::trivialDemo());
    ::unsetenv("MESA_NO_ERROR");   // Mesa must report GL errors to the tests
    ::testing::InitGoogleTest(&argc, argv);
    return RUN_ALL_TESTS();
}
