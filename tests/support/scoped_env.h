#pragma once
// Test support: an environment variable set (or unset) for as long as an object lives, for
// the code that reads the user's folders ($XDG_DATA_HOME, $HOME) and the programs a test
// starts, which inherit it.

#include <cstdlib>
#include <optional>
#include <string>

namespace gdpn::testing {

/// Environment variable `name` set to a value (unset for nullopt) while it lives, then put back.
class ScopedEnv {
 public:
  /// Sets `name` to `value`, or unsets it when `value` is nullopt.
  ScopedEnv(const char* name, const std::optional<std::string>& value) : name_(name) {
    if (const char* old = std::getenv(name)) old_ = old;
    if (value) ::setenv(name, value->c_str(), 1);
    else ::unsetenv(name);
  }
  ~ScopedEnv() {
    if (old_) ::setenv(name_.c_str(), old_->c_str(), 1);
    else ::unsetenv(name_.c_str());
  }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  std::string name_;
  std::optional<std::string> old_;
};

}  // namespace gdpn::testing
