// The value rules and the one message format, on their own.
#include <catch2/catch.hpp>
#include <cmath>
#include <limits>

#include "flags/flag_values.h"

using namespace raycam::flags;

TEST_CASE("number_in keeps open bounds open and closed bounds closed", "[flags]") {
  const ValueRule<double> res = number_in({0.0, 1.0, true, false});
  CHECK(res.expected == "a number in ]0, 1]");
  CHECK_FALSE(res.parse("0"));
  CHECK_FALSE(res.parse("-0"));
  CHECK(res.parse("1") == 1.0);
  CHECK_FALSE(res.parse("1.0000000000000002"));                               // one ulp above 1
  CHECK(res.parse("4.9e-324") == std::numeric_limits<double>::denorm_min());  // tiny but > 0
  const ValueRule<double> closed = number_in({-1.0, 2.0, false, true});
  CHECK(closed.expected == "a number in [-1, 2[");
  CHECK(closed.parse("-1") == -1.0);
  CHECK_FALSE(closed.parse("2"));
}

TEST_CASE("number_in accepts subnormals and refuses what is not a finite number", "[flags]") {
  const ValueRule<double> angle = number_in({-1e6, 1e6}, "an angle in degrees");
  CHECK(angle.expected == "an angle in degrees in [-1e6, 1e6]");
  const std::optional<double> tiny = angle.parse("2.8e-322");  // strtod says ERANGE: still a fine value
  REQUIRE(tiny);
  CHECK(std::fpclassify(*tiny) == FP_SUBNORMAL);
  CHECK(*tiny == 2.8e-322);
  CHECK(angle.parse("1e-400") == 0.0);  // underflows to 0, which is in range
  for (const char* bad : {"nan", "inf", "-inf", "1e999", "", "12abc", "1,5", "0x", " "})
    CHECK_FALSE(angle.parse(bad));
  CHECK_FALSE(angle.parse("1000000.0001"));
}

TEST_CASE("integer_in takes decimal integers in range only", "[flags]") {
  const ValueRule<int> threads = integer_in(1, 256);
  CHECK(threads.expected == "an integer in [1, 256]");
  CHECK(threads.parse("1") == 1);
  CHECK(threads.parse("256") == 256);
  for (const char* bad : {"0", "257", "x", "", "2.5", "3x", "99999999999999999999"})
    CHECK_FALSE(threads.parse(bad));
}

TEST_CASE("one_of names the accepted values", "[flags]") {
  const ValueRule<int> mode = one_of({"2d", "3d"});
  CHECK(mode.expected == "2d or 3d");
  CHECK(mode.parse("3d") == 1);
  CHECK_FALSE(mode.parse("4d"));
  CHECK(name_list({"a", "b", "c"}) == "a, b or c");
}

TEST_CASE("short numbers are written as a reader would", "[flags]") {
  CHECK(short_number(1e12) == "1e12");
  CHECK(short_number(1e-9) == "1e-9");
  CHECK(short_number(0.5) == "0.5");
  CHECK(short_number(4) == "4");
}

TEST_CASE("checked_value throws the one message format", "[flags]") {
  CHECK(checked_value(integer_in(1, 9), "3", "--repeats") == 3);
  CHECK_THROWS_WITH(checked_value(integer_in(1, 9), "x", "--repeats"),
                    "--repeats: expected an integer in [1, 9], got 'x'");
}
