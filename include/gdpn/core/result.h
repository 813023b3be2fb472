#pragma once
/// \file
/// Result<T>: a value, or the located diagnostic that says why there is none (Jolt's
/// `Result`). New fallible functions return one, marked [[nodiscard]] by the type itself.

#include <optional>
#include <string>
#include <utility>

#include "gdpn/core/assert.h"
#include "gdpn/core/diagnostics.h"

namespace gdpn::core {

/// A value of type T, or the error (a diagnostic with its location) that stopped it.
template <typename T>
class [[nodiscard]] Result {
 public:
  /// A result holding `value`.
  Result(T value) : value_(std::move(value)) {}  // NOLINT(google-explicit-constructor): returned as is
  /// A result holding no value and the error `error` (its severity is made Error).
  Result(Diagnostic error) : error_(std::move(error)) {  // NOLINT(google-explicit-constructor)
    error_.severity = Severity::Error;
  }
  /// A result holding no value: `message` at `loc`.
  [[nodiscard]] static Result failure(SourceLoc loc, std::string message) {
    return Result(Diagnostic{Severity::Error, std::move(loc), std::move(message)});
  }

  /// True when it holds a value.
  [[nodiscard]] bool ok() const { return value_.has_value(); }
  /// True when it holds a value.
  explicit operator bool() const { return ok(); }
  /// The value (only when ok()).
  [[nodiscard]] T& value() {
    GDPN_ASSERT(ok(), "Result::value() of a failure");
    return *value_;
  }
  /// The value (only when ok()).
  [[nodiscard]] const T& value() const {
    GDPN_ASSERT(ok(), "Result::value() of a failure");
    return *value_;
  }
  /// The value (only when ok()).
  T& operator*() { return value(); }
  /// The value (only when ok()).
  const T& operator*() const { return value(); }
  /// The value's members (only when ok()).
  T* operator->() { return &value(); }
  /// The value's members (only when ok()).
  const T* operator->() const { return &value(); }
  /// Why there is no value (only when !ok()): the message and where.
  [[nodiscard]] const Diagnostic& error() const {
    GDPN_ASSERT(!ok(), "Result::error() of a success");
    return error_;
  }

 private:
  std::optional<T> value_;
  Diagnostic error_;
};

}  // namespace gdpn::core
