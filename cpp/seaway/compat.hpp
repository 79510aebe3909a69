// The few compiler-specific things the engine uses, in one place: forced inlining, counting
// leading zeros, a prefetch hint, and relaxed atomic loads and stores on plain memory (the lazy
// labels another thread reads while their owner writes them). GCC and Clang (Linux, macOS,
// MinGW) use their builtins; MSVC its intrinsics (written for it, not built by CI here).
#pragma once

#include <cstdint>

#if defined(_MSC_VER) && !defined(__clang__)
#include <intrin.h>
#define SEAWAY_ALWAYS_INLINE __forceinline
#define SEAWAY_RESTRICT __restrict
namespace seaway::compat {
inline int clz64(std::uint64_t x) {  // x != 0
  unsigned long i;
  _BitScanReverse64(&i, x);
  return 63 - int(i);
}
inline void prefetch(const void* p) { _mm_prefetch(static_cast<const char*>(p), _MM_HINT_T0); }
// Aligned loads and stores of up to 8 bytes are single moves on x64 and arm64 (relaxed order).
template <class T>
T load_relaxed(const T* p) {
  return *static_cast<const volatile T*>(p);
}
template <class T>
void store_relaxed(T* p, T v) {
  *static_cast<volatile T*>(p) = v;
}
}  // namespace seaway::compat
#else
#define SEAWAY_ALWAYS_INLINE __attribute__((always_inline))
#define SEAWAY_RESTRICT __restrict
namespace seaway::compat {
inline int clz64(std::uint64_t x) { return __builtin_clzll(x); }  // x != 0
inline void prefetch(const void* p) { __builtin_prefetch(p); }
template <class T>
T load_relaxed(const T* p) {
  return __atomic_load_n(p, __ATOMIC_RELAXED);
}
template <class T>
void store_relaxed(T* p, T v) {
  __atomic_store_n(p, v, __ATOMIC_RELAXED);
}
}  // namespace seaway::compat
#endif
