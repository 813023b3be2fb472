#include "gdpn/core/child_process.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>

#include "gdpn/core/sanitizers.h"
#include "gdpn/core/text.h"

namespace gdpn::core {
namespace {


/// The bytes of address space this process maps now (/proc/self/statm's first field).
std::size_t mappedBytes() {
  std::size_t pages = 0;
  if (FILE* f = std::fopen("/proc/self/statm", "r")) {
    if (std::fscanf(f, "%zu", &pages) != 1) pages = 0;
    std::fclose(f);
  }
  return pages * static_cast<std::size_t>(::sysconf(_SC_PAGESIZE));
}

/// Writes every byte of `data` to `fd`; false when the pipe is gone.
bool writeAll(int fd, const char* data, std::size_t size) {
  while (size > 0) {
    const ssize_t n = ::write(fd, data, size);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return false;
    data += n;
    size -= static_cast<std::size_t>(n);
  }
  return true;
}

/// The child's side: runs `work` and writes '1' and its output, or '0' and its reason; never
/// returns.
[[noreturn]] void childMain(const ChildWork& work, std::size_t memoryBytes, int fd) {
  // a crash here must end this process and nothing else: no handler of the parent's (a
  // sanitizer's or a fuzzer's) reports it as the parent's own
  for (const int sig : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT, SIGTRAP, SIGSYS}) {
    struct sigaction dfl{};
    dfl.sa_handler = SIG_DFL;
    ::sigaction(sig, &dfl, nullptr);
  }
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (memoryBytes != 0 && !kSanitized) {
    // the cap counts from what the fork already maps (a large process maps gigabytes)
    const std::size_t limit = mappedBytes() + memoryBytes;
    const rlimit cap{limit, limit};
    ::setrlimit(RLIMIT_AS, &cap);
  }
  std::string out, why;
  bool ok = false;
  try {
    ok = work(out, why);
  } catch (const std::exception& e) {
    why = e.what();
  } catch (...) {
    why = "it failed";
  }
  const std::string& payload = ok ? out : why;
  const char tag = ok ? '1' : '0';
  const bool sent = writeAll(fd, &tag, 1) && writeAll(fd, payload.data(), payload.size());
  ::_exit(sent ? 0 : 1);  // no exit handlers: they are the parent's
}

}  // namespace

bool childMemoryCapped() { return !kSanitized; }

ChildEnd runInChild(const ChildWork& work, double timeoutSeconds, std::size_t memoryBytes, std::string& out,
                    std::string& why) {
  int fds[2];
  if (::pipe2(fds, O_CLOEXEC) != 0) {
    why = std::string("could not be started: ") + std::strerror(errno);
    return ChildEnd::lost;
  }
  const pid_t pid = ::fork();
  if (pid < 0) {
    why = std::string("could not be started: ") + std::strerror(errno);
    ::close(fds[0]);
    ::close(fds[1]);
    return ChildEnd::lost;
  }
  if (pid == 0) {
    ::close(fds[0]);
    childMain(work, memoryBytes, fds[1]);
  }
  ::close(fds[1]);
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(timeoutSeconds);
  std::string received;
  bool late = false;
  char buffer[65536];
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(deadline - Clock::now()).count();
    if (left <= 0) {
      late = true;
      break;
    }
    pollfd p{fds[0], POLLIN, 0};
    const int ready = ::poll(&p, 1, static_cast<int>(std::min<long long>(left, 1 << 30)));
    if (ready < 0 && errno == EINTR) continue;
    if (ready == 0) continue;  // the deadline is checked above
    const ssize_t n = ::read(fds[0], buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) break;  // the child closed its end: done or dead
    received.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fds[0]);
  if (late) ::kill(pid, SIGKILL);
  int status = 0;
  pid_t waited;
  do {
    waited = ::waitpid(pid, &status, 0);
  } while (waited < 0 && errno == EINTR);
  if (late) {
    why = "took longer than " + formatDouble(timeoutSeconds) + " s";
    return ChildEnd::lost;
  }
  if (waited == pid && WIFSIGNALED(status)) {
    const int sig = WTERMSIG(status);
    why = "crashed (signal " + std::to_string(sig) + ", " + ::strsignal(sig) + ")";
    return ChildEnd::lost;
  }
  const bool exitedWell = waited != pid || (WIFEXITED(status) && WEXITSTATUS(status) == 0);
  if (received.empty() || !exitedWell) {
    why = waited == pid && WIFEXITED(status) ? "stopped with exit status " + std::to_string(WEXITSTATUS(status))
                                             : "stopped without an answer";
    return ChildEnd::lost;
  }
  const bool ok = received[0] == '1';
  (ok ? out : why).assign(received, 1, std::string::npos);
  if (!ok && why.empty()) why = "it failed";
  return ok ? ChildEnd::done : ChildEnd::failed;
}

}  // namespace gdpn::core
