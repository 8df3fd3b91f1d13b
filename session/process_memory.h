#pragma once
// The process's memory as the kernel and the C library see it, for long
// runs (summary.json "process_memory"): resident memory, and how much of
// the heap is in use against what the allocator holds free for reuse.
// Growth of the resident figure with heap_free_mb growing beside it is
// memory freed and kept by malloc for later allocations, not lost.

#include <nlohmann/json.hpp>

namespace ig::session {

// rss_mb, peak_rss_mb (VmRSS, VmHWM of /proc/self/status; absent where
// unreadable), heap_in_use_mb, heap_free_mb, heap_mmapped_mb (mallinfo2,
// every arena).
nlohmann::json process_memory();

// VmRSS alone, in MB (0 where unreadable): cheap enough to read around
// each heap trim, unlike the heap figures (mallinfo2 walks every arena).
double resident_mb();

}  // namespace ig::session
