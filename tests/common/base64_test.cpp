// Base64 (common/base64.h) against RFC 4648's test vectors (section 10), decoding back every
// byte value, and the decoder's refusals.

#include "common/base64.h"

#include <gtest/gtest.h>

#include <string>

namespace systole {
namespace {

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
    EXPECT_EQ(base64_decode(text), input);
  }
}

TEST(Base64, DecodesRfc4648sTestVectors) {
  for (const char* plain : {"", "f", "fo", "foo", "foob", "fooba", "foobar"}) {
    EXPECT_EQ(base64_decode(base64(plain)), std::string(plain)) << plain;
  }
  EXPECT_EQ(base64_decode("Zm9vYmE="), std::string("fooba"));
}

TEST(Base64, DecodingSkipsWhitespaceAndJoinsStreams) {
  EXPECT_EQ(base64_decode("  Zm9v\n  YmFy\r\n"), std::string("foobar"));
  // VTK may encode an array's 4-byte header as its own padded stream before the data.
  EXPECT_EQ(base64_decode(base64("abcd") + base64("xyz")), std::string("abcdxyz"));
}

TEST(Base64, DecodingRefusesWhatIsNotBase64) {
  EXPECT_EQ(base64_decode("Zm9"), std::nullopt) << "a group cut short";
  EXPECT_EQ(base64_decode("Zm*v"), std::nullopt) << "outside the alphabet";
  EXPECT_EQ(base64_decode("Z=9v"), std::nullopt) << "'=' inside a group";
  EXPECT_EQ(base64_decode("Z==="), std::nullopt) << "three '=' leave no whole byte";
  EXPECT_EQ(base64_decode("Zm-_"), std::nullopt) << "the URL-safe alphabet is not ours";
}

}  // namespace
}  // namespace systole
