// A record of the numbers a deck's reading read: each field's path, place, text and the unit
// the reader stated for it; and, for the field-walk test, the other fields it read and the
// keys each map allows. The reader's own bookkeeping (which dimension a bare parameter flows
// into, BareParameters.hpp) and the field-walk test read it; nothing is recorded unless a log
// is open on the reading thread.
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

/// A map's allowed keys (Field::allowOnly).
struct AllowedKeys {
  std::string path;  ///< the map's
  std::vector<std::string> keys;
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
  /// The paths of the fields read as text (names, choices, labels, booleans).
  const std::vector<std::string>& textReads() const { return texts_; }
  const std::vector<AllowedKeys>& allowed() const { return allowed_; }
  /// The log open on this thread, or null.
  static NumericReadLog* open();
  void record(NumericRead read) { reads_.push_back(std::move(read)); }
  void recordText(const std::string& path) { texts_.push_back(path); }
  void recordAllowed(AllowedKeys keys) { allowed_.push_back(std::move(keys)); }

 private:
  NumericReadLog* outer_;
  std::vector<NumericRead> reads_;
  std::vector<std::string> texts_;
  std::vector<AllowedKeys> allowed_;
};

}  // namespace beamrotor
