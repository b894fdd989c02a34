#pragma once
// The executable's allocator (allocation.cpp): operator new on top of malloc, and its
// settings.

namespace molsurf::cli {

// Large (2 MiB) pages for the allocator's segments when the executable is linked with
// mimalloc; nothing otherwise. Called first thing in main().
void use_large_pages();
// From now on, small pages and freed memory returned to the kernel at once: a smaller
// footprint for a little more time (allocation.cpp). Nothing without mimalloc.
void save_memory();

}  // namespace molsurf::cli
