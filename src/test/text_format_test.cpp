#include "ppp_core/text_format.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace ppp {
namespace {

/// printf's output, for comparison (tests run in the C locale).
std::string printed(const char* format, int precision, double value) {
  std::vector<char> buffer(512);
  std::snprintf(buffer.data(), buffer.size(), format, precision, value);
  return buffer.data();
}

const double kValues[] = {0.0, 0.5, 2.46, 12.0, -3.14159, 1e-7, 0.0625, 123456789.123, -1e20, 1e300};

TEST(TextFormatTest, FixedAndGeneralPrintAsPrintfDoes) {
  EXPECT_EQ(formatFixed(2.46, 1), "2.5");
  EXPECT_EQ(formatFixed(12, 1), "12.0");
  EXPECT_EQ(formatFixed(-0.004, 2), "-0.00");
  EXPECT_EQ(formatGeneral(0.5625, 6), "0.5625");
  EXPECT_EQ(formatGeneral(1234567, 6), "1.23457e+06");
  EXPECT_EQ(formatGeneral(100, 6), "100");
  for (const double value : kValues) {
    for (const int decimals : {0, 1, 2, 4}) {
      EXPECT_EQ(formatFixed(value, decimals), printed("%.*f", decimals, value)) << value << " " << decimals;
    }
    for (const int digits : {6, 10, 15}) {
      EXPECT_EQ(formatGeneral(value, digits), printed("%.*g", digits, value)) << value << " " << digits;
    }
  }
}

TEST(TextFormatTest, FixedWritesEveryDigitOfLargeNumbers) {
  const std::string text = formatFixed(1e300, 2);
  EXPECT_EQ(text.size(), 304u);  // 301 digits, the point, two decimals
  EXPECT_EQ(text.rfind("1000000000", 0), 0u);
}

TEST(TextFormatTest, ShortestReadsBackExactly) {
  EXPECT_EQ(formatShortest(0.1), "0.1");
  EXPECT_EQ(formatShortest(0.05), "0.05");
  EXPECT_EQ(formatShortest(-2.0), "-2");
  EXPECT_EQ(formatShortest(1e21), "1e+21");
  for (const double value : {1.0 / 3.0, 2.0 / 3.0, 0.1 + 0.2, 6.02214076e23, 5e-324}) {
    const std::string text = formatShortest(value);
    EXPECT_EQ(std::strtod(text.c_str(), nullptr), value) << text;
  }
}

TEST(TextFormatTest, DisplayLengthCountsCharactersNotBytes) {
  EXPECT_EQ(displayLength(""), 0u);
  EXPECT_EQ(displayLength("abc"), 3u);
  EXPECT_EQ(displayLength("a\xC3\xB1" "b"), 3u);     // a, n with tilde, b
  EXPECT_EQ(displayLength("\xE2\x80\xA6"), 1u);       // one ellipsis
  EXPECT_EQ(displayLength("\xF0\x9F\x98\x80!"), 2u);  // a four-byte character and '!'
}

TEST(TextFormatTest, ShortenTextEndsCutTextWithAnEllipsis) {
  EXPECT_EQ(shortenText("abcdef", 6), "abcdef");
  EXPECT_EQ(shortenText("abcdefg", 6), "abcde\xE2\x80\xA6");
  EXPECT_EQ(shortenText("\xC3\xB1\xC3\xB1\xC3\xB1\xC3\xB1", 3), "\xC3\xB1\xC3\xB1\xE2\x80\xA6");
  EXPECT_EQ(shortenText("abc", 1), "\xE2\x80\xA6");
  EXPECT_EQ(shortenText("abc", 0), "");
  EXPECT_EQ(shortenText("", 0), "");
}

TEST(TextFormatTest, EscapeMarkupEscapesTheFiveSpecialCharacters) {
  EXPECT_EQ(escapeMarkup("a<b>&\"c'"), "a&lt;b&gt;&amp;&quot;c&#39;");
  EXPECT_EQ(escapeMarkup("plain"), "plain");
}

TEST(TextFormatTest, Hex64WritesSixteenLowercaseDigits) {
  EXPECT_EQ(formatHex64(0), "0000000000000000");
  EXPECT_EQ(formatHex64(255), "00000000000000ff");
  EXPECT_EQ(formatHex64(0x0123456789abcdefULL), "0123456789abcdef");
  EXPECT_EQ(formatHex64(~0ULL), "ffffffffffffffff");
}

TEST(TextFormatTest, TickStepIsOneTwoOrFiveTimesAPowerOfTen) {
  EXPECT_DOUBLE_EQ(tickStep(100), 20);  // raw step 20
  EXPECT_DOUBLE_EQ(tickStep(30), 5);    // raw 6
  EXPECT_DOUBLE_EQ(tickStep(40), 10);   // raw 8
  EXPECT_DOUBLE_EQ(tickStep(16.5), 2);  // raw 3.3
  EXPECT_DOUBLE_EQ(tickStep(7), 1);     // raw 1.4
  EXPECT_DOUBLE_EQ(tickStep(1), 0.2);   // raw 0.2
}

}  // namespace
}  // namespace ppp
