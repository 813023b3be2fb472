// The inscription language's text: a tokenizer that keeps each token's line and column, a
// recursive-descent parser of the grammar in net/inscription.h, and the printer back to text.

#include <algorithm>
#include <cctype>
#include <charconv>
#include <limits>

#include "gdpn/net/inscription.h"

namespace gdpn::net {
namespace {

enum class Tok : std::uint8_t { End, Name, Number, String, Punct };

struct Token {
  Tok kind = Tok::End;
  std::string text;  // a name, the digits, the string's contents (unescaped), the punctuation
  SourceLoc loc;
};

// how deep parentheses, `not`, `-` and the like may nest before the text is refused: each level
// takes a dozen frames of the parser, so this keeps hostile input far from the stack's end
constexpr int kMaxDepth = 200;

// how deep the tree may grow (long chains of `++` or `+` included): the checker, the evaluator
// and the printer walk it recursively
constexpr int kMaxTreeDepth = 2000;

// a mistake in the text: where and what (thrown inside the parser, caught at its entry)
struct SyntaxError {
  SourceLoc loc;
  std::string message;
};

bool nameStart(char c) { return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool nameChar(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }
bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

bool keyword(std::string_view w) {
  for (std::string_view k : {"if", "then", "else", "or", "and", "not", "true", "false", "dot", "empty", "all", "succ",
                             "pred"}) {
    if (w == k) return true;
  }
  return false;
}

class Lexer {
 public:
  Lexer(std::string_view text, const SourceLoc& at) : text_(text), at_(at) {}

  std::vector<Token> run() {
    std::vector<Token> out;
    while (true) {
      skipSpace();
      Token t;
      t.loc = here();
      if (i_ >= text_.size()) {
        out.push_back(std::move(t));
        return out;
      }
      const char c = text_[i_];
      if (nameStart(c)) {
        const std::size_t j = i_;
        while (i_ < text_.size() && nameChar(text_[i_])) advance();
        t.kind = Tok::Name;
        t.text = std::string(text_.substr(j, i_ - j));
      } else if (digit(c)) {
        const std::size_t j = i_;
        while (i_ < text_.size() && digit(text_[i_])) advance();
        t.kind = Tok::Number;
        t.text = std::string(text_.substr(j, i_ - j));
      } else if (c == '"') {
        t.kind = Tok::String;
        t.text = readString(t.loc);
      } else {
        t.kind = Tok::Punct;
        static constexpr std::string_view kTwo[] = {"++", "==", "<>", "!=", "<=", ">="};
        std::string_view op = text_.substr(i_, 1);
        for (std::string_view two : kTwo) {
          if (text_.substr(i_, 2) == two) op = two;
        }
        if (op == "!") throw SyntaxError{t.loc, "'!' is not part of the inscription language (write 'not')"};
        if (std::string_view("(){},.'=<>+-*/%").find(op[0]) == std::string_view::npos && op.size() == 1) {
          const auto u = static_cast<unsigned char>(op[0]);
          std::string shown = std::isprint(u) != 0 ? "'" + std::string(op) + "'" : "byte " + std::to_string(u);
          throw SyntaxError{t.loc, shown + " is not part of the inscription language"};
        }
        t.text = std::string(op);
        for (std::size_t k = 0; k < op.size(); ++k) advance();
      }
      out.push_back(std::move(t));
    }
  }

 private:
  SourceLoc here() const {
    SourceLoc l;
    l.file = at_.file;
    l.line = (at_.line > 0 ? at_.line : 1) + line_;
    l.column = line_ == 0 && at_.column > 0 ? at_.column + column_ : column_ + 1;
    return l;
  }
  void advance() {
    if (text_[i_] == '\n') {
      ++line_;
      column_ = 0;
    } else {
      ++column_;
    }
    ++i_;
  }
  void skipSpace() {
    while (i_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[i_])) != 0) advance();
  }
  std::string readString(const SourceLoc& start) {
    std::string s;
    advance();  // the opening quote
    while (true) {
      if (i_ >= text_.size() || text_[i_] == '\n') throw SyntaxError{start, "a string that is never closed"};
      const char c = text_[i_];
      if (c == '"') {
        advance();
        return s;
      }
      if (c == '\\') {
        const SourceLoc esc = here();
        advance();
        if (i_ >= text_.size()) throw SyntaxError{start, "a string that is never closed"};
        switch (text_[i_]) {
          case '"': s += '"'; break;
          case '\\': s += '\\'; break;
          case 'n': s += '\n'; break;
          case 't': s += '\t'; break;
          default: throw SyntaxError{esc, "unknown escape in a string (write \\\", \\\\, \\n or \\t)"};
        }
        advance();
        continue;
      }
      s += c;
      advance();
    }
  }

  std::string_view text_;
  SourceLoc at_;
  std::size_t i_ = 0;
  int line_ = 0;    // lines passed in the text
  int column_ = 0;  // characters passed on the current line
};

class Parser {
 public:
  explicit Parser(std::vector<Token> tokens) : toks_(std::move(tokens)) {}

  Expr whole() {
    Expr e = expr();
    if (peek().kind != Tok::End) fail("expected the end of the inscription, found " + shown(peek()));
    clearDepths(e);
    return e;
  }

 private:
  // one level deeper while alive: refuses text nested beyond kMaxDepth
  class Deeper {
   public:
    explicit Deeper(Parser& p) : p_(p) {
      if (++p_.depth_ > kMaxDepth) {
        p_.fail("the inscription nests deeper than " + std::to_string(kMaxDepth) + " levels");
      }
    }
    ~Deeper() { --p_.depth_; }
    Deeper(const Deeper&) = delete;
    Deeper& operator=(const Deeper&) = delete;

   private:
    Parser& p_;
  };

  const Token& peek() const { return toks_[pos_]; }
  bool isPunct(std::string_view p) const { return peek().kind == Tok::Punct && peek().text == p; }
  bool isWord(std::string_view w) const { return peek().kind == Tok::Name && peek().text == w; }
  Token take() {
    Token t = toks_[pos_];
    if (pos_ + 1 < toks_.size()) ++pos_;
    return t;
  }
  [[noreturn]] void fail(std::string message) const { throw SyntaxError{peek().loc, std::move(message)}; }
  static std::string shown(const Token& t) {
    switch (t.kind) {
      case Tok::End: return "end of the inscription";
      case Tok::Name: return "'" + t.text + "'";
      case Tok::Number: return "number " + t.text;
      case Tok::String: return "a string";
      case Tok::Punct: return "'" + t.text + "'";
    }
    return "?";
  }
  void expectPunct(std::string_view p, const std::string& what) {
    if (!isPunct(p)) fail("expected '" + std::string(p) + "' " + what + ", found " + shown(peek()));
    take();
  }
  void expectWord(std::string_view w, const std::string& what) {
    if (!isWord(w)) fail("expected '" + std::string(w) + "' " + what + ", found " + shown(peek()));
    take();
  }

  // while parsing, a node's `index` holds the depth of its tree (a leaf's -1 counts as 1), so
  // that a tree too deep is refused as it grows; whole() sets them back to -1
  void seal(Expr& e) const {
    int depth = 1;
    for (const Expr& a : e.args) depth = std::max(depth, std::max(a.index, 1) + 1);
    if (depth > kMaxTreeDepth) fail("the inscription nests deeper than " + std::to_string(kMaxTreeDepth) + " levels");
    e.index = depth;
  }
  static void clearDepths(Expr& e) {
    e.index = -1;
    for (Expr& a : e.args) clearDepths(a);
  }
  Expr node(Expr::Op op, const SourceLoc& loc, std::vector<Expr> args) const {
    Expr e;
    e.op = op;
    e.loc = loc;
    e.args = std::move(args);
    seal(e);
    return e;
  }
  Expr binary(Expr::Op op, Expr a, Expr b) const {
    SourceLoc loc = a.loc;
    std::vector<Expr> args;
    args.push_back(std::move(a));
    args.push_back(std::move(b));
    return node(op, loc, std::move(args));
  }

  // expr := 'if' expr 'then' expr 'else' expr | sum
  Expr expr() {
    const Deeper deeper(*this);
    if (isWord("if")) {
      const SourceLoc loc = take().loc;
      std::vector<Expr> args;
      args.push_back(expr());
      expectWord("then", "after the condition of 'if'");
      args.push_back(expr());
      expectWord("else", "after the 'then' branch");
      args.push_back(expr());
      return node(Expr::Op::If, loc, std::move(args));
    }
    return sum();
  }
  // sum := or ('++' or)*
  Expr sum() {
    Expr e = disjunction();
    while (isPunct("++")) {
      take();
      e = binary(Expr::Op::Sum, std::move(e), disjunction());
    }
    return e;
  }
  // or := and ('or' and)*
  Expr disjunction() {
    Expr e = conjunction();
    while (isWord("or")) {
      take();
      e = binary(Expr::Op::Or, std::move(e), conjunction());
    }
    return e;
  }
  // and := not ('and' not)*
  Expr conjunction() {
    Expr e = negation();
    while (isWord("and")) {
      take();
      e = binary(Expr::Op::And, std::move(e), negation());
    }
    return e;
  }
  // not := 'not' not | cmp
  Expr negation() {
    if (isWord("not")) {
      const Deeper deeper(*this);
      const SourceLoc loc = take().loc;
      std::vector<Expr> args;
      args.push_back(negation());
      return node(Expr::Op::Not, loc, std::move(args));
    }
    return comparison();
  }
  // cmp := add (op add)?
  Expr comparison() {
    Expr e = additive();
    if (peek().kind != Tok::Punct) return e;
    static constexpr std::pair<std::string_view, Expr::Op> kOps[] = {
        {"=", Expr::Op::Eq}, {"==", Expr::Op::Eq}, {"<>", Expr::Op::Ne}, {"!=", Expr::Op::Ne}, {"<", Expr::Op::Lt},
        {"<=", Expr::Op::Le}, {">", Expr::Op::Gt}, {">=", Expr::Op::Ge}};
    for (const auto& [text, op] : kOps) {
      if (peek().text == text) {
        take();
        e = binary(op, std::move(e), additive());
        for (const auto& [again, unused] : kOps) {
          if (isPunct(again)) fail("comparisons do not chain: put one of them in parentheses");
        }
        return e;
      }
    }
    return e;
  }
  // add := mul (('+' | '-') mul)*
  Expr additive() {
    Expr e = multiplicative();
    while (isPunct("+") || isPunct("-")) {
      const Expr::Op op = take().text == "+" ? Expr::Op::Add : Expr::Op::Sub;
      e = binary(op, std::move(e), multiplicative());
    }
    return e;
  }
  // mul := unary (('*' | '/' | '%') unary)*
  Expr multiplicative() {
    Expr e = unary();
    while (isPunct("*") || isPunct("/") || isPunct("%")) {
      const std::string op = take().text;
      const Expr::Op o = op == "*" ? Expr::Op::Mul : op == "/" ? Expr::Op::Div : Expr::Op::Mod;
      e = binary(o, std::move(e), unary());
    }
    return e;
  }
  // unary := '-' unary | times
  Expr unary() {
    if (isPunct("-")) {
      const Deeper deeper(*this);
      const SourceLoc loc = take().loc;
      std::vector<Expr> args;
      args.push_back(unary());
      return node(Expr::Op::Neg, loc, std::move(args));
    }
    return times();
  }
  // times := postfix ("'" postfix)?
  Expr times() {
    Expr e = postfix();
    if (isPunct("'")) {
      take();
      e = binary(Expr::Op::Times, std::move(e), postfix());
      if (isPunct("'")) fail("n'v takes one multiplicity: put the inner one in parentheses");
    }
    return e;
  }
  // postfix := primary ('.' field)*
  Expr postfix() {
    Expr e = primary();
    while (isPunct(".")) {
      take();
      if (peek().kind != Tok::Name || keyword(peek().text)) fail("expected a field's name after '.'");
      Token f = take();
      std::vector<Expr> args;
      args.push_back(std::move(e));
      const SourceLoc loc = args.front().loc;
      e = node(Expr::Op::Field, loc, std::move(args));
      e.name = std::move(f.text);
    }
    return e;
  }
  Expr primary() {
    const Token& t = peek();
    Expr e;
    e.loc = t.loc;
    switch (t.kind) {
      case Tok::End: fail("expected a value, found the end of the inscription");
      case Tok::Number: {
        std::int64_t n = 0;
        const auto [end, ec] = std::from_chars(t.text.data(), t.text.data() + t.text.size(), n);
        if (ec != std::errc() || end != t.text.data() + t.text.size()) {
          fail("number " + t.text + " is too large (at most " +
               std::to_string(std::numeric_limits<std::int64_t>::max()) + ")");
        }
        take();
        e.value = Value::integer(n);
        e.type = Colours::kInt;
        return e;
      }
      case Tok::String:
        e.value = Value::string(take().text);
        e.type = Colours::kString;
        return e;
      case Tok::Punct: return punctuated();
      case Tok::Name: break;
    }
    const std::string w = t.text;
    if (w == "true" || w == "false") {
      take();
      e.value = Value::boolean(w == "true");
      e.type = Colours::kBool;
      return e;
    }
    if (w == "dot") {
      take();
      e.value = Value::dot();
      e.type = Colours::kDot;
      return e;
    }
    if (w == "empty") {
      take();
      e.op = Expr::Op::Empty;
      return e;
    }
    if (w == "all") {
      take();
      e.op = Expr::Op::All;
      if (isPunct("(")) {
        take();
        if (peek().kind != Tok::Name || keyword(peek().text)) fail("expected a colour set's name after 'all('");
        e.name = take().text;
        expectPunct(")", "after the colour set of 'all'");
      }
      return e;
    }
    if (w == "succ" || w == "pred") {
      take();
      e.op = w == "succ" ? Expr::Op::Succ : Expr::Op::Pred;
      expectPunct("(", "after '" + w + "'");
      e.args.push_back(expr());
      expectPunct(")", "after the operand of '" + w + "'");
      seal(e);
      return e;
    }
    if (keyword(w)) fail("expected a value, found '" + w + "'");
    e.op = Expr::Op::Name;
    e.name = take().text;
    return e;
  }
  // '(' expr (',' expr)* ')' and '{' field '=' expr (',' field '=' expr)* '}'
  Expr punctuated() {
    Expr e;
    e.loc = peek().loc;
    if (isPunct("(")) {
      take();
      std::vector<Expr> parts;
      parts.push_back(expr());
      while (isPunct(",")) {
        take();
        parts.push_back(expr());
      }
      if (parts.size() == 1) {
        expectPunct(")", "after the expression in parentheses");
        return std::move(parts.front());
      }
      expectPunct(")", "after the tuple's components");
      e.op = Expr::Op::Tuple;
      e.args = std::move(parts);
      seal(e);
      return e;
    }
    if (isPunct("{")) {
      take();
      e.op = Expr::Op::Record;
      while (true) {
        if (peek().kind != Tok::Name || keyword(peek().text)) fail("expected a field's name in the record");
        e.fields.push_back(take().text);
        expectPunct("=", "after the field's name");
        e.args.push_back(expr());
        if (!isPunct(",")) break;
        take();
      }
      expectPunct("}", "after the record's fields");
      seal(e);
      return e;
    }
    fail("expected a value, found " + shown(peek()));
  }

  std::vector<Token> toks_;
  std::size_t pos_ = 0;
  int depth_ = 0;
};

// how tightly each node binds when written: a child looser than its place needs parentheses
enum Level : int { kIf = 0, kSum, kOr, kAnd, kNot, kCmp, kAdd, kMul, kUnary, kTimes, kPostfix, kPrimary };

int level(const Expr& e) {
  switch (e.op) {
    case Expr::Op::If: return kIf;
    case Expr::Op::Sum: return kSum;
    case Expr::Op::Or: return kOr;
    case Expr::Op::And: return kAnd;
    case Expr::Op::Not: return kNot;
    case Expr::Op::Eq:
    case Expr::Op::Ne:
    case Expr::Op::Lt:
    case Expr::Op::Le:
    case Expr::Op::Gt:
    case Expr::Op::Ge: return kCmp;
    case Expr::Op::Add:
    case Expr::Op::Sub: return kAdd;
    case Expr::Op::Mul:
    case Expr::Op::Div:
    case Expr::Op::Mod: return kMul;
    case Expr::Op::Neg: return kUnary;
    case Expr::Op::Times: return kTimes;
    case Expr::Op::Field: return kPostfix;
    case Expr::Op::Const:
      // a negative number is written with its sign: a unary minus, as the parser reads it
      return e.value.tag == Value::Tag::Int && e.value.i < 0 ? kUnary : kPrimary;
    case Expr::Op::Name:
    case Expr::Op::Var:
    case Expr::Op::Tuple:
    case Expr::Op::Record:
    case Expr::Op::Succ:
    case Expr::Op::Pred:
    case Expr::Op::All:
    case Expr::Op::Empty: return kPrimary;
  }
  return kPrimary;
}

const char* binaryText(Expr::Op op) {
  switch (op) {
    case Expr::Op::Sum: return " ++ ";
    case Expr::Op::Or: return " or ";
    case Expr::Op::And: return " and ";
    case Expr::Op::Eq: return " = ";
    case Expr::Op::Ne: return " <> ";
    case Expr::Op::Lt: return " < ";
    case Expr::Op::Le: return " <= ";
    case Expr::Op::Gt: return " > ";
    case Expr::Op::Ge: return " >= ";
    case Expr::Op::Add: return " + ";
    case Expr::Op::Sub: return " - ";
    case Expr::Op::Mul: return " * ";
    case Expr::Op::Div: return " / ";
    case Expr::Op::Mod: return " % ";
    case Expr::Op::Times: return "'";
    case Expr::Op::Const:
    case Expr::Op::Name:
    case Expr::Op::Var:
    case Expr::Op::Tuple:
    case Expr::Op::Record:
    case Expr::Op::Field:
    case Expr::Op::Neg:
    case Expr::Op::Not:
    case Expr::Op::If:
    case Expr::Op::Succ:
    case Expr::Op::Pred:
    case Expr::Op::All:
    case Expr::Op::Empty: break;
  }
  return " ? ";
}

class Printer {
 public:
  Printer(const Colours& colours, const std::vector<std::string>* names) : colours_(colours), names_(names) {}

  // `e` where a node of at least `min` binds without parentheses
  void write(const Expr& e, int min) {
    const bool parens = level(e) < min;
    if (parens) out_ += '(';
    body(e);
    if (parens) out_ += ')';
  }
  std::string take() { return std::move(out_); }

 private:
  void body(const Expr& e) {
    switch (e.op) {
      case Expr::Op::Const: out_ += colours_.text(e.type, e.value); return;
      case Expr::Op::Name: out_ += e.name; return;
      case Expr::Op::Var:
        if (names_ != nullptr && e.index >= 0 && static_cast<std::size_t>(e.index) < names_->size()) {
          out_ += (*names_)[static_cast<std::size_t>(e.index)];
        } else {
          out_ += "$" + std::to_string(e.index);
        }
        return;
      case Expr::Op::Tuple:
        out_ += '(';
        for (std::size_t i = 0; i < e.args.size(); ++i) {
          if (i > 0) out_ += ", ";
          write(e.args[i], kIf);
        }
        out_ += ')';
        return;
      case Expr::Op::Record:
        out_ += '{';
        for (std::size_t i = 0; i < e.args.size(); ++i) {
          if (i > 0) out_ += ", ";
          out_ += i < e.fields.size() ? e.fields[i] : std::string("?");
          out_ += " = ";
          write(e.args[i], kIf);
        }
        out_ += '}';
        return;
      case Expr::Op::Field:
        write(e.args[0], kPostfix);
        out_ += "." + e.name;
        return;
      case Expr::Op::Neg: {
        out_ += '-';
        const std::size_t at = out_.size();
        write(e.args[0], kUnary);
        if (at < out_.size() && out_[at] == '-') out_.insert(at, " ");
        return;
      }
      case Expr::Op::Not:
        out_ += "not ";
        write(e.args[0], kNot);
        return;
      case Expr::Op::Sum:
      case Expr::Op::Or:
      case Expr::Op::And:
      case Expr::Op::Add:
      case Expr::Op::Sub:
      case Expr::Op::Mul:
      case Expr::Op::Div:
      case Expr::Op::Mod:
        // left-associative: the right operand one level tighter
        write(e.args[0], level(e));
        out_ += binaryText(e.op);
        write(e.args[1], level(e) + 1);
        return;
      case Expr::Op::Eq:
      case Expr::Op::Ne:
      case Expr::Op::Lt:
      case Expr::Op::Le:
      case Expr::Op::Gt:
      case Expr::Op::Ge:
        write(e.args[0], kAdd);
        out_ += binaryText(e.op);
        write(e.args[1], kAdd);
        return;
      case Expr::Op::Times:
        write(e.args[0], kPostfix);
        out_ += "'";
        write(e.args[1], kPostfix);
        return;
      case Expr::Op::If:
        out_ += "if ";
        write(e.args[0], kIf);
        out_ += " then ";
        write(e.args[1], kIf);
        out_ += " else ";
        write(e.args[2], kIf);
        return;
      case Expr::Op::Succ:
      case Expr::Op::Pred:
        out_ += e.op == Expr::Op::Succ ? "succ(" : "pred(";
        write(e.args[0], kIf);
        out_ += ')';
        return;
      case Expr::Op::All:
        out_ += "all";
        if (!e.name.empty()) out_ += "(" + e.name + ")";
        return;
      case Expr::Op::Empty: out_ += "empty"; return;
    }
  }

  const Colours& colours_;
  const std::vector<std::string>* names_;
  std::string out_;
};

}  // namespace

std::optional<Expr> parseInscription(std::string_view text, const SourceLoc& at, core::Diagnostics& diags) {
  try {
    Parser parser(Lexer(text, at).run());
    return parser.whole();
  } catch (const SyntaxError& e) {
    diags.error(e.loc, e.message);
    return std::nullopt;
  }
}

namespace {
void relocate(Expr& e, const SlotText& text) {
  e.loc = text.where(e.loc);
  for (auto& a : e.args) relocate(a, text);
}
}  // namespace

std::optional<Expr> parseInscription(const SlotText& text, core::Diagnostics& diags) {
  core::Diagnostics found;
  auto e = parseInscription(text.text, SourceLoc{text.loc.file, 1, 1}, found);
  for (const auto& d : found.all()) {
    switch (d.severity) {
      case core::Severity::Error: diags.error(text.where(d.loc), d.message); break;
      case core::Severity::Warning: diags.warning(text.where(d.loc), d.message); break;
      case core::Severity::Note: diags.note(text.where(d.loc), d.message); break;
    }
  }
  if (e) relocate(*e, text);
  return e;
}

std::string inscriptionText(const Expr& e, const Colours& colours, const std::vector<std::string>* names) {
  Printer p(colours, names);
  p.write(e, kIf);
  return p.take();
}

}  // namespace gdpn::net
