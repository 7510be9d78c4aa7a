// BEAMROTOR_THREADS set for a test's scope: passes split into parts (fem/assembly/
// ParallelParts.hpp) compared on one part and on several.
#pragma once

#include <cstdlib>
#include <optional>
#include <string>

namespace beamrotor::test {

/// Sets BEAMROTOR_THREADS for the scope of the object, and puts back what was there.
class ThreadsSetting {
 public:
  explicit ThreadsSetting(const std::string& value) {
    if (const char* old = std::getenv("BEAMROTOR_THREADS")) old_ = old;
    setenv("BEAMROTOR_THREADS", value.c_str(), 1);
  }
  ~ThreadsSetting() {
    if (old_)
      setenv("BEAMROTOR_THREADS", old_->c_str(), 1);
    else
      unsetenv("BEAMROTOR_THREADS");
  }
  ThreadsSetting(const ThreadsSetting&) = delete;
  ThreadsSetting& operator=(const ThreadsSetting&) = delete;

 private:
  std::optional<std::string> old_;
};

}  // namespace beamrotor::test
