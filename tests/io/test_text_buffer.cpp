// TextBuffer (src/io/text_buffer.hpp) writes what an ostream writes: the CSV and VTU files it now
// builds must stay byte for byte those of the stream writers they replaced.
#include "stcontact/io/text_buffer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <vector>

namespace {

std::string streamed(double value, int digits) {
  std::ostringstream out;
  out.precision(digits);
  out << value;
  return out.str();
}

TEST(TextBuffer, NumbersAreThoseOfAStreamWithTheSamePrecision) {
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> values{0.0, -0.0, 1.0, -1.0, 0.1, 1.0 / 3.0, 1e-5, 1e-4, 123456789012.0, 1234567890123.0,
                             1e100, -2.5e-300, std::numeric_limits<double>::denorm_min(),
                             std::numeric_limits<double>::max(), inf, -inf, std::nan("")};
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-30.0, 30.0), sign(-1.0, 1.0);
  for (int i = 0; i < 2000; ++i) values.push_back(sign(random) * std::pow(10.0, exponent(random)));
  for (int digits : {10, 12, 17})
    for (double v : values) {
      stc::TextBuffer text;
      text.number(v, digits);
      EXPECT_EQ(text.str(), streamed(v, digits)) << v << " at " << digits << " digits";
    }
}

TEST(TextBuffer, IntegersTextAndFlush) {
  stc::TextBuffer text;
  text.integer(-42).put(',').integer(0).text(",x,").integer(9007199254740993LL);
  EXPECT_EQ(text.str(), "-42,0,x,9007199254740993");
  std::ostringstream out;
  text.flushTo(out);
  text.integer(1);
  text.flushTo(out);
  EXPECT_EQ(out.str(), "-42,0,x,90071992547409931");
  EXPECT_EQ(text.size(), 0u);
}

}  // namespace
