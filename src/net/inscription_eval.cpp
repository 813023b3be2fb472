// The inscription language's evaluation: a checked expression under a binding gives a value or
// a multiset, or no value where the semantics has none (a division by zero, an overflow, the
// successor of a non-cyclic enumeration's last constant, a number outside its range).

#include <algorithm>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

std::optional<std::int64_t> arithmetic(Expr::Op op, std::int64_t a, std::int64_t b) {
  std::int64_t r = 0;
  switch (op) {
    case Expr::Op::Add:
      if (__builtin_add_overflow(a, b, &r)) return std::nullopt;
      return r;
    case Expr::Op::Sub:
      if (__builtin_sub_overflow(a, b, &r)) return std::nullopt;
      return r;
    case Expr::Op::Mul:
      if (__builtin_mul_overflow(a, b, &r)) return std::nullopt;
      return r;
    case Expr::Op::Div:
      // truncated toward zero, as in C
      if (b == 0 || (a == INT64_MIN && b == -1)) return std::nullopt;
      return a / b;
    case Expr::Op::Mod:
      // the remainder of that division: the sign of a
      if (b == 0 || (a == INT64_MIN && b == -1)) return std::nullopt;
      return a % b;
    case Expr::Op::Const:
    case Expr::Op::Name:
    case Expr::Op::Var:
    case Expr::Op::Tuple:
    case Expr::Op::Record:
    case Expr::Op::Field:
    case Expr::Op::Neg:
    case Expr::Op::Not:
    case Expr::Op::Eq:
    case Expr::Op::Ne:
    case Expr::Op::Lt:
    case Expr::Op::Le:
    case Expr::Op::Gt:
    case Expr::Op::Ge:
    case Expr::Op::And:
    case Expr::Op::Or:
    case Expr::Op::If:
    case Expr::Op::Succ:
    case Expr::Op::Pred:
    case Expr::Op::Times:
    case Expr::Op::Sum:
    case Expr::Op::All:
    case Expr::Op::Empty: break;
  }
  return std::nullopt;
}

// e's value without a copy where it is a constant, a variable or a field of one: a pointer into
// `e` or `b`; null otherwise (and where it has no value)
const Value* peek(const Expr& e, const Binding& b) {
  if (e.op == Expr::Op::Const) return &e.value;
  if (e.op == Expr::Op::Var) {
    return e.index >= 0 && static_cast<std::size_t>(e.index) < b.size() ? &b[static_cast<std::size_t>(e.index)] : nullptr;
  }
  if (e.op == Expr::Op::Field) {
    const Value* r = peek(e.args[0], b);
    if (!r || r->tag != Value::Tag::Tuple || e.index < 0 || static_cast<std::size_t>(e.index) >= r->items.size()) {
      return nullptr;
    }
    return &r->items[static_cast<std::size_t>(e.index)];
  }
  return nullptr;
}

// e's value: peeked where it can be, else evaluated into `scratch`; null where it has none
const Value* valueOf(const Expr& e, const Binding& b, const Colours& colours, std::optional<Value>& scratch) {
  if (const Value* v = peek(e, b)) return v;
  scratch = evaluate(e, b, colours);
  return scratch ? &*scratch : nullptr;
}

// a number made by the language: a value of its node's set, or none outside its range
std::optional<Value> number(std::int64_t n, ColourId set, const Colours& colours) {
  Value v = Value::integer(n);
  if (set < colours.sets().size() && colours.at(set).kind == ColourKind::Integer && !colours.contains(set, v)) {
    return std::nullopt;
  }
  return v;
}

// succ (step +1) or pred (step -1) of `v` in set `id`
std::optional<Value> step(const Value& v, ColourId id, const Colours& colours, int by) {
  if (v.tag != Value::Tag::Int || id >= colours.sets().size()) return std::nullopt;
  const ColourSet& s = colours.at(id);
  if (s.kind == ColourKind::Enum) {
    const auto n = static_cast<std::int64_t>(s.constants.size());
    if (v.i < 0 || v.i >= n) return std::nullopt;
    std::int64_t k = v.i + by;
    if (k < 0 || k >= n) {
      if (!s.cyclic) return std::nullopt;
      k = k < 0 ? n - 1 : 0;
    }
    return Value::integer(k);
  }
  if (s.kind != ColourKind::Integer) return std::nullopt;
  if (s.range) {
    // a finite range wraps around, like a cyclic enumeration (the contest's successor)
    if (v.i < s.lo || v.i > s.hi) return std::nullopt;
    if (by > 0) return Value::integer(v.i == s.hi ? s.lo : v.i + 1);
    return Value::integer(v.i == s.lo ? s.hi : v.i - 1);
  }
  std::int64_t r = 0;
  if (__builtin_add_overflow(v.i, static_cast<std::int64_t>(by), &r)) return std::nullopt;
  return Value::integer(r);
}

// the multiset `e` denotes, each element of set `set` when `set` is given
bool into(const Expr& e, const Binding& b, const Colours& colours, std::optional<ColourId> set, Multiset& out,
          std::int64_t times);

// adds `times` x `v` to `out`, when it is of `set` (moved in when it is new there)
template <class V>
bool add(V&& v, const Colours& colours, std::optional<ColourId> set, Multiset& out, std::int64_t times) {
  if (set && !colours.contains(*set, v)) return false;
  if (times == 0) return true;
  std::int64_t& k = out.try_emplace(std::forward<V>(v), 0).first->second;
  if (__builtin_add_overflow(k, times, &k)) return false;
  return true;
}

// the set of component `k` of the tuple or record set `set`, if known
std::optional<ColourId> componentSet(std::optional<ColourId> set, std::size_t k, const Colours& colours) {
  if (!set || *set >= colours.sets().size()) return std::nullopt;
  const ColourSet& s = colours.at(*set);
  if ((s.kind != ColourKind::Product && s.kind != ColourKind::Record) || k >= s.components.size()) return std::nullopt;
  return s.components[k];
}

// a tuple or record with a multiset among its components: every combination, the
// multiplicities multiplied
bool combinations(const Expr& e, const Binding& b, const Colours& colours, std::optional<ColourId> set, Multiset& out,
                  std::int64_t times) {
  // each component's multiset, in the value's order (a record's field order)
  const std::size_t n = e.args.size();
  std::vector<std::size_t> arg_of(n);
  for (std::size_t k = 0; k < n; ++k) arg_of[k] = k;
  if (e.op == Expr::Op::Record) {
    if (e.type >= colours.sets().size()) return false;
    const auto& fields = colours.at(e.type).fields;
    if (fields.size() != n) return false;
    for (std::size_t k = 0; k < n; ++k) {
      const auto it = std::find(e.fields.begin(), e.fields.end(), fields[k]);
      if (it == e.fields.end()) return false;
      arg_of[k] = static_cast<std::size_t>(it - e.fields.begin());
    }
  }
  std::vector<Multiset> parts(n);
  for (std::size_t k = 0; k < n; ++k) {
    if (!into(e.args[arg_of[k]], b, colours, componentSet(set ? set : std::optional<ColourId>(e.type), k, colours),
              parts[k], 1)) {
      return false;
    }
  }
  // the product, first component slowest
  std::vector<std::pair<Value, std::int64_t>> acc = {{Value::tuple({}), times}};
  for (const Multiset& part : parts) {
    std::vector<std::pair<Value, std::int64_t>> next;
    for (const auto& [prefix, k] : acc) {
      for (const auto& [v, m] : part) {
        Value t = prefix;
        t.items.push_back(v);
        std::int64_t km = 0;
        if (__builtin_mul_overflow(k, m, &km)) return false;
        next.emplace_back(std::move(t), km);
      }
    }
    acc = std::move(next);
  }
  for (const auto& [v, k] : acc) {
    if (!add(v, colours, set, out, k)) return false;
  }
  return true;
}

bool into(const Expr& e, const Binding& b, const Colours& colours, std::optional<ColourId> set, Multiset& out,
          std::int64_t times) {
  if (times < 0) return false;
  switch (e.op) {
    case Expr::Op::Sum:
      return into(e.args[0], b, colours, set, out, times) && into(e.args[1], b, colours, set, out, times);
    case Expr::Op::Times: {
      const auto n = evaluate(e.args[0], b, colours);
      if (!n || n->tag != Value::Tag::Int || n->i < 0) return false;
      std::int64_t t = 0;
      if (__builtin_mul_overflow(times, n->i, &t)) return false;
      return into(e.args[1], b, colours, set, out, t);
    }
    case Expr::Op::Empty: return true;
    case Expr::Op::All:
      for (const Value& v : colours.values(e.type)) {
        if (!add(v, colours, set, out, times)) return false;
      }
      return true;
    case Expr::Op::If: {
      const auto c = evaluate(e.args[0], b, colours);
      if (!c || c->tag != Value::Tag::Bool) return false;
      return into(e.args[c->i != 0 ? 1 : 2], b, colours, set, out, times);
    }
    case Expr::Op::Tuple:
    case Expr::Op::Record:
      if (e.multiset) return combinations(e, b, colours, set, out, times);
      break;
    case Expr::Op::Const:
    case Expr::Op::Name:
    case Expr::Op::Var:
    case Expr::Op::Field:
    case Expr::Op::Neg:
    case Expr::Op::Not:
    case Expr::Op::Add:
    case Expr::Op::Sub:
    case Expr::Op::Mul:
    case Expr::Op::Div:
    case Expr::Op::Mod:
    case Expr::Op::Eq:
    case Expr::Op::Ne:
    case Expr::Op::Lt:
    case Expr::Op::Le:
    case Expr::Op::Gt:
    case Expr::Op::Ge:
    case Expr::Op::And:
    case Expr::Op::Or:
    case Expr::Op::Succ:
    case Expr::Op::Pred: break;
  }
  if (const Value* v = peek(e, b)) return add(*v, colours, set, out, times);
  auto v = evaluate(e, b, colours);
  return v && add(std::move(*v), colours, set, out, times);
}

}  // namespace

std::optional<Value> evaluate(const Expr& e, const Binding& b, const Colours& colours) {
  switch (e.op) {
    case Expr::Op::Const: return e.value;
    case Expr::Op::Name: return std::nullopt;  // not checked
    case Expr::Op::Var:
      if (e.index < 0 || static_cast<std::size_t>(e.index) >= b.size()) return std::nullopt;
      return b[static_cast<std::size_t>(e.index)];
    case Expr::Op::Tuple: {
      std::vector<Value> parts;
      parts.reserve(e.args.size());
      for (const Expr& a : e.args) {
        auto v = evaluate(a, b, colours);
        if (!v) return std::nullopt;
        parts.push_back(std::move(*v));
      }
      return Value::tuple(std::move(parts));
    }
    case Expr::Op::Record: {
      // the fields in the set's order, whatever the order written
      if (e.type >= colours.sets().size()) return std::nullopt;
      const auto& fields = colours.at(e.type).fields;
      if (fields.size() != e.args.size()) return std::nullopt;
      std::vector<Value> parts;
      parts.reserve(fields.size());
      for (const std::string& f : fields) {
        const auto it = std::find(e.fields.begin(), e.fields.end(), f);
        if (it == e.fields.end()) return std::nullopt;
        auto v = evaluate(e.args[static_cast<std::size_t>(it - e.fields.begin())], b, colours);
        if (!v) return std::nullopt;
        parts.push_back(std::move(*v));
      }
      return Value::tuple(std::move(parts));
    }
    case Expr::Op::Field: {
      if (const Value* v = peek(e, b)) return *v;
      auto r = evaluate(e.args[0], b, colours);
      if (!r || r->tag != Value::Tag::Tuple || e.index < 0 || static_cast<std::size_t>(e.index) >= r->items.size()) {
        return std::nullopt;
      }
      return std::move(r->items[static_cast<std::size_t>(e.index)]);
    }
    case Expr::Op::Neg: {
      const auto a = evaluate(e.args[0], b, colours);
      if (!a || a->tag != Value::Tag::Int || a->i == INT64_MIN) return std::nullopt;
      return number(-a->i, e.type, colours);
    }
    case Expr::Op::Add:
    case Expr::Op::Sub:
    case Expr::Op::Mul:
    case Expr::Op::Div:
    case Expr::Op::Mod: {
      std::optional<Value> xs, ys;
      const Value* x = valueOf(e.args[0], b, colours, xs);
      if (!x || x->tag != Value::Tag::Int) return std::nullopt;
      const Value* y = valueOf(e.args[1], b, colours, ys);
      if (!y || y->tag != Value::Tag::Int) return std::nullopt;
      const auto r = arithmetic(e.op, x->i, y->i);
      if (!r) return std::nullopt;
      return number(*r, e.type, colours);
    }
    case Expr::Op::Not: {
      const auto a = evaluate(e.args[0], b, colours);
      if (!a || a->tag != Value::Tag::Bool) return std::nullopt;
      return Value::boolean(a->i == 0);
    }
    case Expr::Op::And:
    case Expr::Op::Or: {
      // the right operand only when the left does not decide
      const auto x = evaluate(e.args[0], b, colours);
      if (!x || x->tag != Value::Tag::Bool) return std::nullopt;
      if ((x->i != 0) == (e.op == Expr::Op::Or)) return x;
      const auto y = evaluate(e.args[1], b, colours);
      if (!y || y->tag != Value::Tag::Bool) return std::nullopt;
      return y;
    }
    case Expr::Op::Eq:
    case Expr::Op::Ne:
    case Expr::Op::Lt:
    case Expr::Op::Le:
    case Expr::Op::Gt:
    case Expr::Op::Ge: {
      std::optional<Value> xs, ys;
      const Value* x = valueOf(e.args[0], b, colours, xs);
      if (!x) return std::nullopt;
      const Value* y = valueOf(e.args[1], b, colours, ys);
      if (!y) return std::nullopt;
      const std::strong_ordering c = *x <=> *y;
      const Expr::Op op = e.op;
      const bool r = op == Expr::Op::Eq   ? c == 0
                     : op == Expr::Op::Ne ? c != 0
                     : op == Expr::Op::Lt ? c < 0
                     : op == Expr::Op::Le ? c <= 0
                     : op == Expr::Op::Gt ? c > 0
                                          : c >= 0;
      return Value::boolean(r);
    }
    case Expr::Op::If: {
      const auto c = evaluate(e.args[0], b, colours);
      if (!c || c->tag != Value::Tag::Bool) return std::nullopt;
      return evaluate(e.args[c->i != 0 ? 1 : 2], b, colours);
    }
    case Expr::Op::Succ:
    case Expr::Op::Pred: {
      const auto a = evaluate(e.args[0], b, colours);
      if (!a) return std::nullopt;
      return step(*a, e.args[0].type, colours, e.op == Expr::Op::Succ ? 1 : -1);
    }
    case Expr::Op::Times:
    case Expr::Op::Sum:
    case Expr::Op::All:
    case Expr::Op::Empty: return std::nullopt;  // multisets: evaluateInto
  }
  return std::nullopt;
}

bool evaluateInto(const Expr& e, const Binding& b, const Colours& colours, ColourId set, Multiset& out,
                  std::int64_t times) {
  return into(e, b, colours, set, out, times);
}

}  // namespace gdpn::net
