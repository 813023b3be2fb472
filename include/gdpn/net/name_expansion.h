#pragma once
/// \file
/// Names that stand for several of a net's places or transitions: a coloured net's, once
/// unfolded (unfold.h), as the query parsers read them (query.h).

#include <functional>
#include <map>
#include <string>
#include <vector>

namespace gdpn::net {

/// Names that stand for several of a net's places or transitions: a coloured net's, once
/// unfolded (unfold.h). In a query such a place means the tokens of all its places together,
/// and `fireable` of such a transition means that any of its transitions is enabled.
struct NameExpansion {
  /// A place's qualified name ("net/Fork") -> the qualified names of the net's places it stands for.
  std::map<std::string, std::vector<std::string>, std::less<>> places;
  /// A transition's qualified name -> the qualified names of the net's transitions it stands for.
  std::map<std::string, std::vector<std::string>, std::less<>> transitions;
};

}  // namespace gdpn::net
