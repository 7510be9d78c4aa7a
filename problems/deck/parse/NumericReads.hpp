// A record of the numbers a deck's reading read: each field's path, place, text and the unit
// the reader stated for it. The reader's own bookkeeping (which dimension a bare parameter
// flows into, BareParameters.hpp) and the field-walk test read it; nothing is recorded unless
// a log is open on the reading thread.
#pragma once

#include <string>
#include <vector>

#include "problems/deck/parse/DeckError.hpp"
#include "problems/deck/parse/Units.hpp"

namespace beamrotor {

struct NumericRead {
  std::string file;
  DeckPlace place;   ///< the value's line and column; field: its path
  std::string text;  ///< as written
  FieldUnit unit;    ///< as the reader stated it
  double value = 0;  ///< as read, in the unit's bare size
  bool bare = false;  ///< its expression came out dimensionless (no unit, or units cancelling)
};

/// Collects the numeric reads of its thread from construction to destruction; a log opened
/// while another is open takes the reads until it closes, then hands them to the other.
class NumericReadLog {
 public:
  NumericReadLog();
  ~NumericReadLog();
  NumericReadLog(const NumericReadLog&) = delete;
  NumericReadLog& operator=(const NumericReadLog&) = delete;

  const std::vector<NumericRead>& reads() const { return reads_; }
  /// The log open on this thread, or null.
  static NumericReadLog* open();
  void record(NumericRead read) { reads_.push_back(std::move(read)); }

 private:
  NumericReadLog* outer_;
  std::vector<NumericRead> reads_;
};

}  // namespace beamrotor
