#pragma once
// How the process's heap gives memory back to the system. glibc returns every large block (over
// 128 KiB at first, adapting up to 32 MiB) to the kernel when it is freed, and the next one is faulted in again
// page by page. meshprep frees and reallocates mesh-sized arrays at every stage, and on a
// virtual machine a page fault is expensive: on the 2-core CI VM, `simplify` of bunny00 to 10 %
// faulted 17,137 pages and spent about a fifth of its run doing so (bench/RESULTS.md).

namespace meshprep::cli {

/// Keeps freed memory in the heap for reuse (blocks up to 256 MiB from the heap, not mmap; the
/// top of the heap trimmed only beyond 1 GiB). Peak memory does not change: only what was already
/// used is kept. No effect outside glibc. Called once, from main.
void keep_freed_memory_for_reuse();

}  // namespace meshprep::cli
