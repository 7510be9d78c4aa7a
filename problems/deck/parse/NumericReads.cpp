#include "problems/deck/parse/NumericReads.hpp"

namespace beamrotor {

namespace {

// Per thread: design studies read decks on several threads at once.
thread_local NumericReadLog* current = nullptr;

}  // namespace

NumericReadLog::NumericReadLog() : outer_(current) {
  current = this;
}

NumericReadLog::~NumericReadLog() {
  current = outer_;
  if (!outer_) return;
  outer_->reads_.insert(outer_->reads_.end(), reads_.begin(), reads_.end());
  outer_->texts_.insert(outer_->texts_.end(), texts_.begin(), texts_.end());
  outer_->allowed_.insert(outer_->allowed_.end(), allowed_.begin(), allowed_.end());
}

NumericReadLog* NumericReadLog::open() {
  return current;
}

}  // namespace beamrotor
