#pragma once
/// \file heap_policy.h
/// How the process's heap gives memory back to the system. glibc returns every large block (over
/// 128 KiB at first, adapting up to 32 MiB) to the kernel when it is freed, and the next one is
/// faulted in again page by page. meshprep frees and reallocates mesh-sized arrays at every stage,
/// and on a virtual machine a page fault is expensive: on the 2-core CI VM, `simplify` of bunny00
/// to 10 % faulted 17,134 pages before and 10,319 after, 2.23 -> 2.09 s (bench/RESULTS.md).

namespace meshprep {

/// Keeps freed memory in the heap for reuse (blocks up to 256 MiB from the heap, not mmap; the
/// top of the heap trimmed only beyond 1 GiB). Only memory already used is kept, so the peak does
/// not grow (the pipeline on bunny00: 215 MB either way). No effect outside glibc. Called once, by
/// the command line's main and when the Python module is imported (docs/python.md).
void keep_freed_memory_for_reuse();

}  // namespace meshprep
