// Value tokens edited in the IDE: the declarations checked and replaced as one step, the
// inscription texts checked as typed, and what completion offers in them.

#include "gdpn/ide/colour_edit.h"

#include <algorithm>
#include <cctype>
#include <set>

#include "gdpn/core/text.h"
#include "gdpn/ide/document.h"
#include "gdpn/model/colour_text.h"

namespace gdpn::ide {
namespace {

/// Every page and page type of `net`.
template <class F>
void forEachPage(const net::NetSpec& net, F&& f) {
  for (const auto& p : net.pages) f(p);
  for (const auto& p : net.page_types) f(p);
}

/// The names in inscription `text` (words outside strings that do not follow a dot).
std::set<std::string> namesIn(std::string_view text) {
  std::set<std::string> out;
  bool in_string = false;
  for (std::size_t i = 0; i < text.size();) {
    const char c = text[i];
    if (in_string) {
      if (c == '\\') i += 2;
      else {
        if (c == '"') in_string = false;
        ++i;
      }
      continue;
    }
    if (c == '"') {
      in_string = true;
      ++i;
      continue;
    }
    if (std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_') {
      std::size_t j = i;
      while (j < text.size() && (std::isalnum(static_cast<unsigned char>(text[j])) != 0 || text[j] == '_')) ++j;
      if (i == 0 || text[i - 1] != '.') out.emplace(text.substr(i, j - i));
      i = j;
      continue;
    }
    ++i;
  }
  return out;
}

/// The first diagnostic of `diags` as a problem in a text whose first character is at line 1,
/// column 1 of file "inscription".
TextProblem firstProblem(const core::Diagnostics& diags) {
  for (const auto& d : diags.all()) {
    if (d.severity == core::Severity::Error) return {std::max(0, d.loc.line), std::max(0, d.loc.column), d.message};
  }
  return {};
}

/// The words of the language completion offers at the start of a word, with their lines.
struct Word {
  const char* name;
  const char* kind;
  const char* detail;
  const char* signature;
};
constexpr Word kWords[] = {
    {"succ", "function", "the next constant of an enumeration (wrapping when cyclic) or number of a range", "(x)"},
    {"pred", "function", "the previous constant of an enumeration (wrapping when cyclic) or number of a range", "(x)"},
    {"all", "keyword", "every value of a finite set once; all(Set), or alone the set of its place", ""},
    {"empty", "keyword", "no tokens", ""},
    {"dot", "keyword", "the plain token's value", ""},
    {"true", "keyword", "a bool", ""},
    {"false", "keyword", "a bool", ""},
    {"if", "keyword", "if c then a else b: a where the bool c holds, else b", ""},
    {"then", "keyword", "if c then a else b", ""},
    {"else", "keyword", "if c then a else b", ""},
    {"and", "keyword", "both bools hold", ""},
    {"or", "keyword", "either bool holds", ""},
    {"not", "keyword", "the bool does not hold", ""},
};

}  // namespace

ColourScope colourScopeOf(const net::NetSpec& net) {
  ColourScope out;
  core::Diagnostics diags;
  if (!out.colours.declare(net.colours, diags)) out.error = firstProblem(diags).message;
  std::set<std::string> seen;
  for (const auto& v : net.variables) {
    const auto set = out.colours.find(v.colour);
    if (!seen.insert(v.name).second || out.colours.find(v.name) || out.colours.constant(v.name) || !set) {
      if (out.error.empty()) out.error = "variable '" + v.name + "' does not resolve";
      continue;
    }
    out.variables.push_back(v.name);
    out.sets.push_back(*set);
  }
  return out;
}

std::string checkDeclarations(const std::vector<net::ColourSetSpec>& colours, const std::vector<net::VariableSpec>& variables) {
  net::Colours c;
  core::Diagnostics diags;
  if (!c.declare(colours, diags)) return firstProblem(diags).message;
  std::set<std::string> seen;
  for (const auto& v : variables) {
    if (!core::isIdentifier(v.name)) return "a variable's name is a word of letters, digits and _, got '" + v.name + "'";
    if (!seen.insert(v.name).second) return "variable '" + v.name + "' is declared twice";
    if (c.find(v.name) || c.constant(v.name)) return "variable '" + v.name + "' has the name of a colour set or a constant";
    if (!c.find(v.colour)) return "variable '" + v.name + "' is of colour set '" + v.colour + "', which is not declared";
  }
  return {};
}

std::vector<std::string> usesOfColour(const net::NetSpec& net, const std::string& name) {
  std::vector<std::string> out;
  for (const auto& c : net.colours) {
    if (std::find(c.components.begin(), c.components.end(), name) != c.components.end()) out.push_back("colour set " + c.name);
  }
  for (const auto& v : net.variables) {
    if (v.colour == name) out.push_back("variable " + v.name);
  }
  forEachPage(net, [&](const net::PageSpec& page) {
    for (const auto& p : page.places) {
      for (const auto& c : p.colours) {
        if (c.text == name) out.push_back("place " + page.name + "/" + p.name + " " + net::slotName(c.slot));
      }
    }
    // all(Name) in an inscription
    const auto inText = [&](const std::string& text, const std::string& what) {
      if (namesIn(text).count(name) != 0) out.push_back(what);
    };
    for (const auto& p : page.places) {
      for (const auto& v : p.values) inText(v.text, "the values of " + page.name + "/" + p.name);
    }
    for (const auto& a : page.arcs) {
      for (const auto& i : a.inscriptions) inText(i.text, "arc " + page.name + ": " + a.from + " -> " + a.to);
    }
    for (const auto& t : page.transitions) inText(t.when.text, "the condition of " + page.name + "/" + t.name);
  });
  return out;
}

std::vector<std::string> usesOfVariable(const net::NetSpec& net, const std::string& name) {
  std::vector<std::string> out;
  forEachPage(net, [&](const net::PageSpec& page) {
    for (const auto& a : page.arcs) {
      for (const auto& i : a.inscriptions) {
        if (namesIn(i.text).count(name) != 0) out.push_back("arc " + page.name + ": " + a.from + " -> " + a.to);
      }
    }
    for (const auto& t : page.transitions) {
      if (namesIn(t.when.text).count(name) != 0) out.push_back("the condition of " + page.name + "/" + t.name);
    }
  });
  return out;
}

std::optional<std::vector<net::ColourSetSpec>> editedColours(const net::NetSpec& net, std::size_t index,
                                                             const std::string& name, std::string_view definition,
                                                             TextProblem& problem) {
  problem = {};
  // the definition alone: its syntax and form, located in its text
  core::Diagnostics diags;
  auto spec = model::readColourDefinition(name, definition, diags);
  if (!spec) {
    const auto p = firstProblem(diags);
    // a mistake in the name is the name's, not the definition's
    const bool of_name = !core::isIdentifier(name);
    problem = {of_name ? 0 : 1, of_name ? 0 : p.column, p.message};
    return std::nullopt;
  }
  auto out = net.colours;
  const bool added = index >= out.size();
  if (!added) {
    const auto& was = out[index];
    spec->loc = was.loc;
    spec->pnml_id = was.pnml_id;
    if (was.name != name) {
      const auto uses = usesOfColour(net, was.name);
      if (!uses.empty()) {
        problem = {0, 0, "colour set '" + was.name + "' is used (by " + uses.front() +
                             (uses.size() > 1 ? " and " + std::to_string(uses.size() - 1) + " more" : "") +
                             "): a rename would leave its uses behind"};
        return std::nullopt;
      }
    }
    out[index] = std::move(*spec);
  } else {
    out.push_back(std::move(*spec));
  }
  // among the others: names, components declared before it
  if (auto why = checkDeclarations(out, net.variables); !why.empty()) {
    problem = {0, 0, why};
    return std::nullopt;
  }
  return out;
}

std::optional<std::vector<net::VariableSpec>> editedVariables(const net::NetSpec& net, std::size_t index,
                                                              const std::string& name, const std::string& set,
                                                              TextProblem& problem) {
  problem = {};
  if (!core::isIdentifier(name)) {
    problem = {0, 0, "a variable's name is a word of letters, digits and _ (not starting with a digit), got '" + name + "'"};
    return std::nullopt;
  }
  auto out = net.variables;
  if (index < out.size()) {
    if (out[index].name != name) {
      const auto uses = usesOfVariable(net, out[index].name);
      if (!uses.empty()) {
        problem = {0, 0, "variable '" + out[index].name + "' is used (by " + uses.front() +
                             (uses.size() > 1 ? " and " + std::to_string(uses.size() - 1) + " more" : "") +
                             "): a rename would leave its uses behind"};
        return std::nullopt;
      }
    }
    out[index].name = name;
    out[index].colour = set;
  } else {
    out.push_back({name, set, {}});
  }
  if (auto why = checkDeclarations(net.colours, out); !why.empty()) {
    problem = {0, 0, why};
    return std::nullopt;
  }
  return out;
}

std::string SetDeclarationsCommand::apply(Document& doc) {
  if (auto why = checkDeclarations(colours_, variables_); !why.empty()) return why;
  auto& net = doc.editableNet();
  old_colours_ = std::exchange(net.colours, colours_);
  old_variables_ = std::exchange(net.variables, variables_);
  doc.touched(false);
  return {};
}

void SetDeclarationsCommand::revert(Document& doc) {
  auto& net = doc.editableNet();
  net.colours = old_colours_;
  net.variables = old_variables_;
  doc.touched(false);
}

std::optional<TextProblem> checkInscriptionText(const ColourScope& scope, std::string_view text, const std::string& set,
                                                InscriptionRole role) {
  if (text.find_first_not_of(" \t\r\n") == std::string_view::npos) {
    return TextProblem{1, 1, role == InscriptionRole::Condition ? "the condition is empty" : "the inscription is empty"};
  }
  net::ColourId id = net::Colours::kBool;
  if (role != InscriptionRole::Condition) {
    const auto found = scope.colours.find(set);
    if (!found) return TextProblem{0, 0, set.empty() ? "the slot has no colour set" : "colour set '" + set + "' is not declared"};
    id = *found;
  }
  core::Diagnostics diags;
  auto e = net::parseInscription(text, {"inscription", 1, 1}, diags);
  if (!e) return firstProblem(diags);
  std::vector<std::uint32_t> used;
  const auto what = role == InscriptionRole::Condition ? net::Expect::Condition : net::Expect::Tokens;
  if (!net::checkInscription(*e, id, what, scope.scope(), used, diags)) return firstProblem(diags);
  if (role == InscriptionRole::Values) {
    if (!used.empty()) return TextProblem{1, 1, "initial values cannot name variables ('" + scope.variables[used[0]] + "')"};
    net::Multiset m;
    if (!net::evaluateInto(*e, {}, scope.colours, id, m)) {
      return TextProblem{1, 1, "the initial values have no value in colour set '" + set + "' (a number outside its range?)"};
    }
  }
  return std::nullopt;
}

CompletionQuery completeInscription(const ColourScope& scope, std::string_view text, std::size_t cursor) {
  CompletionQuery q;
  cursor = std::min(cursor, text.size());
  // none inside a string
  bool in_string = false;
  for (std::size_t i = 0; i < cursor; ++i) {
    if (in_string && text[i] == '\\') ++i;
    else if (text[i] == '"') in_string = !in_string;
  }
  if (in_string) return q;
  const auto word = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; };
  std::size_t start = cursor;
  while (start > 0 && word(text[start - 1])) --start;
  q.start = start;
  q.prefix = std::string(text.substr(start, cursor - start));
  if (!q.prefix.empty() && std::isdigit(static_cast<unsigned char>(q.prefix.front())) != 0) return q;  // a number
  const auto offer = [&](const std::string& name, const char* kind, std::string detail, const char* signature = "") {
    if (name.compare(0, q.prefix.size(), q.prefix) == 0) q.names.push_back({name, kind, std::move(detail), signature});
  };
  if (start > 0 && text[start - 1] == '.') {
    // a record's fields: the chain of names before the dot, from a variable
    q.member = true;
    std::size_t b = start - 1;
    while (b > 0 && (word(text[b - 1]) || text[b - 1] == '.')) --b;
    q.context = std::string(text.substr(b, start - 1 - b));
    std::vector<std::string> chain;
    for (std::size_t i = 0; i <= q.context.size();) {
      const auto dot = q.context.find('.', i);
      const auto end = dot == std::string::npos ? q.context.size() : dot;
      chain.push_back(q.context.substr(i, end - i));
      i = end + 1;
    }
    const auto v = std::find(scope.variables.begin(), scope.variables.end(), chain.front());
    if (v == scope.variables.end()) return q;
    net::ColourId set = scope.sets[static_cast<std::size_t>(v - scope.variables.begin())];
    for (std::size_t k = 1; k < chain.size(); ++k) {
      const auto& s = scope.colours.at(set);
      const auto f = std::find(s.fields.begin(), s.fields.end(), chain[k]);
      if (s.kind != net::ColourKind::Record || f == s.fields.end()) return q;
      set = s.components[static_cast<std::size_t>(f - s.fields.begin())];
    }
    const auto& s = scope.colours.at(set);
    if (s.kind != net::ColourKind::Record) return q;
    for (std::size_t i = 0; i < s.fields.size(); ++i) {
      offer(s.fields[i], "field", "field of " + s.name + ": " + scope.colours.at(s.components[i]).name);
    }
    return q;
  }
  // at the start of a word: variables, constants, sets, then the language's words
  for (std::size_t i = 0; i < scope.variables.size(); ++i) {
    offer(scope.variables[i], "variable", "variable of colour set " + scope.colours.at(scope.sets[i]).name);
  }
  const auto& sets = scope.colours.sets();
  for (const auto& s : sets) {
    for (const auto& c : s.constants) offer(c, "constant", "constant of " + s.name + (s.cyclic ? " (cyclic)" : ""));
  }
  for (std::size_t i = 0; i < sets.size(); ++i) {
    const auto& s = sets[i];
    std::string size = s.size ? std::to_string(*s.size) + " values" : "not finite";
    offer(s.name, "colour set", std::string(net::colourKindName(s.kind)) + ", " + size + (i > net::Colours::kString ? "" : " (built in)"));
  }
  for (const auto& w : kWords) {
    // `dot` is a set and a value: offered once
    const bool offered = std::any_of(q.names.begin(), q.names.end(), [&](const Completion& c) { return c.name == w.name; });
    if (!offered) offer(w.name, w.kind, w.detail, w.signature);
  }
  return q;
}

std::string valuesText(const net::Colours& colours, net::ColourId set, const net::Multiset& m, std::size_t most) {
  if (m.empty()) return "empty";
  std::string out;
  std::size_t shown = 0;
  for (const auto& [v, n] : m) {
    if (shown == most) break;
    out += (shown == 0 ? "" : " ++ ") + std::to_string(n) + "'" + colours.text(set, v);
    ++shown;
  }
  if (m.size() > shown) {
    const auto left = m.size() - shown;
    out += " ... and " + std::to_string(left) + (left == 1 ? " more value" : " more values");
  }
  return out;
}

std::string bindingText(const net::Colours& colours, const net::TransitionInscriptions& t, const net::Binding& b) {
  std::string out;
  for (std::size_t i = 0; i < b.size() && i < t.variables.size(); ++i) {
    out += (i == 0 ? "" : ", ") + t.variables[i] + " = " + colours.text(t.sets[i], b[i]);
  }
  return out;
}

}  // namespace gdpn::ide
