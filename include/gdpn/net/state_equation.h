#pragma once
/// \file
/// Bounds from the state equation (semantics §11): every reachable marking M satisfies
/// M = M0 + C·x for some firing count vector x >= 0, so the most tokens a place slot can hold
/// is at most the optimum of a linear program over x. The program is a relaxation (it ignores
/// the order of firings, test and inhibitor arcs), so its bound is sound but may be above the
/// true one; where the invariants were cut short it still bounds what they could not.

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "gdpn/net/invariants.h"
#include "gdpn/net/net.h"
#include "gdpn/net/query.h"

namespace gdpn::net {

/// Per place slot, a bound from the state equation, tokens: for the slots where `wanted` is
/// true, the largest M(p) with M = M0 + C·x, 0 <= M <= capacity, x >= 0 (GLPK's simplex, one
/// program per slot, each starting from the last one's basis), rounded down; -1 where the
/// program is unbounded, where it was not wanted, or once `options`' deadline has passed.
std::vector<std::int64_t> stateEquationBounds(const Net& net, const std::vector<bool>& wanted,
                                              const InvariantOptions& options = {});

/// Per sum of `sums`, a bound from the state equation, tokens: the largest value of the sum
/// (its slots' tokens plus its constant) over M = M0 + C·x, 0 <= M <= capacity, x >= 0 (one
/// program per sum, each starting from the last one's basis), rounded down; -1 where the
/// program is unbounded, or once `options`' deadline has passed. The same relaxation as
/// stateEquationBounds: sound, and at least as tight as any P-invariant's bound.
std::vector<std::int64_t> stateEquationMaxima(const Net& net, const std::vector<TokenSum>& sums,
                                              const InvariantOptions& options = {});

/// True when no solution of the state equation (M = M0 + C·x, x >= 0, 0 <= M <= capacity,
/// over the reals) satisfies the state formula `f`: then no reachable marking does, and `EF f`
/// is false without a search. `f` is put in disjunctive normal form over linear constraints
/// (a transition enabled: its inputs, tests, inhibitors and capacities; sensor conditions free)
/// and each disjunct tried as a linear program (GLPK). False when one may hold, or when the
/// form grows past 256 disjuncts (`deadlock` in a net of many transitions).
bool stateEquationExcludes(const Net& net, const Formula& f);

/// Whether some x >= 1 (every entry) has x·A = 0 (`equality`) or x·A <= 0, for the sparse
/// integer matrix A given by its rows (each (column, value) pairs, columns below `columns`):
/// one linear program (GLPK), feasible or not. It answers what a listing of minimal semiflows
/// answers by covering (conservative, structurally bounded, consistent) where the listing was
/// cut short. Nullopt when GLPK fails.
std::optional<bool> positiveSolution(const std::vector<std::vector<std::pair<std::uint32_t, std::int64_t>>>& rows,
                                     std::size_t columns, bool equality);

}  // namespace gdpn::net
