// exact/cdref/exact/gmp_pool.hpp - a per-thread cache of GMP's small blocks.
//
// The exact paths (CGAL::Gmpq, MPFR) allocate and free a limb array on nearly every operation,
// and glibc's malloc and free then take about a fifth of a campaign's time (the main job,
// `perf` on these machines). use_gmp_pool() hands GMP (and MPFR, which allocates through
// GMP's functions) a cache in front of malloc: each thread keeps up to `cap` freed blocks of
// each size 8, 16, ..., 256 bytes and gives them back for a request of exactly that size.
//
// Why it is safe whenever it is installed, before or after objects already exist:
//  - every cached block was obtained from malloc with at least its size: a block freed through
//    the cache enters the list of exactly the size GMP states on free (GMP passes the size it
//    asked for), and a list hands a block out only for a request of that same size. A block
//    GMP allocated with plain malloc before the cache was installed is therefore no smaller
//    than any request it later serves;
//  - sizes that are not a multiple of 8 or exceed 256 go to malloc, realloc and free;
//  - every block is a malloc'd pointer, so code that frees a GMP string with std::free stays
//    correct;
//  - a thread's lists are freed when the thread ends; after that, that thread's frees go to
//    free (a trivially destructible flag says so), so objects destroyed at exit are safe.
// Nothing else changes: the numbers computed are the same bits.
#pragma once

#include <gmp.h>

#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cdref::exact {

namespace gmp_pool_detail {

inline constexpr std::size_t classes = 32;  // 8, 16, ..., 256 bytes
inline constexpr int cap = 512;             // blocks kept a size, a thread

struct Node {
  Node* next;
};
struct Lists {
  Node* head[classes] = {};
  int count[classes] = {};
  ~Lists();
};
// set when the thread's lists have been destroyed (trivially destructible: still readable then)
inline thread_local bool lists_gone = false;
inline Lists& lists() {
  thread_local Lists l;
  return l;
}
inline Lists::~Lists() {
  lists_gone = true;
  for (std::size_t c = 0; c < classes; ++c)
    while (head[c]) {
      Node* n = head[c];
      head[c] = n->next;
      std::free(n);
    }
}
// the class of an exact size, or -1 when the size is not cached
inline int class_of(std::size_t size) {
  if (size == 0 || size > classes * 8 || size % 8 != 0) return -1;
  return int(size / 8 - 1);
}
// out of memory: GMP's own functions end the process here too (it cannot take an exception)
inline void* checked(void* p) {
  if (!p) {
    std::fputs("cdref: GMP could not allocate memory\n", stderr);
    std::abort();
  }
  return p;
}
inline void* allocate(std::size_t size) {
  const int c = class_of(size);
  if (c >= 0 && !lists_gone) {
    Lists& l = lists();
    if (Node* n = l.head[c]) {
      l.head[c] = n->next;
      --l.count[c];
      return n;
    }
  }
  return checked(std::malloc(size));
}
inline void release(void* p, std::size_t size) {
  if (!p) return;
  const int c = class_of(size);
  if (c >= 0 && !lists_gone) {
    Lists& l = lists();
    if (l.count[c] < cap) {
      Node* n = static_cast<Node*>(p);
      n->next = l.head[c];
      l.head[c] = n;
      ++l.count[c];
      return;
    }
  }
  std::free(p);
}
inline void* reallocate(void* p, std::size_t old_size, std::size_t new_size) {
  if (!p) return allocate(new_size);
  if (old_size == new_size) return p;
  if (class_of(old_size) < 0 && class_of(new_size) < 0) return checked(std::realloc(p, new_size));
  void* q = allocate(new_size);
  std::memcpy(q, p, old_size < new_size ? old_size : new_size);
  release(p, old_size);
  return q;
}

}  // namespace gmp_pool_detail

// Installs the cache as GMP's memory functions (for every thread; each has its own lists).
// Call it once, early in main; calling it again changes nothing.
inline void use_gmp_pool() {
  mp_set_memory_functions(gmp_pool_detail::allocate, gmp_pool_detail::reallocate, gmp_pool_detail::release);
}

}  // namespace cdref::exact
