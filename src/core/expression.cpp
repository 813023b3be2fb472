// Arithmetic over named numbers: a recursive-descent evaluator with located errors.

#include "gdpn/core/expression.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>

#include "gdpn/core/text.h"

namespace gdpn::core {
namespace {

class Evaluator {
 public:
  Evaluator(std::string_view text, const NameLookup& lookup, const std::vector<std::string>& names)
      : s_(text), lookup_(lookup), names_(names) {}

  std::optional<double> run(ExpressionError& error) {
    auto v = sum();
    skip();
    if (v && i_ < s_.size()) fail(i_, std::string("unexpected '") + s_[i_] + "'");
    if (!v || !error_.message.empty()) {
      error = error_;
      return std::nullopt;
    }
    if (!std::isfinite(*v)) {
      error = {0, "the expression gives " + formatDouble(*v)};
      return std::nullopt;
    }
    return v;
  }

  std::vector<std::string> used;  // names met, in order

 private:
  void skip() {
    while (i_ < s_.size() && (s_[i_] == ' ' || s_[i_] == '\t')) ++i_;
  }
  std::nullopt_t fail(std::size_t at, std::string message) {
    if (error_.message.empty()) error_ = {at, std::move(message)};
    return std::nullopt;
  }
  bool eat(char c) {
    skip();
    if (i_ < s_.size() && s_[i_] == c) {
      ++i_;
      return true;
    }
    return false;
  }

  std::optional<double> sum() {
    auto v = product();
    while (v) {
      if (eat('+')) {
        auto r = product();
        if (!r) return std::nullopt;
        *v += *r;
      } else if (eat('-')) {
        auto r = product();
        if (!r) return std::nullopt;
        *v -= *r;
      } else {
        break;
      }
    }
    return v;
  }

  std::optional<double> product() {
    auto v = unary();
    while (v) {
      if (eat('*')) {
        auto r = unary();
        if (!r) return std::nullopt;
        *v *= *r;
      } else if (eat('/')) {
        const std::size_t at = i_;
        auto r = unary();
        if (!r) return std::nullopt;
        if (*r == 0.0) return fail(at, "division by zero");
        *v /= *r;
      } else {
        break;
      }
    }
    return v;
  }

  std::optional<double> unary() {
    if (eat('-')) {
      auto v = unary();
      return v ? std::optional<double>(-*v) : std::nullopt;
    }
    if (eat('+')) return unary();
    return primary();
  }

  std::optional<double> primary() {
    skip();
    if (i_ >= s_.size()) return fail(i_, "expected a number, a name or '('");
    const std::size_t start = i_;
    if (eat('(')) {
      auto v = sum();
      if (!v) return std::nullopt;
      if (!eat(')')) return fail(i_, "expected ')'");
      return v;
    }
    const char c = s_[i_];
    if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') {
      std::size_t end = i_;
      while (end < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[end])) || s_[end] == '.' ||
                                 ((s_[end] == '+' || s_[end] == '-') && (s_[end - 1] == 'e' || s_[end - 1] == 'E')))) {
        ++end;
      }
      auto v = parseNumber(s_.substr(i_, end - i_));
      if (!v) return fail(i_, "'" + std::string(s_.substr(i_, end - i_)) + "' is not a number");
      i_ = end;
      return v;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t end = i_;
      while (end < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[end])) || s_[end] == '_')) ++end;
      const std::string name(s_.substr(i_, end - i_));
      i_ = end;
      if (eat('(')) return call(name, start);
      if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
      auto v = lookup_ ? lookup_(name) : std::nullopt;
      if (!v) return fail(start, "no parameter '" + name + "'" + didYouMean(name, names_));
      return v;
    }
    return fail(i_, std::string("unexpected '") + c + "'");
  }

  std::optional<double> call(const std::string& name, std::size_t at) {
    std::vector<double> args;
    if (!eat(')')) {
      while (true) {
        auto v = sum();
        if (!v) return std::nullopt;
        args.push_back(*v);
        if (eat(')')) break;
        if (!eat(',')) return fail(i_, "expected ',' or ')'");
      }
    }
    const auto want = [&](std::size_t n) -> bool {
      if (args.size() == n) return true;
      fail(at, name + "() takes " + std::to_string(n) + " argument" + (n == 1 ? "" : "s") + ", got " +
                   std::to_string(args.size()));
      return false;
    };
    if (name == "min" || name == "max") {
      if (!want(2)) return std::nullopt;
      return name == "min" ? std::min(args[0], args[1]) : std::max(args[0], args[1]);
    }
    if (name == "atan2d") {  // degrees, as MATLAB's: the angle parts turn by
      if (!want(2)) return std::nullopt;
      return std::atan2(args[0], args[1]) * 180.0 / std::numbers::pi;
    }
    if (name == "sind" || name == "cosd") {
      if (!want(1)) return std::nullopt;
      const double r = args[0] * std::numbers::pi / 180.0;
      return name == "sind" ? std::sin(r) : std::cos(r);
    }
    if (name == "abs" || name == "sqrt" || name == "floor" || name == "ceil") {
      if (!want(1)) return std::nullopt;
      if (name == "abs") return std::abs(args[0]);
      if (name == "floor") return std::floor(args[0]);
      if (name == "ceil") return std::ceil(args[0]);
      if (args[0] < 0.0) return fail(at, "sqrt() of a negative number");
      return std::sqrt(args[0]);
    }
    return fail(at, "no function '" + name + "'" +
                        didYouMean(name, {"min", "max", "abs", "sqrt", "floor", "ceil", "sind", "cosd", "atan2d"}) +
                        " (there are: min, max, abs, sqrt, floor, ceil, sind, cosd, atan2d)");
  }

  std::string_view s_;
  const NameLookup& lookup_;
  const std::vector<std::string>& names_;
  std::size_t i_ = 0;
  ExpressionError error_;
};

}  // namespace

std::optional<double> evaluate(std::string_view text, const NameLookup& lookup, ExpressionError& error,
                               const std::vector<std::string>& names) {
  Evaluator e(text, lookup, names);
  return e.run(error);
}

std::vector<std::string> expressionNames(std::string_view text) {
  const NameLookup any = [](std::string_view) -> std::optional<double> { return 1.0; };
  Evaluator e(text, any, {});
  ExpressionError error;
  if (!e.run(error) && error.message.find("division") == std::string::npos) return {};
  return e.used;
}

}  // namespace gdpn::core
