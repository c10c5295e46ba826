// tire::parse_double reads what std::from_chars reads (it stands in for it where libc++ has no
// floating-point from_chars: the browser build) and refuses what it refuses.
#include <catch2/catch.hpp>
#include <charconv>
#include <cmath>
#include <string>

#include "tire/math/numbers.h"

TEST_CASE("parse_double reads and refuses what std::from_chars does", "[parse]") {
  for (const std::string text : {"0",
                                 "-0",
                                 "1",
                                 "-2.5",
                                 "1e3",
                                 "1E-3",
                                 ".5",
                                 "5.",
                                 "0.1",
                                 "123456789.123456789",
                                 "4.9406564584124654e-324",
                                 "1.7976931348623157e308",
                                 "inf",
                                 "-inf",
                                 "nan",
                                 "",
                                 "+1",
                                 " 1",
                                 "1 ",
                                 "0x10",
                                 "-0x1p3",
                                 "1e",
                                 "e5",
                                 "--1",
                                 "-+1",
                                 "abc",
                                 "1e999",
                                 "1.5.2",
                                 "1,5"}) {
    INFO("\"" << text << "\"");
    double want = 0.0;
    const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), want);
    const bool ok = ec == std::errc{} && end == text.data() + text.size() && !text.empty();
    const std::optional<double> got = tire::parse_double(text);
    REQUIRE(got.has_value() == ok);
    if (ok && !std::isnan(want)) CHECK(*got == want);
    if (ok && std::isnan(want)) CHECK(std::isnan(*got));
  }
}
