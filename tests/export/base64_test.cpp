// Base64 (export/base64.h) against RFC 4648's test vectors (section 10), and decoding back
// every byte value.

#include "export/base64.h"

#include <gtest/gtest.h>

#include <string>

namespace systole::exporter {
namespace {

std::string decode(const std::string& text) {
  const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  unsigned bits = 0;
  int count = 0;
  for (char c : text) {
    if (c == '=') break;
    const auto v = alphabet.find(c);
    EXPECT_NE(v, std::string::npos) << "not in the alphabet: " << c;
    bits = (bits << 6) | static_cast<unsigned>(v);
    count += 6;
    if (count >= 8) {
      count -= 8;
      out += static_cast<char>((bits >> count) & 0xff);
    }
  }
  return out;
}

TEST(Base64, MatchesRfc4648sTestVectors) {
  EXPECT_EQ(base64(""), "");
  EXPECT_EQ(base64("f"), "Zg==");
  EXPECT_EQ(base64("fo"), "Zm8=");
  EXPECT_EQ(base64("foo"), "Zm9v");
  EXPECT_EQ(base64("foob"), "Zm9vYg==");
  EXPECT_EQ(base64("fooba"), "Zm9vYmE=");
  EXPECT_EQ(base64("foobar"), "Zm9vYmFy");
}

TEST(Base64, UsesTheStandardAlphabetNotTheUrlSafeOne) {
  EXPECT_EQ(base64(std::string("\xfb\xff", 2)), "+/8=");
  EXPECT_EQ(base64(std::string("\0\0\0", 3)), "AAAA");
}

TEST(Base64, EveryByteValueDecodesBack) {
  std::string bytes;
  for (int i = 0; i < 256; ++i) bytes += static_cast<char>(i);
  for (std::size_t n : {bytes.size(), bytes.size() - 1, bytes.size() - 2}) {
    const std::string input = bytes.substr(0, n);
    const std::string text = base64(input);
    EXPECT_EQ(text.size(), 4 * ((n + 2) / 3));  // Padded to whole quads.
    EXPECT_EQ(decode(text), input);
  }
}

}  // namespace
}  // namespace systole::exporter
