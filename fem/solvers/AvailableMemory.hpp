// How much more memory this process can have, so that a run too large for the machine is
// refused with its estimate before it allocates, instead of ending in std::bad_alloc or the
// kernel's out-of-memory killer.
#pragma once

#include <cstddef>
#include <string>

namespace beamrotor {

/// The least of: the system's available memory (MemAvailable), what the address-space and
/// data-size limits (ulimit -v, -d) leave beyond what the process maps now, and what the memory
/// cgroup's limit leaves beyond its usage (v2 memory.max, v1 memory.limit_in_bytes).
std::size_t availableMemoryBytes();

/// "1.2 GB", "350 MB", "12 kB": a size for messages.
std::string memoryText(double bytes);

}  // namespace beamrotor
