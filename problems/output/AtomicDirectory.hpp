// Fills an output directory so that it appears complete or not at all: everything is written
// into a temporary sibling (DIR.tmp-XXXXXX), which replaces DIR only once it is finished.
#pragma once

#include <filesystem>
#include <functional>

namespace beamrotor {

/// Calls fill(temporary directory), then removes an earlier `dir` and renames the temporary
/// one to `dir`. If fill (or the swap) throws, the temporary directory is removed, an earlier
/// `dir` is left as it was, and the exception propagates.
///
/// To keep a typing slip from deleting someone's files, an existing `dir` is replaced only
/// when it looks like beamrotor output (it holds results.json or sweep.json) or is empty;
/// otherwise std::runtime_error is thrown before fill runs. `dir` must name a directory
/// (not "", "." or "..").
void writeDirectoryAtomically(const std::filesystem::path& dir,
                              const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace beamrotor
