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
//   swept by the next run writing next to them; except one whose writer said it holds work
//   worth resuming (a design study's rows), which the next run keeps and names instead.
#pragma once

#include <filesystem>
#include <functional>
#include <string>

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
///
/// `resumable`, when not empty, says what the temporary directory holds that is worth keeping
/// should the process be killed before it finishes (e.g. "the rows of an unfinished design
/// study; ..."): a later run writing `dir` then keeps that directory and prints its name and
/// this text, instead of sweeping it. Such a fill stops early by itself when a signal arrives
/// (Interruption.hpp) and what it wrote is put in place.
void writeDirectoryAtomically(const std::filesystem::path& dir,
                              const std::function<void(const std::filesystem::path&)>& fill,
                              const std::string& resumable = {});

/// The temporary directory (DIR.tmp-XXXXXX) of a run that was killed before it finished,
/// taken over by a run that carries its content on: its marker is locked, so no sweep removes
/// it and no second run takes it over meanwhile.
class UnfinishedDirectory {
 public:
  /// Throws std::runtime_error when `dir` is not such a directory, or a live run writes it.
  explicit UnfinishedDirectory(const std::filesystem::path& dir);
  ~UnfinishedDirectory();
  UnfinishedDirectory(const UnfinishedDirectory&) = delete;
  UnfinishedDirectory& operator=(const UnfinishedDirectory&) = delete;
  /// The results directory it was being written for (DIR).
  std::filesystem::path destination() const;
  /// Removes it, once what it held is in place elsewhere.
  void remove();

 private:
  std::filesystem::path dir_;
  int fd_ = -1;
};

/// Whether `dir` is a temporary directory beamrotor was writing (its marker says so).
bool isUnfinishedDirectory(const std::filesystem::path& dir);

}  // namespace beamrotor
