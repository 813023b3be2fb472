#pragma once
/// \file
/// The names scripts reach on gdpn's views (`sim`, `self`, a slot, a node token ...), read from
/// the very Python classes the engine registers (src/script/views.cpp), each with the first line
/// of its docstring: the one description that the IDE's completion shows and that
/// docs/format.md's tables of script names are held to (tests/script/api_test.cpp). Also the
/// names a globals script defines, read by Python's ast without running it.

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace gdpn::script {

/// A class of the objects scripts see.
enum class ViewClass : std::uint8_t {
  Sim,         ///< `sim`: the running simulation
  Transition,  ///< `self` in a transition's scripts and an arc's predicates and conditions
  Place,       ///< `self` in a place slot's scripts; `sim.place(name)`
  Slot,        ///< `self.a0`: one slot of a place or transition
  Node,        ///< a node token (`token`, `self.d0[0]`, `sim.node(path)`); its fields besides
  Sensor,      ///< what a sensor reports (a sensor slot, `sim.node(path)` of a sensor)
  Random,      ///< `sim.random`
  Params,      ///< `sim.params`, `self.params`
  Part,        ///< `sim.part(name)`, `self.part`
  Data,        ///< `node.data`: a node's user data
};

/// Every view class, in the order docs/format.md lists them.
inline constexpr std::array<ViewClass, 10> kViewClasses = {
    ViewClass::Sim,    ViewClass::Transition, ViewClass::Place,  ViewClass::Slot, ViewClass::Node,
    ViewClass::Sensor, ViewClass::Random,     ViewClass::Params, ViewClass::Part, ViewClass::Data};

/// The class's Python name ("Sim", "Transition" ...), as `gdpn_script` registers it.
const char* viewClassName(ViewClass c);

/// The first line of the class's docstring ("The running simulation").
const std::string& viewClassDoc(ViewClass c);

/// One name of a view class: an attribute or a method.
struct ViewName {
  std::string name;       ///< as scripts write it (`time`, `log`)
  bool method = false;    ///< called: `sim.log(...)`
  std::string arguments;  ///< a method's parameters as its binding gives them, `self` left out ("" for an attribute)
  std::string doc;        ///< the first line of its docstring ("" when the binding gives none)
};

/// The public names (no leading underscore) of class `c`, sorted, as the bindings define them.
/// Starts the interpreter and registers the views when needed; read once per process.
const std::vector<ViewName>& viewNames(ViewClass c);

/// The markdown table of `c`'s names that docs/format.md shows after `<!-- script-api: NAME -->`.
std::string viewNamesMarkdown(ViewClass c);

/// A name a globals script binds at its top level.
struct GlobalName {
  std::string name;    ///< the name
  std::string kind;    ///< "function", "class", "variable" or "import"
  std::string detail;  ///< a function's parameters and the first line of its docstring, a variable's value ("= 0")
  int line = 0;        ///< the line of the script's text where it is bound, 1 its first
};

/// The names `code` (a globals script) binds at its top level (also inside top-level `if`,
/// `try`, `with` and `for` blocks), in the order first bound, read by Python's ast without
/// running it. Empty when the code does not parse. Starts the interpreter when needed.
std::vector<GlobalName> globalNames(const std::string& code);

}  // namespace gdpn::script
