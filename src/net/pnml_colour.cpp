// PNML symmetric nets, the high-level parts in: declarations into colour sets and variables,
// terms into the inscription language's text (detail/pnml_colour.h).

#include <charconv>
#include <cstdint>

#include "detail/pnml_colour.h"
#include "gdpn/core/text.h"
#include "gdpn/net/inscription.h"
#include "gdpn/net/pnml.h"

namespace gdpn::net::detail {
namespace {

/// Words a declaration may not be called: the language's keywords and built-in sets.
constexpr const char* kReserved[] = {"if",  "then", "else", "or",   "and", "not",  "true",   "false", "dot",
                                     "empty", "all", "succ", "pred", "int", "bool", "string", "integer"};

/// The operands of term `e`: the element inside each `<subterm>`.
std::vector<const XmlElement*> operands(const XmlElement& e) {
  std::vector<const XmlElement*> out;
  for (const auto& c : e.children) {
    if (c->name == "subterm" && !c->children.empty()) out.push_back(c->children[0].get());
  }
  return out;
}

/// The first child of `e` that is neither `<text>` nor `<graphics>` nor `<toolspecific>`.
const XmlElement* firstTerm(const XmlElement& e) {
  for (const auto& c : e.children) {
    if (c->name != "text" && c->name != "graphics" && c->name != "toolspecific") return c.get();
  }
  return nullptr;
}

}  // namespace

bool isSymmetricNet(const std::string& type) { return type.find("symmetricnet") != std::string::npos; }

std::nullopt_t PnmlColourReader::fail(const XmlElement& e, const std::string& message) {
  diags_.error(e.loc, message);
  return std::nullopt;
}

std::string PnmlColourReader::nameFor(const std::string& pnml_name, const std::string& id) {
  if (used_.empty()) used_.insert(std::begin(kReserved), std::end(kReserved));
  if (core::isIdentifier(pnml_name) && !used_.count(pnml_name)) {
    used_.insert(pnml_name);
    return pnml_name;
  }
  std::string n = pnmlName(id);
  while (used_.count(n)) n += "_";
  used_.insert(n);
  return n;
}

void PnmlColourReader::declarations(const XmlElement& net, NetSpec& spec) {
  // every <declarations> list, in document order (the net's, then its pages')
  std::vector<const XmlElement*> lists;
  auto gather = [&](const XmlElement& el, auto&& self) -> void {
    for (const auto& c : el.children) {
      if (c->name == "declaration") {
        const XmlElement* s = c->child("structure");
        const XmlElement* d = s ? s->child("declarations") : nullptr;
        if (d) lists.push_back(d);
        else fail(*c, "a <declaration> holds <structure><declarations>...");
      } else if (c->name == "page") {
        self(*c, self);
      }
    }
  };
  gather(net, gather);
  // names first, so that a sort may name one declared after it
  for (const XmlElement* list : lists) {
    for (const auto& d : list->children) {
      const std::string* id = d->attr("id");
      const std::string* name = d->attr("name");
      if (!id || id->empty()) {
        fail(*d, "<" + d->name + "> has no id");
        continue;
      }
      const std::string n = name ? *name : *id;
      if (d->name == "namedsort") {
        sorts_[*id] = nameFor(n, *id);
        if (const XmlElement* body = firstTerm(*d)) {
          for (const auto& c : body->children) {
            const std::string* cid = c->attr("id");
            const std::string* cname = c->attr("name");
            if (c->name != "feconstant") continue;
            if (!cid || cid->empty()) {
              fail(*c, "<feconstant> has no id");
              continue;
            }
            constants_[*cid] = nameFor(cname ? *cname : *cid, *cid);
          }
        }
      } else if (d->name == "variabledecl") {
        variables_[*id] = nameFor(n, *id);
      }
    }
  }
  for (const XmlElement* list : lists) {
    for (const auto& dp : list->children) {
      const XmlElement& d = *dp;
      const std::string* id = d.attr("id");
      if (!id || id->empty()) continue;
      if (d.name == "namedsort") {
        ColourSetSpec s;
        s.name = sorts_.at(*id);
        s.pnml_id = s.name == *id ? std::string() : *id;
        s.loc = d.loc;
        const XmlElement* body = firstTerm(d);
        if (!body) {
          fail(d, "<namedsort> '" + *id + "' declares no sort");
          continue;
        }
        const std::string& k = body->name;
        if (k == "dot") {
          s.kind = ColourKind::Dot;
          dots_.insert(s.name);
        } else if (k == "bool") {
          s.kind = ColourKind::Bool;
        } else if (k == "finiteintrange") {
          s.kind = ColourKind::Integer;
          s.range = true;
          const std::string* lo = body->attr("start");
          const std::string* hi = body->attr("end");
          auto number = [&](const std::string* t, std::int64_t& out) {
            if (!t) return false;
            const auto [ptr, ec] = std::from_chars(t->data(), t->data() + t->size(), out);
            return ec == std::errc() && ptr == t->data() + t->size();
          };
          if (!number(lo, s.lo) || !number(hi, s.hi)) {
            fail(*body, "<finiteintrange> needs whole numbers start and end");
            continue;
          }
        } else if (k == "cyclicenumeration" || k == "finiteenumeration") {
          s.kind = ColourKind::Enum;
          s.cyclic = k == "cyclicenumeration";
          for (const auto& c : body->children) {
            const std::string* cid = c->attr("id");
            if (c->name != "feconstant" || !cid || !constants_.count(*cid)) continue;
            s.constants.push_back(constants_.at(*cid));
            s.constant_pnml_ids.push_back(s.constants.back() == *cid ? std::string() : *cid);
          }
          bool renamed = false;
          for (const auto& c : s.constant_pnml_ids) renamed = renamed || !c.empty();
          if (!renamed) s.constant_pnml_ids.clear();
        } else if (k == "productsort") {
          s.kind = ColourKind::Product;
          bool ok = true;
          for (const auto& c : body->children) {
            auto part = sortName(*c);
            if (!part) ok = false;
            else s.components.push_back(*part);
          }
          if (!ok) continue;
        } else if (k == "usersort") {
          // another name for a declared sort: its copy under this name
          auto other = sortName(*body);
          if (!other) continue;
          bool found = false;
          for (const auto& o : spec.colours) {
            if (o.name != *other) continue;
            const std::string name = s.name, pid = s.pnml_id;
            s = o;
            s.name = name, s.pnml_id = pid, s.loc = d.loc;
            s.constants.clear(), s.constant_pnml_ids.clear();
            if (o.kind == ColourKind::Enum) {
              fail(*body, "a namedsort of another enumeration is not supported (its constants would be declared twice)");
              found = false;
              break;
            }
            found = true;
          }
          if (!found) {
            fail(*body, "<usersort> names sort '" + *body->attr("declaration") + "', which is not declared before it");
            continue;
          }
        } else {
          fail(*body, "sort <" + k + "> is not supported (dot, bool, finiteintrange, cyclicenumeration, "
                                     "finiteenumeration, productsort)");
          continue;
        }
        spec.colours.push_back(std::move(s));
      } else if (d.name == "variabledecl") {
        VariableSpec v;
        v.name = variables_.at(*id);
        v.pnml_id = v.name == *id ? std::string() : *id;
        v.loc = d.loc;
        const XmlElement* sort = firstTerm(d);
        auto set = sort ? sortName(*sort) : fail(d, "<variabledecl> '" + *id + "' names no sort");
        if (!set) continue;
        v.colour = *set;
        spec.variables.push_back(std::move(v));
      } else if (d.name == "namedoperator" || d.name == "partition") {
        fail(d, "<" + d.name + "> declarations are not supported");
      }
    }
  }
}

std::optional<std::string> PnmlColourReader::sortName(const XmlElement& sort) {
  if (sort.name == "usersort") {
    const std::string* to = sort.attr("declaration");
    if (!to) return fail(sort, "<usersort> has no declaration");
    const auto at = sorts_.find(*to);
    if (at == sorts_.end()) return fail(sort, "<usersort> names '" + *to + "', which no namedsort declares");
    return at->second;
  }
  if (sort.name == "dot") return std::string("dot");
  if (sort.name == "bool") return std::string("bool");
  return fail(sort, "a sort here is a <usersort> of a namedsort (or <dot/>, <bool/>), not <" + sort.name + ">");
}

std::optional<std::string> PnmlColourReader::placeSort(const XmlElement& type) {
  const XmlElement* s = type.child("structure");
  const XmlElement* sort = s ? firstTerm(*s) : nullptr;
  if (!sort) return fail(type, "a place's <type> holds <structure> with a sort");
  return sortName(*sort);
}

std::optional<std::string> PnmlColourReader::term(const XmlElement& label) {
  const XmlElement* s = label.child("structure");
  const XmlElement* t = s ? firstTerm(*s) : nullptr;
  if (!t) return fail(label, "<" + label.name + "> holds <structure> with a term");
  auto r = render(*t, 0);
  if (!r) return std::nullopt;
  return r->text;
}

std::optional<std::string> PnmlColourReader::operand(const XmlElement& e, int level, int depth) {
  auto r = render(e, depth + 1);
  if (!r) return std::nullopt;
  return r->level < level ? "(" + r->text + ")" : r->text;
}

std::optional<PnmlColourReader::Text> PnmlColourReader::render(const XmlElement& e, int depth) {
  if (depth > 200) return fail(e, "the term is nested more than 200 levels deep");
  const std::string& n = e.name;
  const auto ops = operands(e);
  auto arity = [&](std::size_t k) {
    if (ops.size() == k) return true;
    fail(e, "<" + n + "> takes " + std::to_string(k) + " subterm" + (k == 1 ? "" : "s") + ", not " +
                std::to_string(ops.size()));
    return false;
  };
  // binary operators: (element, language, level of the result, level of the operands)
  struct Binary {
    const char* element;
    const char* op;
    int level, operand_level;
  };
  static constexpr Binary kBinary[] = {
      {"equality", " = ", 4, 5},         {"inequality", " <> ", 4, 5},       {"lessthan", " < ", 4, 5},
      {"lessthanorequal", " <= ", 4, 5}, {"greaterthan", " > ", 4, 5},       {"greaterthanorequal", " >= ", 4, 5},
      // associative: an operand of the same operator needs no parentheses
      {"and", " and ", 2, 2},            {"or", " or ", 1, 1},               {"add", " ++ ", 0, 0},
  };
  for (const auto& b : kBinary) {
    if (n != b.element) continue;
    const bool many = n == "and" || n == "or" || n == "add";
    if (many ? ops.empty() : !arity(2)) {
      if (many) fail(e, "<" + n + "> takes one subterm or more");
      return std::nullopt;
    }
    Text out{{}, b.level};
    for (std::size_t i = 0; i < ops.size(); ++i) {
      auto o = operand(*ops[i], b.operand_level, depth);
      if (!o) return std::nullopt;
      out.text += (i ? b.op : "") + *o;
    }
    if (ops.size() == 1) return render(*ops[0], depth + 1);
    return out;
  }
  if (n == "not") {
    if (!arity(1)) return std::nullopt;
    auto o = operand(*ops[0], 3, depth);
    if (!o) return std::nullopt;
    return Text{"not " + *o, 3};
  }
  if (n == "numberof") {
    if (!arity(2)) return std::nullopt;
    if (ops[0]->name != "numberconstant") return fail(*ops[0], "<numberof> counts with a <numberconstant>");
    auto count = operand(*ops[0], 7, depth);
    auto what = operand(*ops[1], 7, depth);
    if (!count || !what) return std::nullopt;
    return Text{*count + "'" + *what, 6};
  }
  if (n == "numberconstant" || n == "finiteintrangeconstant") {
    const std::string* v = e.attr("value");
    std::int64_t x = 0;
    const auto read = v ? std::from_chars(v->data(), v->data() + v->size(), x) : std::from_chars_result{};
    if (!v || v->empty() || read.ptr != v->data() + v->size()) return fail(e, "<" + n + "> needs a whole number value");
    if (read.ec != std::errc{}) return fail(e, "<" + n + "> value " + *v + " is too large (64-bit whole numbers)");
    return Text{std::to_string(x), x < 0 ? 5 : 7};
  }
  if (n == "booleanconstant") {
    const std::string* v = e.attr("value");
    if (!v || (*v != "true" && *v != "false")) return fail(e, "<booleanconstant> has value \"true\" or \"false\"");
    return Text{*v, 7};
  }
  if (n == "dotconstant") return Text{"dot", 7};
  if (n == "variable") {
    const std::string* v = e.attr("refvariable");
    const auto at = v ? variables_.find(*v) : variables_.end();
    if (at == variables_.end()) {
      return fail(e, "<variable> refers to '" + (v ? *v : std::string()) + "', which no variabledecl declares");
    }
    return Text{at->second, 7};
  }
  if (n == "useroperator") {
    const std::string* v = e.attr("declaration");
    const auto at = v ? constants_.find(*v) : constants_.end();
    if (at == constants_.end()) {
      return fail(e, "<useroperator> refers to '" + (v ? *v : std::string()) + "', which is no feconstant");
    }
    return Text{at->second, 7};
  }
  if (n == "successor" || n == "predecessor") {
    if (!arity(1)) return std::nullopt;
    auto o = operand(*ops[0], 0, depth);
    if (!o) return std::nullopt;
    return Text{std::string(n == "successor" ? "succ" : "pred") + "(" + *o + ")", 7};
  }
  if (n == "tuple") {
    if (ops.empty()) return fail(e, "<tuple> takes one subterm or more");
    std::string out = "(";
    for (std::size_t i = 0; i < ops.size(); ++i) {
      auto o = operand(*ops[i], 1, depth);
      if (!o) return std::nullopt;
      out += (i ? ", " : "") + *o;
    }
    if (ops.size() == 1) return render(*ops[0], depth + 1);
    return Text{out + ")", 7};
  }
  if (n == "all") {
    const XmlElement* sort = firstTerm(e);
    if (!sort) return fail(e, "<all> names a sort");
    auto set = sortName(*sort);
    if (!set) return std::nullopt;
    // the built-ins' names are words of the language
    if (*set == "dot") return Text{"dot", 7};
    if (*set == "bool") return Text{"false ++ true", 0};
    return Text{"all(" + *set + ")", 7};
  }
  if (n == "subtract") {
    return fail(e, "<subtract> (a multiset's difference) has no counterpart in gdpn's inscription language");
  }
  return fail(e, "term <" + n + "> is not supported in a symmetric net");
}

// ---- out -----------------------------------------------------------------------------------

namespace {

/// `s` escaped for XML.
std::string esc(std::string_view s) { return core::xmlEscape(s); }

/// Writes a term of the language (as parsed, names unresolved) as PNML.
class TermWriter {
 public:
  TermWriter(const NetSpec& spec, std::string& why) : why_(why) {
    for (const auto& c : spec.colours) {
      sorts_[c.name] = declarationId(c.name, c.pnml_id);
      for (std::size_t i = 0; i < c.constants.size(); ++i) {
        const std::string& id = i < c.constant_pnml_ids.size() ? c.constant_pnml_ids[i] : std::string();
        constants_[c.constants[i]] = declarationId(c.constants[i], id);
      }
    }
    for (const auto& v : spec.variables) variables_[v.name] = declarationId(v.name, v.pnml_id);
  }

  std::optional<std::string> term(const Expr& e) {
    using Op = Expr::Op;
    auto sub = [&](const Expr& x) -> std::optional<std::string> {
      auto t = term(x);
      if (!t) return std::nullopt;
      return "<subterm>" + *t + "</subterm>";
    };
    auto element = [&](const std::string& name, const std::vector<const Expr*>& args) -> std::optional<std::string> {
      std::string out = "<" + name + ">";
      for (const Expr* a : args) {
        auto t = sub(*a);
        if (!t) return std::nullopt;
        out += *t;
      }
      return out + "</" + name + ">";
    };
    auto flat = [&](const Expr& x, Op op) {
      std::vector<const Expr*> out;
      auto walk = [&](const Expr& y, auto&& self) -> void {
        if (y.op == op) {
          for (const auto& a : y.args) self(a, self);
        } else {
          out.push_back(&y);
        }
      };
      walk(x, walk);
      return out;
    };
    switch (e.op) {
      case Op::Const:
        switch (e.value.tag) {
          case Value::Tag::Dot: return std::string("<dotconstant/>");
          case Value::Tag::Bool: return "<booleanconstant value=\"" + std::string(e.value.i ? "true" : "false") + "\"/>";
          case Value::Tag::Int:
            return "<numberconstant value=\"" + std::to_string(e.value.i) + "\">" +
                   (e.value.i > 0 ? "<positive/>" : "<natural/>") + "</numberconstant>";
          case Value::Tag::String:
          case Value::Tag::Tuple: break;
        }
        return refuse(e, "a value that is no number, boolean or dot");
      case Op::Name: {
        if (const auto v = variables_.find(e.name); v != variables_.end()) {
          return "<variable refvariable=\"" + esc(v->second) + "\"/>";
        }
        if (const auto c = constants_.find(e.name); c != constants_.end()) {
          return "<useroperator declaration=\"" + esc(c->second) + "\"/>";
        }
        return refuse(e, "'" + e.name + "', which is neither a variable nor a constant");
      }
      case Op::Var: return refuse(e, "a resolved variable");
      case Op::Tuple: {
        std::vector<const Expr*> args;
        for (const auto& a : e.args) args.push_back(&a);
        return element("tuple", args);
      }
      case Op::Times: return element("numberof", {&e.args[0], &e.args[1]});
      case Op::Sum: return element("add", flat(e, Op::Sum));
      case Op::And: return element("and", flat(e, Op::And));
      case Op::Or: return element("or", flat(e, Op::Or));
      case Op::Not: return element("not", {&e.args[0]});
      case Op::Eq: return element("equality", {&e.args[0], &e.args[1]});
      case Op::Ne: return element("inequality", {&e.args[0], &e.args[1]});
      case Op::Lt: return element("lessthan", {&e.args[0], &e.args[1]});
      case Op::Le: return element("lessthanorequal", {&e.args[0], &e.args[1]});
      case Op::Gt: return element("greaterthan", {&e.args[0], &e.args[1]});
      case Op::Ge: return element("greaterthanorequal", {&e.args[0], &e.args[1]});
      case Op::Succ: return element("successor", {&e.args[0]});
      case Op::Pred: return element("predecessor", {&e.args[0]});
      case Op::All: {
        const auto s = sorts_.find(e.name);
        if (s == sorts_.end()) return refuse(e, "'all' of no declared colour set");
        return "<all><usersort declaration=\"" + esc(s->second) + "\"/></all>";
      }
      case Op::Record:
      case Op::Field:
      case Op::Neg:
      case Op::Add:
      case Op::Sub:
      case Op::Mul:
      case Op::Div:
      case Op::Mod:
      case Op::If:
      case Op::Empty: break;
    }
    return refuse(e, "an operator a symmetric net has no term for");
  }

 private:
  std::nullopt_t refuse(const Expr& e, const std::string& what) {
    if (why_.empty()) why_ = "column " + std::to_string(e.loc.column) + ": " + what;
    return std::nullopt;
  }

  std::string& why_;
  std::map<std::string, std::string> sorts_, constants_, variables_;  // name -> PNML id
};

}  // namespace

std::string sortXml(const NetSpec& spec, const std::string& set) {
  if (set == "dot") return "<dot/>";
  if (set == "bool") return "<bool/>";
  for (const auto& c : spec.colours) {
    if (c.name == set) return "<usersort declaration=\"" + esc(declarationId(c.name, c.pnml_id)) + "\"/>";
  }
  return "<usersort declaration=\"" + esc(set) + "\"/>";
}

std::optional<std::string> termXml(const NetSpec& spec, const std::string& text, std::string& why) {
  core::Diagnostics diags;
  auto e = parseInscription(text, core::SourceLoc{"", 1, 1}, diags);
  if (!e) {
    why = diags.str();
    return std::nullopt;
  }
  why.clear();
  TermWriter w(spec, why);
  return w.term(*e);
}

std::string declarationsXml(const NetSpec& spec) {
  if (spec.colours.empty() && spec.variables.empty()) return {};
  std::string out = "    <declaration><structure><declarations>\n";
  for (const auto& c : spec.colours) {
    const std::string& id = declarationId(c.name, c.pnml_id);
    out += "      <namedsort id=\"" + esc(id) + "\" name=\"" + esc(c.name) + "\">";
    switch (c.kind) {
      case ColourKind::Dot: out += "<dot/>"; break;
      case ColourKind::Bool: out += "<bool/>"; break;
      case ColourKind::Integer:
        out += "<finiteintrange start=\"" + std::to_string(c.lo) + "\" end=\"" + std::to_string(c.hi) + "\"/>";
        break;
      case ColourKind::Enum:
        out += c.cyclic ? "<cyclicenumeration>" : "<finiteenumeration>";
        for (std::size_t i = 0; i < c.constants.size(); ++i) {
          const std::string& cid = i < c.constant_pnml_ids.size() ? c.constant_pnml_ids[i] : std::string();
          out += "<feconstant id=\"" + esc(declarationId(c.constants[i], cid)) + "\" name=\"" + esc(c.constants[i]) +
                 "\"/>";
        }
        out += c.cyclic ? "</cyclicenumeration>" : "</finiteenumeration>";
        break;
      case ColourKind::Product:
        out += "<productsort>";
        for (const auto& part : c.components) out += sortXml(spec, part);
        out += "</productsort>";
        break;
      case ColourKind::String:
      case ColourKind::Record: break;
    }
    out += "</namedsort>\n";
  }
  for (const auto& v : spec.variables) {
    out += "      <variabledecl id=\"" + esc(declarationId(v.name, v.pnml_id)) + "\" name=\"" + esc(v.name) + "\">" +
           sortXml(spec, v.colour) + "</variabledecl>\n";
  }
  return out + "    </declarations></structure></declaration>\n";
}

}  // namespace gdpn::net::detail
