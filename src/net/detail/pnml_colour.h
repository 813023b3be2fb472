#pragma once
// Internal: no promises. The high-level parts of a PNML symmetric net (the Model Checking
// Contest's coloured format): its declarations read into colour sets and variables, and its
// terms (place types, initial markings, arc inscriptions, transition conditions) into the
// inscription language's text; and back.

#include <map>
#include <optional>
#include <set>
#include <string>

#include "xml.h"
#include "gdpn/core/diagnostics.h"
#include "gdpn/net/spec.h"

namespace gdpn::net::detail {

/// True when the net type `type` (the `type` attribute of `<net>`) is a symmetric net.
bool isSymmetricNet(const std::string& type);

/// The PNML id of a declaration named `name` that keeps `pnml_id` ("" for the same).
inline const std::string& declarationId(const std::string& name, const std::string& pnml_id) {
  return pnml_id.empty() ? name : pnml_id;
}

/// Reads a symmetric net's declarations and terms. Every declaration is named by its PNML
/// name where that is an identifier that no other declaration, built-in set or word of the
/// language has, else by an identifier made from its id (the contest names enumeration
/// constants "1", "2" ...); the ids are kept (ColourSetSpec::pnml_id ...).
class PnmlColourReader {
 public:
  /// Reports to `diags`.
  explicit PnmlColourReader(core::Diagnostics& diags) : diags_(diags) {}

  /// Reads every `<declaration>` of `net` (its own and its pages') into `spec`'s colour sets
  /// and variables, in document order.
  void declarations(const XmlElement& net, NetSpec& spec);

  /// The colour set a place's `<type>` names (by its name in the spec); nullopt, reported,
  /// when it names none.
  std::optional<std::string> placeSort(const XmlElement& type);

  /// The term inside high-level label `label` (`<hlinitialMarking>`, `<hlinscription>`,
  /// `<condition>`: its `<structure>`'s one element) in the inscription language; nullopt,
  /// reported at the element at fault, when it is none the language has.
  std::optional<std::string> term(const XmlElement& label);

  /// True when colour set `name` is one of `dot` (the built-in or a namedsort of `<dot/>`).
  [[nodiscard]] bool isDot(const std::string& name) const { return name == "dot" || dots_.count(name) > 0; }

 private:
  /// An operand's text and how loosely it binds (0: a `++` sum ... 7: a primary).
  struct Text {
    std::string text;
    int level = 7;
  };
  std::string nameFor(const std::string& pnml_name, const std::string& id);
  std::optional<std::string> sortName(const XmlElement& sort);
  std::optional<Text> render(const XmlElement& e, int depth);
  std::optional<std::string> operand(const XmlElement& e, int level, int depth);
  std::nullopt_t fail(const XmlElement& e, const std::string& message);

  core::Diagnostics& diags_;
  std::set<std::string> used_;                     // names given, and the language's words
  std::map<std::string, std::string> sorts_;       // namedsort id -> its set's name
  std::map<std::string, std::string> constants_;   // feconstant id -> its name
  std::map<std::string, std::string> variables_;   // variabledecl id -> its name
  std::set<std::string> dots_;                     // sets of <dot/>
};

/// Writes the declarations of `spec` (colour sets and variables) as a symmetric net's
/// `<declaration>`; "" when there are none.
std::string declarationsXml(const NetSpec& spec);

/// The `<structure>` of a place type naming set `set`.
std::string sortXml(const NetSpec& spec, const std::string& set);

/// The `<structure>` of the inscription text `text` (a term of the language, as the reader
/// makes them); nullopt with `why` where the text is no term a symmetric net has.
std::optional<std::string> termXml(const NetSpec& spec, const std::string& text, std::string& why);

}  // namespace gdpn::net::detail
