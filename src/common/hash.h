#pragma once
// FNV-1a, 64 bits (Fowler, Noll, Vo): a tiny, stable, byte-order-free hash for content
// identity (has this scene changed?) and integrity (is this bake file whole?). Not
// cryptographic: it guards against accidents, not attackers.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace systole {

class Fnv1a64 {
 public:
  void update(const void* data, std::size_t bytes) {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i) {
      state_ ^= p[i];
      state_ *= 0x100000001b3ULL;  // The 64-bit FNV prime.
    }
  }
  void update(std::string_view text) { update(text.data(), text.size()); }
  std::uint64_t value() const { return state_; }

 private:
  std::uint64_t state_ = 0xcbf29ce484222325ULL;  // The 64-bit FNV offset basis.
};

/// 16 lower-case hex digits.
inline std::string to_hex(std::uint64_t value) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value));
  return text;
}

}  // namespace systole
