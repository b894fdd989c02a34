// operator new and delete for the molsurf executable: on top of malloc, throwing
// std::bad_alloc when memory runs out.
//
// Why: the executable is linked with mimalloc (CMakeLists.txt), whose own operator new,
// built as C, calls abort() when an allocation fails, so a run that exhausts memory died
// with SIGABRT and no message. Its malloc returns null like any malloc; these
// replacements (which take precedence over the shared library's) turn null into
// std::bad_alloc, which main() reports as "out of memory" in one line. Speed is
// unchanged: malloc is still mimalloc's. Sanitizer builds keep their own allocator.
//
// use_large_pages(): mimalloc then asks the kernel for 2 MiB pages (transparent huge
// pages, through madvise) for the segments it maps from then on. A surface run touches
// most of its memory once, and on virtual machines a 4 KiB page fault is expensive: on
// 2hhb the process takes 24 000 minor faults instead of 56 000, for 30 MB more resident
// memory (docs/performance.md). Set before mimalloc starts (MIMALLOC_LARGE_OS_PAGES=1 in
// the environment) it covers every segment: 7 000 faults.
//
// save_memory(): for a job that may fill a large share of the machine. mimalloc keeps
// the pages a stage frees for 100 ms (and a 2 MiB page whole while any of it is used), so
// each stage's peak stacked on what the stages before it had freed: 2btv at probe 0,
// density 4 peaked at 5.2 GB in the cleanup, 3.9 GB with freed pages returned at once
// and small pages. A small job would pay for that in page faults (2hhb: 5 % slower).
#include "cli/allocation.hpp"

#if defined(MOLSURF_HAVE_MIMALLOC)
#include <mimalloc.h>
#endif

namespace molsurf::cli {

void use_large_pages() {
#if defined(MOLSURF_HAVE_MIMALLOC)
  mi_option_enable(mi_option_large_os_pages);
#endif
}

void save_memory() {
#if defined(MOLSURF_HAVE_MIMALLOC)
  mi_option_disable(mi_option_large_os_pages);
  mi_option_set(mi_option_decommit_delay, 0);
#endif
}

}  // namespace molsurf::cli

#if !defined(__SANITIZE_ADDRESS__)
#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MOLSURF_KEEP_SANITIZER_NEW 1
#endif
#endif
#else
#define MOLSURF_KEEP_SANITIZER_NEW 1
#endif

#if !defined(MOLSURF_KEEP_SANITIZER_NEW)
#include <cstdlib>
#include <new>

namespace {

void* allocate(std::size_t size) {
  if (size == 0) size = 1;
  while (true) {
    if (void* p = std::malloc(size)) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

void* allocate_aligned(std::size_t size, std::align_val_t alignment) {
  const std::size_t align = static_cast<std::size_t>(alignment);
  const std::size_t rounded = (size + align - 1) / align * align;  // aligned_alloc wants a multiple
  while (true) {
    if (void* p = std::aligned_alloc(align, rounded == 0 ? align : rounded)) return p;
    std::new_handler handler = std::get_new_handler();
    if (!handler) throw std::bad_alloc();
    handler();
  }
}

}  // namespace

void* operator new(std::size_t size) { return allocate(size); }
void* operator new[](std::size_t size) { return allocate(size); }
void* operator new(std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size == 0 ? 1 : size); }
void* operator new[](std::size_t size, const std::nothrow_t&) noexcept { return std::malloc(size == 0 ? 1 : size); }
void* operator new(std::size_t size, std::align_val_t alignment) { return allocate_aligned(size, alignment); }
void* operator new[](std::size_t size, std::align_val_t alignment) { return allocate_aligned(size, alignment); }
void* operator new(std::size_t size, std::align_val_t alignment, const std::nothrow_t&) noexcept {
  try {
    return allocate_aligned(size, alignment);
  } catch (...) {
    return nullptr;
  }
}
void* operator new[](std::size_t size, std::align_val_t alignment, const std::nothrow_t& tag) noexcept {
  return operator new(size, alignment, tag);
}

void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
#endif
