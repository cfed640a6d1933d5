// The numbers and fields of the lab's reports and the tools' files
// (lab/report/text_format.h): table decimals, CSV numbers and quoting, and
// durations, with what each prints for values that are not finite.

#include "lab/report/text_format.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace mlndt {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

TEST(Fmt, RoundsToTheDecimalsAndDashesWhatIsNotFinite) {
  EXPECT_EQ(Fmt(1.23456, 2), "1.23");
  EXPECT_EQ(Fmt(-0.5, 0), "-0");
  EXPECT_EQ(Fmt(2.0, 3), "2.000");
  EXPECT_EQ(Fmt(kNan, 2), "–");
  EXPECT_EQ(Fmt(-kInf, 1), "–");
}

TEST(Num, KeepsTenSignificantDigitsAndSaysNan) {
  EXPECT_EQ(Num(0.1), "0.1");
  EXPECT_EQ(Num(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(Num(123456789012.0), "1.23456789e+11");
  EXPECT_EQ(Num(kNan), "nan");
  EXPECT_EQ(Num(kInf), "nan");
}

TEST(CsvField, QuotesOnlyWhatNeedsItAndDoublesQuotes) {
  EXPECT_EQ(CsvField("plain"), "plain");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(CsvField(""), "");
}

TEST(FormatDuration, SecondsMinutesAndHours) {
  EXPECT_EQ(FormatDuration(0.0), "0s");
  EXPECT_EQ(FormatDuration(12.4), "12s");
  EXPECT_EQ(FormatDuration(59.6), "1m00s");
  EXPECT_EQ(FormatDuration(65.0), "1m05s");
  EXPECT_EQ(FormatDuration(3720.0), "1h02m");
  EXPECT_EQ(FormatDuration(-1.0), "?");
  EXPECT_EQ(FormatDuration(kNan), "?");
  EXPECT_EQ(FormatDuration(kInf), "?");
}

}  // namespace
}  // namespace mlndt
