// Fills an output directory so that it appears complete or not at all, and never deletes what
// beamrotor did not write:
// - everything is written into a temporary sibling (DIR.tmp-XXXXXX), which takes DIR's place
//   in one step (renameat2 RENAME_EXCHANGE) only once it is finished: a reader sees the old
//   results or the new ones, never neither;
// - every results directory holds a marker file, .beamrotor, listing what beamrotor wrote
//   there; an existing DIR is replaced only when it is empty or its marker lists everything
//   in it, and of the old directory only the listed files are removed;
// - an interrupted write (SIGINT, SIGTERM, SIGHUP) removes its temporary directory before
//   the process ends, and temporary directories left by a run that was killed outright are
//   swept by the next run writing next to them.
#pragma once

#include <filesystem>
#include <functional>

namespace beamrotor {

/// The marker file in every results directory: a comment line, then the relative path of each
/// file and directory beamrotor wrote (directories end in '/').
inline constexpr const char* kMarkerFile = ".beamrotor";

/// Calls fill(temporary directory), then puts the result in `dir`'s place and removes the
/// earlier `dir`. If fill throws (or an Interrupted arrives), the temporary directory is
/// removed, an earlier `dir` is left as it was, and the exception propagates.
///
/// An existing `dir` that is not a directory, not empty and has no marker, or holds anything
/// its marker does not list (a deck, notes, an older beamrotor's results), is refused with
/// std::runtime_error before fill runs, naming what is in the way and how to choose another
/// directory. `dir` must name a directory (not "", "." or ".."); std::invalid_argument
/// otherwise.
void writeDirectoryAtomically(const std::filesystem::path& dir,
                              const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace beamrotor
