// Arithmetic over named numbers: a recursive-descent evaluator with located errors.

#include "gdpn/core/expression.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <numbers>

#include "gdpn/core/text.h"

namespace gdpn::core {
namespace {

struct Function {
  std::string_view name;
  std::size_t arity;
};
// the functions, in the order Program::Op::Call numbers them
constexpr std::array<Function, 10> kFunctions{{{"min", 2}, {"max", 2}, {"abs", 1}, {"sqrt", 1}, {"floor", 1},
                                               {"ceil", 1}, {"sind", 1}, {"cosd", 1}, {"atan2d", 2}, {"exp", 1}}};

std::uint32_t functionIndex(std::string_view f) {
  for (std::uint32_t k = 0; k < kFunctions.size(); ++k) {
    if (kFunctions[k].name == f) return k;
  }
  return 0;
}

// function number `k` of kFunctions on its arguments `a` (sqrt of a negative number: 0 at run time)
double applyFunctionAt(std::uint32_t k, const double* a) {
  switch (k) {
    case 0: return std::min(a[0], a[1]);
    case 1: return std::max(a[0], a[1]);
    case 2: return std::abs(a[0]);
    case 3: return a[0] < 0.0 ? 0.0 : std::sqrt(a[0]);
    case 4: return std::floor(a[0]);
    case 5: return std::ceil(a[0]);
    case 6: return std::sin(a[0] * std::numbers::pi / 180.0);
    case 7: return std::cos(a[0] * std::numbers::pi / 180.0);
    case 8: return std::atan2(a[0], a[1]) * 180.0 / std::numbers::pi;  // degrees, as MATLAB's
    default: return std::exp(a[0]);
  }
}

double applyFunction(std::string_view f, const double* a) { return applyFunctionAt(functionIndex(f), a); }

// The grammar, once, for two sinks: one computes as it reads (evaluate), one writes the
// operations in the order a stack machine runs them (compileExpression). A recursive descent
// meets an operator's operands before the operator, so the second sink only appends.
struct Computing {
  using V = double;
  const NameLookup& lookup;
  std::optional<V> constant(double x) { return x; }
  std::optional<V> name(const std::string& n) { return lookup ? lookup(n) : std::nullopt; }
  V binary(char op, V a, V b) {
    switch (op) {
      case '+': return a + b;
      case '-': return a - b;
      case '*': return a * b;
      default: return a / b;
    }
  }
  V negate(V a) { return -a; }
  // the value of function `f` (checked: known, with its count of arguments)
  V call(std::string_view f, const std::vector<V>& a) { return applyFunction(f, a.data()); }
  static constexpr bool kRunTime = false;
};

struct Compiling {
  struct V {};
  Program& program;
  const std::function<std::optional<std::uint32_t>(std::string_view)>& resolve;
  std::optional<V> constant(double x) {
    program.ops.push_back({Program::Op::Const, 0, x});
    return V{};
  }
  std::optional<V> name(const std::string& n) {
    const auto slot = resolve(n);
    if (!slot) return std::nullopt;
    program.ops.push_back({Program::Op::Load, *slot, 0.0});
    program.reads.push_back(*slot);
    return V{};
  }
  V binary(char op, V, V) {
    program.ops.push_back({op == '+' ? Program::Op::Add : op == '-' ? Program::Op::Sub : op == '*' ? Program::Op::Mul
                                                                                                    : Program::Op::Div,
                           0, 0.0});
    return V{};
  }
  V negate(V) {
    program.ops.push_back({Program::Op::Neg, 0, 0.0});
    return V{};
  }
  V call(std::string_view f, const std::vector<V>&) {
    program.ops.push_back({Program::Op::Call, functionIndex(f), 0.0});
    return V{};
  }
  static constexpr bool kRunTime = true;
};

template <class Sink>
class Evaluator {
 public:
  using V = typename Sink::V;
  Evaluator(std::string_view text, Sink sink, const std::vector<std::string>& names)
      : s_(text), sink_(std::move(sink)), names_(names) {}

  std::optional<V> run(ExpressionError& error) {
    auto v = sum();
    skip();
    if (v && i_ < s_.size()) fail(i_, std::string("unexpected '") + s_[i_] + "'");
    if (!v || !error_.message.empty()) {
      error = error_;
      return std::nullopt;
    }
    if constexpr (!Sink::kRunTime) {
      if (!std::isfinite(*v)) {
        error = {0, "the expression gives " + formatDouble(*v)};
        return std::nullopt;
      }
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

  std::optional<V> sum() {
    auto v = product();
    while (v) {
      const char op = eat('+') ? '+' : eat('-') ? '-' : 0;
      if (op == 0) break;
      auto r = product();
      if (!r) return std::nullopt;
      v = sink_.binary(op, *v, *r);
    }
    return v;
  }

  std::optional<V> product() {
    auto v = unary();
    while (v) {
      const char op = eat('*') ? '*' : eat('/') ? '/' : 0;
      if (op == 0) break;
      const std::size_t at = i_;
      auto r = unary();
      if (!r) return std::nullopt;
      if constexpr (!Sink::kRunTime) {
        if (op == '/' && *r == 0.0) return fail(at, "division by zero");
      }
      v = sink_.binary(op, *v, *r);
    }
    return v;
  }

  std::optional<V> unary() {
    if (eat('-')) {
      auto v = unary();
      return v ? std::optional<V>(sink_.negate(*v)) : std::nullopt;
    }
    if (eat('+')) return unary();
    return primary();
  }

  std::optional<V> primary() {
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
      return sink_.constant(*v);
    }
    if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') {
      std::size_t end = i_;
      while (end < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[end])) || s_[end] == '_')) ++end;
      const std::string name(s_.substr(i_, end - i_));
      i_ = end;
      if (eat('(')) return call(name, start);
      if (std::find(used.begin(), used.end(), name) == used.end()) used.push_back(name);
      auto v = sink_.name(name);
      if (!v) return fail(start, std::string(Sink::kRunTime ? "no name '" : "no parameter '") + name + "'" + didYouMean(name, names_));
      return v;
    }
    return fail(i_, std::string("unexpected '") + c + "'");
  }

  std::optional<V> call(const std::string& name, std::size_t at) {
    std::vector<V> args;
    if (!eat(')')) {
      while (true) {
        auto v = sum();
        if (!v) return std::nullopt;
        args.push_back(*v);
        if (eat(')')) break;
        if (!eat(',')) return fail(i_, "expected ',' or ')'");
      }
    }
    const auto f = std::find_if(kFunctions.begin(), kFunctions.end(), [&](const Function& k) { return k.name == name; });
    if (f == kFunctions.end()) {
      std::vector<std::string> known;
      std::string list;
      for (const auto& k : kFunctions) {
        known.emplace_back(k.name);
        list += (list.empty() ? "" : ", ") + std::string(k.name);
      }
      return fail(at, "no function '" + name + "'" + didYouMean(name, known) + " (there are: " + list + ")");
    }
    if (args.size() != f->arity) {
      return fail(at, name + "() takes " + std::to_string(f->arity) + " argument" + (f->arity == 1 ? "" : "s") +
                          ", got " + std::to_string(args.size()));
    }
    if constexpr (!Sink::kRunTime) {
      if (name == "sqrt" && args[0] < 0.0) return fail(at, "sqrt() of a negative number");
    }
    return sink_.call(name, args);
  }

  std::string_view s_;
  Sink sink_;
  const std::vector<std::string>& names_;
  std::size_t i_ = 0;
  ExpressionError error_;
};

}  // namespace

std::optional<double> evaluate(std::string_view text, const NameLookup& lookup, ExpressionError& error,
                               const std::vector<std::string>& names) {
  Evaluator<Computing> e(text, Computing{lookup}, names);
  return e.run(error);
}

std::vector<std::string> expressionNames(std::string_view text) {
  const NameLookup any = [](std::string_view) -> std::optional<double> { return 1.0; };
  Evaluator<Computing> e(text, Computing{any}, {});
  ExpressionError error;
  if (!e.run(error) && error.message.find("division") == std::string::npos) return {};
  return e.used;
}

std::optional<Program> compileExpression(std::string_view text,
                                         const std::function<std::optional<std::uint32_t>(std::string_view)>& resolve,
                                         ExpressionError& error, const std::vector<std::string>& names) {
  Program program;
  Evaluator<Compiling> e(text, Compiling{program, resolve}, names);
  if (!e.run(error)) return std::nullopt;
  std::sort(program.reads.begin(), program.reads.end());
  program.reads.erase(std::unique(program.reads.begin(), program.reads.end()), program.reads.end());
  // the deepest the stack gets
  std::size_t depth = 0;
  for (const auto& op : program.ops) {
    switch (op.op) {
      case Program::Op::Const:
      case Program::Op::Load: ++depth; break;
      case Program::Op::Add:
      case Program::Op::Sub:
      case Program::Op::Mul:
      case Program::Op::Div: --depth; break;
      case Program::Op::Neg: break;
      case Program::Op::Call: depth -= kFunctions[op.arg].arity - 1; break;
    }
    program.depth = std::max(program.depth, depth);
  }
  if (program.depth > Program::kMostDepth) {
    error = {0, "the expression nests too deep (at most " + std::to_string(Program::kMostDepth) + " values at once)"};
    return std::nullopt;
  }
  return program;
}

double Program::run(const double* values) const {
  double stack[kMostDepth];
  std::size_t n = 0;
  for (const auto& op : ops) {
    switch (op.op) {
      case Op::Const: stack[n++] = op.value; break;
      case Op::Load: stack[n++] = values[op.arg]; break;
      case Op::Add: --n, stack[n - 1] += stack[n]; break;
      case Op::Sub: --n, stack[n - 1] -= stack[n]; break;
      case Op::Mul: --n, stack[n - 1] *= stack[n]; break;
      case Op::Div: --n, stack[n - 1] /= stack[n]; break;
      case Op::Neg: stack[n - 1] = -stack[n - 1]; break;
      case Op::Call: {
        const std::size_t arity = kFunctions[op.arg].arity;
        n -= arity;
        stack[n] = applyFunctionAt(op.arg, stack + n);
        ++n;
        break;
      }
    }
  }
  return n == 1 ? stack[0] : 0.0;
}

}  // namespace gdpn::core
