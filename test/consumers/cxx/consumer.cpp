// A C++17 program using mcspec through find_package(mcspec) and the
// imported target mcspec::mcspec (test/consumers/run.sh builds it against
// the installed package only). Exit status 0 when mcspec_checks.h holds and
// the capacities the package passed and the DFT back end are the ones expected.
#include <array>
#include <cstdio>
#include <string_view>

#include "../mcspec_checks.h"

int main()
{
    int bad = mcspec_checks();
    static_assert(MCS_MAX_N == EXPECT_MAX_N, "mcspec::mcspec passed another MCS_MAX_N");
    static_assert(MCS_MAX_SIDE == EXPECT_MAX_SIDE, "mcspec::mcspec passed another MCS_MAX_SIDE");
    constexpr std::string_view header_version{MCS_VERSION_STRING};
    const std::array<int, 3> parts{MCS_VERSION_MAJOR, MCS_VERSION_MINOR, MCS_VERSION_PATCH};
    if (header_version.empty() || parts[0] < 0) {
        std::puts("FAIL version macros");
        ++bad;
    }
    return bad == 0 ? 0 : 1;
}
