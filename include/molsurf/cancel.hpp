#pragma once
// Stopping a long call from another thread: the caller owns a flag, passes its address in
// the call's options, and sets it (a Python binding on Ctrl-C, a GUI's stop button). The
// library reads it inside its long parallel loops and between stages, and ends the call
// with Cancelled; nothing the call would have returned is left behind.
#include <atomic>

#include "molsurf/error.hpp"

namespace molsurf {

using CancelFlag = std::atomic<bool>;

class Cancelled : public Error {
 public:
  Cancelled() : Error("cancelled") {}
};

// Whether `flag` (may be null: never) has been set.
inline bool cancel_requested(const CancelFlag* flag) { return flag && flag->load(std::memory_order_relaxed); }

// Throws Cancelled when `flag` has been set.
inline void throw_if_cancelled(const CancelFlag* flag) {
  if (cancel_requested(flag)) throw Cancelled();
}

}  // namespace molsurf
