#pragma once
/// \file
/// The kernel's interface to scripts (semantics §3-§6, §8). The net knows nothing of Python:
/// the script layer implements these hooks, and the kernel calls them only for constructs
/// the frozen net marks as scripted, in the order the step prescribes.

#include "gdpn/net/net.h"

namespace gdpn::net {

/// Script hooks, called by the kernel. A hook that fails records its error and makes
/// halted() true; the kernel then calls no more hooks, and its owner stops the run at the end
/// of the phase. Every hook but guard() and eligible() may re-enter the kernel through
/// Kernel::setMarking(), addNode() and dropNodes() (never a phase): the kernel calls hooks
/// only between complete changes of its state.
class ScriptHooks {
 public:
  virtual ~ScriptHooks() = default;
  /// The guard of `t` (only for transitions that have one): may `t` start now?
  virtual bool guard(TransitionId t) = 0;
  /// The predicate of term `term` on node token `token`: is the token eligible?
  virtual bool eligible(TermId term, NodeRef token) = 0;
  /// `t` has started: its tokens are taken and its outputs reserved.
  virtual void preFire(TransitionId t) = 0;
  /// `t` is occurring, in the step at the end of which it is `elapsed` steps old.
  virtual void inFire(TransitionId t) = 0;
  /// `t` completes: it still holds its tokens.
  virtual void postFire(TransitionId t) = 0;
  /// A token arrived on place slot `ps` (`token` is null for a control token).
  virtual void onDeposit(PlaceSlotId ps, const NodeRef* token) = 0;
  /// A token left place slot `ps` (`token` is null for a control token).
  virtual void onRemove(PlaceSlotId ps, const NodeRef* token) = 0;
  /// True once a script failed or asked the run to stop: no more hooks are called.
  [[nodiscard]] virtual bool halted() const = 0;
};

}  // namespace gdpn::net
