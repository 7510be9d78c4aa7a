#include "fem/solvers/HeapReserve.hpp"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>

namespace beamrotor {

namespace {

#ifdef MADV_POPULATE_WRITE
constexpr int kPopulateWrite = MADV_POPULATE_WRITE;
#else
constexpr int kPopulateWrite = 23;  // Linux 5.14; older kernels reject it (EINVAL): no-op
#endif

std::size_t populated = 0;  // what an earlier prefaultHeap made ready

}  // namespace

void keepFreedMemory() {
  mallopt(M_MMAP_MAX, 0);         // no separate mappings: everything reusable
  mallopt(M_TRIM_THRESHOLD, -1);  // never trim: freed heap stays for reuse
  mallopt(M_TOP_PAD, 64 << 20);   // grow the heap in large steps
}

void prefaultHeap(std::size_t bytes) {
  constexpr std::size_t kWorthIt = std::size_t(64) << 20;
  if (bytes < kWorthIt || bytes <= populated) return;
  char* block = static_cast<char*>(std::malloc(bytes));
  if (!block) return;
  constexpr std::uintptr_t page = 4096;
  const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(block) + page - 1) & ~(page - 1);
  const std::uintptr_t last = (reinterpret_cast<std::uintptr_t>(block) + bytes) & ~(page - 1);
  if (last > first && madvise(reinterpret_cast<void*>(first), last - first, kPopulateWrite) == 0)
    populated = bytes;
  std::free(block);  // back to the heap, populated, for the solve to reuse
}

std::size_t estimatedStaticBytes(long long elements, int dofsPerNode) {
  // Memory per element grows with the square of the dofs a node carries (matrix entries).
  const double perElement = 600.0 * dofsPerNode * dofsPerNode / 9.0;
  return std::size_t(perElement * double(elements));
}

}  // namespace beamrotor
