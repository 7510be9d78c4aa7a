// Transparent huge pages for the command line's heap. Most Linux systems give huge pages only
// to memory advised for them ("madvise" in /sys/kernel/mm/transparent_hugepage/enabled), and
// glibc's malloc advises its heap only when the tunable glibc.malloc.hugetlb=1 is in the
// environment at start-up (tunables are read by the dynamic loader, before main).
#pragma once

namespace beamrotor::cli {

/// When the kernel gives huge pages on advice and the environment does not yet name
/// glibc.malloc.hugetlb, starts this program again (same pid, arguments and environment, plus
/// that tunable, and OPENBLAS_NUM_THREADS=1 when the environment names no count) and does not
/// return; otherwise, or when that fails, returns and the run goes on as it is.
/// GLIBC_TUNABLES=glibc.malloc.hugetlb=0 keeps the heap on 4 KiB pages (and keeps a tool such
/// as valgrind, which follows no exec by default, attached).
void restartWithHugePages(char** argv);

}  // namespace beamrotor::cli
