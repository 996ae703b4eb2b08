#include "common/json.h"

#include <gtest/gtest.h>

#include <string>

namespace systole {
namespace {

TEST(JsonQuote, PlainTextIsOnlyQuoted) { EXPECT_EQ(json_quote("heart beats"), "\"heart beats\""); }

TEST(JsonQuote, QuotesBackslashesAndWhitespaceAreEscaped) {
  EXPECT_EQ(json_quote("a\"b\\c\nd\re\tf"), "\"a\\\"b\\\\c\\nd\\re\\tf\"");
}

TEST(JsonQuote, OtherControlCharactersBecomeUnicodeEscapes) {
  EXPECT_EQ(json_quote(std::string("x\x01y\x1f", 4)), "\"x\\u0001y\\u001f\"");
  EXPECT_EQ(json_quote(""), "\"\"");
}

TEST(JsonQuote, Utf8PassesThroughUnchanged) { EXPECT_EQ(json_quote("Herz \xe2\x99\xa5"), "\"Herz \xe2\x99\xa5\""); }

}  // namespace
}  // namespace systole
