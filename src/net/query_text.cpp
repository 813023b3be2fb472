// The text form of queries: a tokenizer and a recursive-descent parser over the net's names,
// and the way back from a formula to text.

#include <cctype>
#include <charconv>

#include "gdpn/net/query.h"

namespace gdpn::net {
namespace {

enum class Tok : std::uint8_t { End, Name, Quoted, Number, LParen, RParen, LBracket, RBracket, Comma, Plus, Op, Bad };

struct Token {
  Tok kind = Tok::End;
  std::string text;
  std::size_t column = 1;
};

// words that are operators, never names (a place so called is written in quotes)
bool keyword(std::string_view w) {
  for (std::string_view k : {"A", "E", "X", "F", "G", "U", "EX", "AX", "EF", "AF", "EG", "AG", "and", "or", "not",
                             "true", "false", "deadlock", "fireable", "bound"}) {
    if (w == k) return true;
  }
  return false;
}

bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool nameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '/' || c == '.' || c == ':' || c == '-';
}

std::vector<Token> tokenize(std::string_view s) {
  std::vector<Token> out;
  std::size_t i = 0;
  while (i < s.size()) {
    const char c = s[i];
    const std::size_t col = i + 1;
    if (std::isspace(static_cast<unsigned char>(c)) != 0) {
      ++i;
      continue;
    }
    if (nameStart(c)) {
      std::size_t j = i;
      while (j < s.size() && nameChar(s[j])) ++j;
      out.push_back({Tok::Name, std::string(s.substr(i, j - i)), col});
      i = j;
    } else if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
      std::size_t j = i;
      while (j < s.size() && std::isdigit(static_cast<unsigned char>(s[j])) != 0) ++j;
      out.push_back({Tok::Number, std::string(s.substr(i, j - i)), col});
      i = j;
    } else if (c == '"') {
      const std::size_t j = s.find('"', i + 1);
      if (j == std::string_view::npos) {
        out.push_back({Tok::Bad, "a name in quotes that is never closed", col});
        return out;
      }
      out.push_back({Tok::Quoted, std::string(s.substr(i + 1, j - i - 1)), col});
      i = j + 1;
    } else {
      static constexpr std::string_view kTwo[] = {"<=", ">=", "==", "!=", "&&", "||"};
      std::string op(1, c);
      for (std::string_view two : kTwo) {
        if (s.substr(i, 2) == two) op = two;
      }
      Tok kind = Tok::Op;
      if (op == "(") kind = Tok::LParen;
      if (op == ")") kind = Tok::RParen;
      if (op == "[") kind = Tok::LBracket;
      if (op == "]") kind = Tok::RBracket;
      if (op == ",") kind = Tok::Comma;
      if (op == "+") kind = Tok::Plus;
      if (kind == Tok::Op && std::string_view("< <= > >= = == != ! & && | ||").find(op) == std::string_view::npos) {
        out.push_back({Tok::Bad, "'" + op + "' is not part of a query", col});
        return out;
      }
      out.push_back({kind, op, col});
      i += op.size();
    }
  }
  out.push_back({Tok::End, "", s.size() + 1});
  return out;
}

// the id `find` gives `name`, or else that of the one among `count` constructs whose name
// (`append(out, id)` appends it) ends in "/" + name
template <class IdType, class Find, class Append>
std::optional<IdType> lookup(std::string_view name, Find find, std::size_t count, Append append) {
  if (const std::optional<IdType> id = find(name)) return id;
  std::optional<IdType> found;
  std::string n;
  for (const IdType i : IdRange<IdType>(count)) {
    n.clear();
    append(n, i);
    if (n.size() > name.size() && n.ends_with(name) && n[n.size() - name.size() - 1] == '/') {
      if (found) return std::nullopt;
      found = i;
    }
  }
  return found;
}

class Parser {
 public:
  Parser(const Net& net, std::vector<Token> tokens, const NameExpansion* names)
      : net_(net), names_(names), t_(std::move(tokens)) {}

  std::optional<Formula> whole() {
    if (t_.back().kind == Tok::Bad) return fail(t_.back(), t_.back().text);
    std::optional<Formula> f;
    if (word("bound")) {
      // bound(a + b): a number, the query on its own
      f = node(FormulaKind::Bound, peek().column);
      take();
      if (!expect(Tok::LParen, "'(' after bound") || !sum(f->left) || !expect(Tok::RParen, "')'")) return std::nullopt;
    } else {
      f = disjunction();
    }
    if (f && peek().kind != Tok::End) return fail(peek(), "expected the end of the query, found " + describe(peek()));
    if (!f) return f;
    // the tree's depth, walked without recursion: everything that reads a formula recurses
    std::vector<std::pair<const Formula*, std::size_t>> todo{{&*f, 1}};
    while (!todo.empty()) {
      const auto [x, depth] = todo.back();
      todo.pop_back();
      if (depth > kMaxDepth) {
        error = {x->column, kTooDeep};
        return std::nullopt;
      }
      for (const Formula& o : x->operands) todo.emplace_back(&o, depth + 1);
    }
    return f;
  }
  QueryError error;

 private:
  const Token& peek(std::size_t ahead = 0) const { return t_[std::min(at_ + ahead, t_.size() - 1)]; }
  const Token& take() { return t_[std::min(at_++, t_.size() - 1)]; }
  bool word(const char* w) const { return peek().kind == Tok::Name && peek().text == w; }
  bool op(std::string_view a, std::string_view b = {}) const {
    return peek().kind == Tok::Op && (peek().text == a || (!b.empty() && peek().text == b));
  }
  bool failed(const Token& at, std::string message) {
    fail(at, std::move(message));
    return false;
  }
  std::nullopt_t fail(const Token& at, std::string message) {
    if (error.message.empty()) error = {at.column, std::move(message)};
    return std::nullopt;
  }
  static std::string describe(const Token& t) {
    return t.kind == Tok::End ? "the end" : t.kind == Tok::Quoted ? "\"" + t.text + "\"" : "'" + t.text + "'";
  }
  bool expect(Tok kind, const char* what) {
    if (peek().kind == kind) {
      take();
      return true;
    }
    fail(peek(), std::string("expected ") + what + ", found " + describe(peek()));
    return false;
  }
  static Formula node(FormulaKind kind, std::size_t column, std::vector<Formula> operands = {}) {
    Formula f;
    f.kind = kind;
    f.column = column;
    f.operands = std::move(operands);
    return f;
  }

  // a chain of `or` (or of `and`) is one node with every operand, not a deep tree
  std::optional<Formula> disjunction() { return chain(FormulaKind::Or, "or", "|", "||", &Parser::conjunction); }
  std::optional<Formula> conjunction() { return chain(FormulaKind::And, "and", "&", "&&", &Parser::unary); }
  std::optional<Formula> chain(FormulaKind kind, const char* name, std::string_view sign, std::string_view sign2,
                               std::optional<Formula> (Parser::*operand)()) {
    auto first = (this->*operand)();
    if (!first || !(word(name) || op(sign, sign2))) return first;
    Formula f = node(kind, first->column, {std::move(*first)});
    while (word(name) || op(sign, sign2)) {
      take();
      auto next = (this->*operand)();
      if (!next) return std::nullopt;
      f.operands.push_back(std::move(*next));
    }
    return f;
  }
  std::optional<Formula> unary() {
    // each level costs stack (parentheses too, so the parser's own depth is bounded more loosely
    // than the tree's)
    struct Level {
      std::size_t& depth;
      explicit Level(std::size_t& d) : depth(++d) {}
      ~Level() { --depth; }
    } level(depth_);
    if (depth_ > 3 * kMaxDepth) return fail(peek(), kTooDeep);
    const Token& t = peek();
    const std::size_t col = t.column;
    if (word("not") || op("!")) {
      take();
      auto f = unary();
      if (!f) return std::nullopt;
      return node(FormulaKind::Not, col, {std::move(*f)});
    }
    if (t.kind == Tok::Name) {
      // CTL's two-letter operators: a quantifier and a path operator
      static constexpr std::pair<std::string_view, FormulaKind> kPath[] = {
          {"X", FormulaKind::Next}, {"F", FormulaKind::Future}, {"G", FormulaKind::Globally}};
      if (t.text.size() == 2 && (t.text[0] == 'A' || t.text[0] == 'E')) {
        for (const auto& [letter, kind] : kPath) {
          if (t.text[1] != letter[0]) continue;
          const FormulaKind q = t.text[0] == 'A' ? FormulaKind::All : FormulaKind::Exists;
          take();
          auto f = unary();
          if (!f) return std::nullopt;
          return node(q, col, {node(kind, col, {std::move(*f)})});
        }
      }
      if (t.text == "A" || t.text == "E") {
        const FormulaKind q = t.text == "A" ? FormulaKind::All : FormulaKind::Exists;
        take();
        if (peek().kind == Tok::LBracket) {
          // E [ p U q ]
          take();
          auto left = disjunction();
          if (!left) return std::nullopt;
          if (!word("U")) return fail(peek(), "expected 'U' in " + std::string(q == FormulaKind::All ? "A" : "E") + " [ ... U ... ], found " + describe(peek()));
          const std::size_t ucol = peek().column;
          take();
          auto right = disjunction();
          if (!right || !expect(Tok::RBracket, "']'")) return std::nullopt;
          return node(q, col, {node(FormulaKind::Until, ucol, {std::move(*left), std::move(*right)})});
        }
        auto f = unary();
        if (!f) return std::nullopt;
        return node(q, col, {std::move(*f)});
      }
      for (const auto& [letter, kind] : kPath) {
        if (t.text != letter) continue;
        take();
        auto f = unary();
        if (!f) return std::nullopt;
        return node(kind, col, {std::move(*f)});
      }
    }
    return atom();
  }
  std::optional<Formula> atom() {
    const Token& t = peek();
    const std::size_t col = t.column;
    if (t.kind == Tok::LParen) {
      take();
      auto f = disjunction();
      if (!f) return std::nullopt;
      if (word("U")) {
        // (p U q), a path formula
        const std::size_t ucol = peek().column;
        take();
        auto right = disjunction();
        if (!right) return std::nullopt;
        f = node(FormulaKind::Until, ucol, {std::move(*f), std::move(*right)});
      }
      if (!expect(Tok::RParen, "')'")) return std::nullopt;
      return f;
    }
    if (word("true") || word("false") || word("deadlock")) {
      const std::string w = take().text;
      return node(w == "true" ? FormulaKind::True : w == "false" ? FormulaKind::False : FormulaKind::Deadlock, col);
    }
    if (word("bound")) return fail(peek(), "bound(...) is a number: it is a query of its own, not part of a formula");
    if (word("fireable")) {
      take();
      if (!expect(Tok::LParen, "'(' after fireable")) return std::nullopt;
      Formula f = node(FormulaKind::Fireable, col);
      do {
        const Token& n = peek();
        if (n.kind != Tok::Name && n.kind != Tok::Quoted) return fail(n, "expected a transition's name, found " + describe(n));
        const auto ids = transition(n.text);
        if (!ids) return fail(n, "no transition is called '" + n.text + "'");
        f.transitions.insert(f.transitions.end(), ids->begin(), ids->end());
        take();
      } while (peek().kind == Tok::Comma && take().kind == Tok::Comma);
      if (!expect(Tok::RParen, "')'")) return std::nullopt;
      return f;
    }
    // a comparison of two sums
    Formula f = node(FormulaKind::Compare, col);
    if (!sum(f.left)) return std::nullopt;
    static constexpr std::pair<std::string_view, Comparison> kOps[] = {
        {"<", Comparison::Less},           {"<=", Comparison::LessEqual}, {"=", Comparison::Equal},
        {"==", Comparison::Equal},         {"!=", Comparison::NotEqual},  {">=", Comparison::GreaterEqual},
        {">", Comparison::Greater}};
    bool found = false;
    for (const auto& [text, cmp] : kOps) {
      if (peek().kind == Tok::Op && peek().text == text) f.compare = cmp, found = true;
    }
    if (!found) return fail(peek(), "expected a comparison (<, <=, =, !=, >=, >) after the tokens, found " + describe(peek()));
    take();
    if (!sum(f.right)) return std::nullopt;
    return f;
  }
  bool sum(TokenSum& out) {
    do {
      const Token& t = peek();
      if (t.kind == Tok::Number) {
        std::int64_t v = 0;
        const auto r = std::from_chars(t.text.data(), t.text.data() + t.text.size(), v);
        if (r.ec != std::errc() || v > kMostConstant) return failed(t, "the number " + t.text + " is too large (the most is 2^60)");
        out.constant += v;
        if (out.constant > kMostConstant) return failed(t, "the numbers of this sum add up to more than 2^60");
      } else if (t.kind == Tok::Quoted || (t.kind == Tok::Name && !keyword(t.text))) {
        const auto ps = place(t.text);
        if (!ps) {
          const bool is_transition = transition(t.text).has_value();
          return failed(t, "no place is called '" + t.text + "'" +
                               (is_transition ? " (a transition is: fireable(" + t.text + ")?)" : ""));
        }
        for (const PlaceId p : *ps) {
          const Place& place = net_.places()[p];
          for (auto k = place.slots_begin; k < place.slots_end; ++k) out.slots.emplace_back(k);
        }
      } else if (t.kind == Tok::Name) {
        return failed(t, "'" + t.text + "' is a keyword: a place so called is written \"" + t.text + "\"");
      } else {
        return failed(t, "expected a place, a number or a formula, found " + describe(t));
      }
      take();
    } while (peek().kind == Tok::Plus && take().kind == Tok::Plus);
    return true;
  }

  std::optional<std::vector<PlaceId>> place(std::string_view n) const { return findPlacesNamed(net_, n, names_); }
  std::optional<std::vector<TransitionId>> transition(std::string_view n) const {
    return findTransitionsNamed(net_, n, names_);
  }

  static constexpr std::size_t kMaxDepth = 100;  // levels of the formula's tree
  static constexpr const char* kTooDeep = "the formula is nested more than 100 levels deep";
  const Net& net_;
  const NameExpansion* names_;
  std::vector<Token> t_;
  std::size_t at_ = 0;
  std::size_t depth_ = 0;  // unary() calls under way
};

std::string name(std::string_view n) {
  bool plain = !n.empty() && nameStart(n[0]) && !keyword(n);
  for (char c : n) plain = plain && nameChar(c);
  return plain ? std::string(n) : "\"" + std::string(n) + "\"";
}

/// `names` with every group that an entry of `table` (when given) lists, all of its members
/// there, written as that entry's key instead, where its first member stood.
std::vector<std::string> collapsed(std::vector<std::string> names,
                                   const std::map<std::string, std::vector<std::string>, std::less<>>* table) {
  if (!table) return names;
  // name -> its positions not yet taken; a group takes its members' last ones, so that a
  // member also named on its own keeps its place before the group
  std::map<std::string, std::vector<std::size_t>> unused;
  for (std::size_t i = 0; i < names.size(); ++i) unused[names[i]].push_back(i);
  std::map<std::size_t, std::string> out;  // position -> what stands there
  for (const auto& [key, members] : *table) {
    if (members.empty()) continue;
    while (true) {
      std::map<std::string, std::size_t> need;
      for (const auto& m : members) ++need[m];
      bool all = true;
      for (const auto& [m, k] : need) {
        const auto at = unused.find(m);
        all = all && at != unused.end() && at->second.size() >= k;
      }
      if (!all) break;
      std::size_t first = names.size();
      for (const auto& m : members) {
        first = std::min(first, unused[m].back());
        unused[m].pop_back();
      }
      out[first] = key;
    }
  }
  for (const auto& [n, positions] : unused) {
    for (const std::size_t i : positions) out[i] = n;
  }
  std::vector<std::string> result;
  for (auto& [i, n] : out) result.push_back(std::move(n));
  return result;
}

std::string sumText(const Net& net, const TokenSum& s, const NameExpansion* names) {
  std::string out;
  std::optional<PlaceId> last;
  std::vector<std::string> places;
  for (PlaceSlotId k : s.slots) {
    const PlaceId p = net.placeSlots()[k].place;
    if (p == last) continue;  // a place's slots were named once, by the place
    last = p;
    places.push_back(net.placeName(p));
  }
  for (const auto& p : collapsed(std::move(places), names ? &names->places : nullptr)) {
    out += (out.empty() ? "" : " + ") + name(p);
  }
  if (s.constant != 0 || out.empty()) out += (out.empty() ? "" : " + ") + std::to_string(s.constant);
  return out;
}

}  // namespace

std::optional<PlaceId> findPlaceNamed(const Net& net, std::string_view name) {
  return lookup<PlaceId>(name, [&](std::string_view x) { return net.findPlace(x); }, net.places().size(),
                [&](std::string& out, PlaceId p) { net.appendPlaceName(out, p); });
}

std::optional<TransitionId> findTransitionNamed(const Net& net, std::string_view name) {
  return lookup<TransitionId>(name, [&](std::string_view x) { return net.findTransition(x); }, net.transitions().size(),
                [&](std::string& out, TransitionId t) { net.appendTransitionName(out, t); });
}

namespace {

/// The entry of `table` called `name`, or else the one whose key ends in "/" + `name`; null
/// when none or several.
const std::vector<std::string>* expansionOf(const std::map<std::string, std::vector<std::string>, std::less<>>& table,
                                            std::string_view name) {
  if (const auto at = table.find(name); at != table.end()) return &at->second;
  const std::vector<std::string>* found = nullptr;
  for (const auto& [key, names] : table) {
    if (key.size() <= name.size() || !key.ends_with(name) || key[key.size() - name.size() - 1] != '/') continue;
    if (found) return nullptr;
    found = &names;
  }
  return found;
}

template <class IdType>
std::optional<std::vector<IdType>> expanded(const std::map<std::string, std::vector<std::string>, std::less<>>* table,
                                            std::string_view name, const auto& find, const auto& findOne) {
  if (const auto* names = table ? expansionOf(*table, name) : nullptr) {
    std::vector<IdType> out;
    for (const auto& n : *names) {
      if (auto id = find(n)) out.push_back(*id);
    }
    return out;
  }
  if (auto id = findOne(name)) return std::vector<IdType>{*id};
  return std::nullopt;
}

}  // namespace

std::optional<std::vector<PlaceId>> findPlacesNamed(const Net& net, std::string_view name, const NameExpansion* names) {
  return expanded<PlaceId>(
      names ? &names->places : nullptr, name, [&](std::string_view n) { return net.findPlace(n); },
      [&](std::string_view n) { return findPlaceNamed(net, n); });
}

std::optional<std::vector<TransitionId>> findTransitionsNamed(const Net& net, std::string_view name,
                                                              const NameExpansion* names) {
  return expanded<TransitionId>(
      names ? &names->transitions : nullptr, name, [&](std::string_view n) { return net.findTransition(n); },
      [&](std::string_view n) { return findTransitionNamed(net, n); });
}

std::optional<Formula> parseQuery(const Net& net, std::string_view text, QueryError& error, const NameExpansion* names) {
  Parser p(net, tokenize(text), names);
  auto f = p.whole();
  if (!f) error = p.error;
  return f;
}

std::string formulaText(const Net& net, const Formula& f, const NameExpansion* names) {
  // an operand in parentheses unless it is one word or a negation
  auto wrap = [&](const Formula& o) {
    // only a conjunction or a disjunction binds looser than what stands before it
    const bool plain = o.kind != FormulaKind::And && o.kind != FormulaKind::Or;
    return plain ? formulaText(net, o, names) : "(" + formulaText(net, o, names) + ")";
  };
  auto until = [&](const Formula& u) { return formulaText(net, u.operands[0], names) + " U " + formulaText(net, u.operands[1], names); };
  switch (f.kind) {
    case FormulaKind::True: return "true";
    case FormulaKind::False: return "false";
    case FormulaKind::Deadlock: return "deadlock";
    case FormulaKind::Fireable: {
      std::vector<std::string> ts;
      for (const TransitionId t : f.transitions) ts.push_back(net.transitionName(t));
      ts = collapsed(std::move(ts), names ? &names->transitions : nullptr);
      std::string out = "fireable(";
      for (std::size_t i = 0; i < ts.size(); ++i) out += (i ? ", " : "") + name(ts[i]);
      return out + ")";
    }
    case FormulaKind::Compare: {
      static constexpr const char* kOps[] = {"<", "<=", "=", "!=", ">=", ">"};
      return sumText(net, f.left, names) + " " + kOps[static_cast<int>(f.compare)] + " " + sumText(net, f.right, names);
    }
    case FormulaKind::Not: return "not " + wrap(f.operands[0]);
    case FormulaKind::And:
    case FormulaKind::Or: {
      std::string out;
      for (const Formula& o : f.operands) out += (out.empty() ? "" : f.kind == FormulaKind::And ? " and " : " or ") + wrap(o);
      return out;
    }
    case FormulaKind::All:
    case FormulaKind::Exists: {
      const std::string q = f.kind == FormulaKind::All ? "A" : "E";
      const Formula& path = f.operands[0];
      if (path.kind == FormulaKind::Until) return q + " [" + until(path) + "]";
      // EF p where p does not start with a path operator (else the LTL form, A (G F p))
      auto pathOp = [](const Formula& x) {
        return x.kind == FormulaKind::Next || x.kind == FormulaKind::Future || x.kind == FormulaKind::Globally ||
               x.kind == FormulaKind::Until;
      };
      const bool ctl = pathOp(path) && path.kind != FormulaKind::Until && !pathOp(path.operands[0]);
      if (ctl) return q + formulaText(net, path, names).substr(0, 1) + " " + wrap(path.operands[0]);
      return q + " (" + formulaText(net, path, names) + ")";
    }
    case FormulaKind::Next: return "X " + wrap(f.operands[0]);
    case FormulaKind::Future: return "F " + wrap(f.operands[0]);
    case FormulaKind::Globally: return "G " + wrap(f.operands[0]);
    case FormulaKind::Until: return "(" + until(f) + ")";
    case FormulaKind::Bound: return "bound(" + sumText(net, f.left, names) + ")";
  }
  return {};
}

bool isStateFormula(const Formula& f) {
  switch (f.kind) {
    case FormulaKind::Bound:  // over every reachable marking
    case FormulaKind::All:
    case FormulaKind::Exists:
    case FormulaKind::Next:
    case FormulaKind::Future:
    case FormulaKind::Globally:
    case FormulaKind::Until:
      return false;
    case FormulaKind::And:
    case FormulaKind::Compare:
    case FormulaKind::Deadlock:
    case FormulaKind::False:
    case FormulaKind::Fireable:
    case FormulaKind::Not:
    case FormulaKind::Or:
    case FormulaKind::True:
      break;
  }
  for (const Formula& o : f.operands) {
    if (!isStateFormula(o)) return false;
  }
  return true;
}

}  // namespace gdpn::net
