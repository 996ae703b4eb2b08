#pragma once
// Gives the heap a history: leaves a chosen byte in its free memory, so the blocks a writer
// (or a library it calls) allocates next start out holding that byte instead of whatever
// happened to be there. Two writes of the same input after two different fills must give
// the same bytes; if they do not, something reads memory nobody wrote. glibc only (mallopt);
// elsewhere, and under a sanitizer's allocator, the fill does nothing and such a test passes.

#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <vector>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace systole::test {

inline void fill_free_heap(unsigned char byte) {
#if defined(__GLIBC__)
  constexpr std::size_t kBlock = std::size_t{1} << 20, kBlocks = 64;  // 64 MB, more than an encoder's frames.
  // Blocks up to 4 MB come from the heap, not from fresh (zeroed) mmap pages, and freed
  // memory stays in the heap rather than being given back (where it would come back zeroed).
  mallopt(M_MMAP_THRESHOLD, 4 << 20);
  mallopt(M_TRIM_THRESHOLD, 512 << 20);
  // Through a volatile pointer: a memset just before free() may otherwise be optimised away.
  void* (*volatile set)(void*, int, std::size_t) = std::memset;
  std::vector<void*> blocks;
  for (std::size_t i = 0; i < kBlocks; ++i) {
    void* p = std::malloc(kBlock);
    if (p == nullptr) break;
    set(p, byte, kBlock);
    blocks.push_back(p);
  }
  for (void* p : blocks) std::free(p);
#else
  (void)byte;
#endif
}

}  // namespace systole::test
