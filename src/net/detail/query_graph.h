#pragma once
// Internal to the net module: the whole reachability graph, stored once for many queries,
// and the answers read from it (CTL by fixed points, reachability and bounds by a
// breadth-first walk over its edges).

#include <memory>

#include "gdpn/net/query.h"
#include "marking_store.h"

namespace gdpn::net::detail {

/// True when every path operator of `f` stands right under a path quantifier and every
/// quantifier right over one: a CTL formula.
bool isCtl(const Formula& f);

/// The reachable markings (ids in breadth-first order, 0 the initial one) and their edges,
/// 12 bytes per edge (the successor, the transition, the predecessor).
struct StateGraph {
  std::unique_ptr<Store> store;
  std::vector<std::uint64_t> first;   ///< successors of s: succ[first[s] .. first[s + 1])
  std::vector<StateId> succ;
  std::vector<TransitionId> via;      ///< per edge: the transition that fires
  std::vector<std::uint64_t> pfirst;  ///< predecessors of s, one per edge: pred[pfirst[s] .. pfirst[s + 1])
  std::vector<StateId> pred;
  ExploreStop stop = ExploreStop::Done;  ///< why the graph is not whole (Done: it is)
  std::size_t size() const { return first.empty() ? 0 : first.size() - 1; }
  std::size_t outDegree(StateId s) const { return first[s + 1] - first[s]; }
};

/// Stores the reachability graph of `net` under `limits` (max_states, max_bytes, deadline).
StateGraph buildGraph(const Net& net, const ExploreOptions& limits);

/// Answers `f` on the whole graph `g` (g.stop == Done): a bound (and a shortest path to a
/// marking holding it), EF or AG of a state formula (with a shortest path to the marking that
/// decides it), any CTL formula (paths are maximal: a dead marking ends its paths, so EX p
/// fails there, AX p holds, EG p holds where p does), or an LTL formula (answerLtl).
QueryAnswer answerOnGraph(const Net& net, const StateGraph& g, const Formula& f, const ExploreOptions& limits);

/// Whether a single infinite path shows answer `v` of CTL formula `f`: AF p, AG p, A [p U q]
/// that fail, EG p, E [p U q] that hold (p, q state formulas) mean the same in LTL, so a lasso
/// of the LTL search shows them (not X: CTL's paths end at a dead marking, LTL's stutter).
bool lassoShows(const Formula& f, Verdict v);

/// Copies the lasso of `shown` (the same formula read as LTL) into `a` where it gives the
/// same answer.
void takeLasso(QueryAnswer& a, QueryAnswer shown);

/// Answers the LTL formula `f` (A or E over a path formula) on the whole graph `g`: a
/// generalized Büchi automaton of the path formula (negated for A) by the tableau method, and
/// its product with the graph searched for an accepting cycle. A dead marking's paths stutter
/// there forever. `limits` bound the product (max_states product states, max_bytes, the
/// deadline): past them the answer is Unknown.
QueryAnswer answerLtl(const Net& net, const StateGraph& g, const Formula& f, const ExploreOptions& limits);

/// The same on the fly: the product searched depth first as the graph is made (LazyGraph),
/// so that a lasso is found without the whole graph; past `limits` the answer is Unknown.
QueryAnswer answerLtlOnTheFly(const Net& net, const Formula& f, const ExploreOptions& limits);

/// Answers the CTL formula `f` at the initial marking on the fly (local_ctl.cpp): each
/// temporal subformula by a depth-first search from the marking it is asked at, which makes
/// only the markings it needs and stops as soon as the answer shows (EF p at the first p;
/// AG p at the first marking that breaks p); what each search settles is kept per marking.
/// Paths are maximal as in answerOnGraph. Past `limits` the answer is Unknown.
QueryAnswer answerCtlLocally(const Net& net, const Formula& f, const ExploreOptions& limits);

}  // namespace gdpn::net::detail
