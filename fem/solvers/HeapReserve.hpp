// Memory for large models, made ready in bulk. On the virtual machines this solver is
// benchmarked on, the first write to each 4 KiB page traps to the hypervisor and costs about
// 30 us (8 s per GB, measured), more than assembling and factorising the data that fills it;
// a batched populate of the same memory costs 0.2 s per GB. So a large solve (1) keeps the
// memory each phase frees for the next instead of returning it to the operating system, and
// (2) populates the heap it is about to need in one call.
#pragma once

#include <cstddef>

namespace beamrotor {

/// Process-wide allocator policy: large blocks come from the heap and freed memory stays
/// there for reuse. Call once at start-up (the command line and the benchmark do).
void keepFreedMemory();

/// Ensures that about `bytes` of heap are backed by memory (one MADV_POPULATE_WRITE), when
/// that is over 64 MiB and more than an earlier call ensured; a no-op where unsupported.
/// Only useful after keepFreedMemory().
void prefaultHeap(std::size_t bytes);

/// Rough peak memory of a linear static solve of a line or frame model with `elements`
/// two-node elements of `dofsPerNode` dofs (model, K, factor, vectors): 600 bytes per planar
/// element (peak RSS of a cold bench run less the process's own 21 MB: 567 and 519 bytes an
/// element at 1e5 and 1e6); 2.4 kB per 3D frame element, where the grid3d bench measures 2.3
/// at 3x10^5 dofs.
std::size_t estimatedStaticBytes(long long elements, int dofsPerNode);

}  // namespace beamrotor
