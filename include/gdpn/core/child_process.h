#pragma once
/// \file
/// Work done in a child process, so that a library that crashes, aborts or hangs on hostile
/// input (Assimp on a malformed mesh) cannot take the calling process with it.

#include <cstddef>
#include <functional>
#include <string>

namespace gdpn::core {

/// What the work in the child does: fills `out` and returns true, or sets `why` and returns
/// false. It runs in a fork of the calling process: it sees the caller's memory as it was at the
/// call, and nothing it changes there comes back but `out` and `why`.
using ChildWork = std::function<bool(std::string& out, std::string& why)>;

/// How a child's work ended.
enum class ChildEnd {
  done,    ///< the work returned true: its output came back
  failed,  ///< the work returned false or threw: its reason came back
  lost,    ///< the child crashed, ran past its time, stopped without a word, or never started
};

/// False in sanitizer builds, where runInChild caps no memory.
bool childMemoryCapped();

/// Runs `work` in a child process and waits for it at most `timeoutSeconds` (s); when
/// `memoryBytes` is not 0 the child may map that many bytes more than the fork already maps (not
/// capped in sanitizer builds, whose shadow memory needs more), so that an allocation past it
/// fails. On `done`, `out` holds
/// the work's output; on `failed`, `why` its reason (or an exception's text); on `lost`, `why`
/// says what became of the child, to follow its name: "crashed (signal 11, Segmentation
/// fault)", "took longer than 10 s" (it is killed), "stopped with exit status 3", "could not be
/// started: ...". The child's crash handlers are reset, so a crash there ends only the child;
/// it dies with the caller too.
ChildEnd runInChild(const ChildWork& work, double timeoutSeconds, std::size_t memoryBytes, std::string& out,
                    std::string& why);

}  // namespace gdpn::core
