#pragma once
/// @file active_tape.hpp
/// The calling thread's active tape of a reverse-mode scalar type: operations on the scalars
/// record onto it. Shared by Tape<N> (exact Hessians) and GradientTape (gradients).

namespace sinew::contact {

/// Makes `tape` the calling thread's active TapeT (TapeT::active() returns a thread_local
/// pointer) for the lifetime of the scope, clearing it first; restores the previous one after.
template <class TapeT>
class ActiveTapeScope {
 public:
  explicit ActiveTapeScope(TapeT& tape) : previous_(TapeT::active()) {
    tape.clear();
    TapeT::active() = &tape;
  }
  ~ActiveTapeScope() { TapeT::active() = previous_; }
  ActiveTapeScope(const ActiveTapeScope&) = delete;
  ActiveTapeScope& operator=(const ActiveTapeScope&) = delete;

 private:
  TapeT* previous_;
};

}  // namespace sinew::contact
