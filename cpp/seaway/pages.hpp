// Zero-filled memory for search labels, mapped lazily, and how it is given back. Two builds:
// * Linux (the default there): anonymous mmap, transparent huge pages declined (one touched
//   pixel would map 2 MiB), pages given back with madvise(MADV_DONTNEED), after which Linux reads
//   private anonymous pages back as zeros.
// * Portable (every other system, or -DSEAWAY_PORTABLE_PAGES=ON, which CI builds and tests):
//   calloc, and giving back frees the block and takes a new zeroed one. Only the C library is
//   used; the allocator decides when memory returns to the system (large blocks are usually
//   mapped on their own and unmapped on free).
// Either way a block reads as zeros until written, and zero() after give_back() holds.
#pragma once

#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__) && !defined(SEAWAY_PORTABLE_PAGES)
#include <sys/mman.h>
#define SEAWAY_LINUX_PAGES 1
#endif

namespace seaway::pages {

// The build's page strategy, for the capabilities the package reports.
#ifdef SEAWAY_LINUX_PAGES
inline constexpr const char* strategy = "linux-madvise";
#else
inline constexpr const char* strategy = "portable-calloc";
#endif

// `bytes` of zeroed memory (at least 1), mapped on first write where the system does so.
inline void* take(std::size_t bytes) {
  if (bytes == 0) bytes = 1;
#ifdef SEAWAY_LINUX_PAGES
  void* p = mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
  if (p == MAP_FAILED) throw std::bad_alloc();
#ifdef MADV_NOHUGEPAGE
  madvise(p, bytes, MADV_NOHUGEPAGE);
#endif
  return p;
#else
  void* p = std::calloc(bytes, 1);
  if (!p) throw std::bad_alloc();
  return p;
#endif
}

inline void put(void* p, std::size_t bytes) {
  if (bytes == 0) bytes = 1;
#ifdef SEAWAY_LINUX_PAGES
  munmap(p, bytes);
#else
  (void)bytes;
  std::free(p);
#endif
}

// Give the pages back; returns the block to use from now on (zeroed, perhaps at a new address).
inline void* give_back(void* p, std::size_t bytes) {
#ifdef SEAWAY_LINUX_PAGES
  madvise(p, bytes ? bytes : 1, MADV_DONTNEED);
  return p;
#else
  put(p, bytes);
  return take(bytes);
#endif
}

// Ask for huge pages on [p, p + bytes) before the first write (a hint; nothing elsewhere).
inline void prefer_huge(void* p, std::size_t bytes) {
#if defined(SEAWAY_LINUX_PAGES) && defined(MADV_HUGEPAGE)
  madvise(p, bytes, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace seaway::pages
