// FNV-1a, 64 bits (common/hash.h), against the reference values of Fowler, Noll and Vo's
// test suite (draft-eastlake-fnv, "FNV-1a 64-bit" test vectors).

#include "common/hash.h"

#include <gtest/gtest.h>

#include <string>

namespace systole {
namespace {

std::uint64_t fnv(std::string_view text) {
  Fnv1a64 h;
  h.update(text);
  return h.value();
}

TEST(Hash, MatchesTheFnv1a64ReferenceVectors) {
  EXPECT_EQ(fnv(""), 0xcbf29ce484222325ULL);  // The offset basis.
  EXPECT_EQ(fnv("a"), 0xaf63dc4c8601ec8cULL);
  EXPECT_EQ(fnv("foobar"), 0x85944171f73967e8ULL);
}

TEST(Hash, FeedingInPiecesEqualsFeedingAtOnce) {
  const std::string text = "systole: a beating heart, frame by frame";
  for (std::size_t cut = 0; cut <= text.size(); ++cut) {
    Fnv1a64 h;
    h.update(std::string_view(text).substr(0, cut));
    h.update(text.data() + cut, text.size() - cut);
    EXPECT_EQ(h.value(), fnv(text)) << cut;
  }
}

TEST(Hash, EveryByteMatters) {
  // A change of one byte, of its place, or a zero byte more changes the hash.
  EXPECT_NE(fnv("ab"), fnv("ba"));
  EXPECT_NE(fnv("a"), fnv(std::string("a\0", 2)));
  const std::string base(64, 'x');
  for (std::size_t i = 0; i < base.size(); ++i) {
    std::string changed = base;
    changed[i] = 'y';
    EXPECT_NE(fnv(changed), fnv(base)) << i;
  }
}

TEST(Hash, HexIsSixteenLowerCaseDigits) {
  EXPECT_EQ(to_hex(0), "0000000000000000");
  EXPECT_EQ(to_hex(0x1), "0000000000000001");
  EXPECT_EQ(to_hex(0xcbf29ce484222325ULL), "cbf29ce484222325");
  EXPECT_EQ(to_hex(~0ULL), "ffffffffffffffff");
}

}  // namespace
}  // namespace systole
