// The fixed-point helpers every stage uses: defined rounding for negative values.
#include <gtest/gtest.h>

#include "fixed_point.hpp"
#include "span_reciprocal.hpp"

using namespace watkins;

TEST(FixedPoint, FloorShiftRoundsTowardMinusInfinity) {
  EXPECT_EQ(floor_shift(7, 2), 1);
  EXPECT_EQ(floor_shift(-7, 2), -2);
  EXPECT_EQ(floor_shift(-8, 2), -2);
  EXPECT_EQ(floor_shift(-1, 16), -1);
}

TEST(FixedPoint, RoundShiftTiesGoUp) {
  EXPECT_EQ(round_shift(6, 2), 2);    // 1.5 -> 2
  EXPECT_EQ(round_shift(-6, 2), -1);  // -1.5 -> -1 (ties toward +infinity, like add-half-and-shift)
  EXPECT_EQ(round_shift(-7, 2), -2);  // -1.75 -> -2
  EXPECT_EQ(round_shift(5, 2), 1);    // 1.25 -> 1
}

TEST(FixedPoint, RoundDivMatchesRoundShiftOnPowersOfTwo) {
  for (int a = -300; a <= 300; ++a) EXPECT_EQ(round_div(a, 8), round_shift(a, 3)) << a;
  EXPECT_EQ(round_div(10, 3), 3);
  EXPECT_EQ(round_div(-10, 3), -3);
}

TEST(FixedPoint, WrapAndSaturateBehaveLikeRegisters) {
  EXPECT_EQ(wrap_signed(127, 8), 127);
  EXPECT_EQ(wrap_signed(128, 8), -128);
  EXPECT_EQ(wrap_signed(-129, 8), 127);
  EXPECT_EQ(saturate_signed(1000, 8), 127);
  EXPECT_EQ(saturate_signed(-1000, 8), -128);
  EXPECT_TRUE(fits_signed(-128, 8));
  EXPECT_FALSE(fits_signed(128, 8));
  EXPECT_EQ(msb_index(1), 0);
  EXPECT_EQ(msb_index(0x80000000ull), 31);
}

// The span reciprocal's double division gives the integer division's quotient for every
// normalized mantissa of the widths it is used at (the span's 24 bits, eq. (2)'s 16) and at the
// widest width it is taken for (26 bits: 2^25 mantissas).
TEST(FixedPoint, ReciprocalByDoubleDivisionIsTheIntegerQuotient) {
  for (const int r : {16, 24, 26}) {
    const i64 dividend = i64{1} << (2 * r - 1);
    long long wrong = 0;
    for (i64 m = i64{1} << (r - 1); m < (i64{1} << r); ++m)
      wrong += watkins::SpanReciprocal::quotient_via_double(r, m) != dividend / m;
    EXPECT_EQ(wrong, 0) << r << " bits";
  }
}

