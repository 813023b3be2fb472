#include "gdpn/net/state_equation.h"

#include <glpk.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>

namespace gdpn::net {
namespace {

/// GLPK writes nothing to the terminal while gdpn runs.
int silent(void*, const char*) { return 1; }

struct ProblemDeleter {
  void operator()(glp_prob* p) const { glp_delete_prob(p); }
};

}  // namespace

std::vector<std::int64_t> stateEquationBounds(const Net& net, const std::vector<bool>& wanted,
                                              const InvariantOptions& options) {
  const std::size_t places = net.placeSlots().size();
  const std::size_t transitions = net.transitions().size();
  std::vector<std::int64_t> out(places, -1);
  bool any = false;
  for (std::size_t k = 0; k < places && k < wanted.size(); ++k) any = any || wanted[k];
  if (!any || transitions == 0) {
    // nothing fires: each slot keeps what it has
    for (std::size_t k = 0; k < places && k < wanted.size(); ++k) {
      if (wanted[k] && transitions == 0) out[k] = net.placeSlots()[k].initial;
    }
    return out;
  }
  glp_term_hook(silent, nullptr);
  std::unique_ptr<glp_prob, ProblemDeleter> lp(glp_create_prob());
  glp_set_obj_dir(lp.get(), GLP_MAX);
  // rows: M(p) - M0(p) = C_p · x, with 0 <= M(p) <= capacity; columns: x >= 0
  glp_add_rows(lp.get(), static_cast<int>(places));
  glp_add_cols(lp.get(), static_cast<int>(transitions));
  for (std::size_t k = 0; k < places; ++k) {
    const PlaceSlot& ps = net.placeSlots()[k];
    const auto m0 = static_cast<double>(ps.initial);
    if (ps.capacity == kUnbounded) {
      glp_set_row_bnds(lp.get(), static_cast<int>(k + 1), GLP_LO, -m0, 0.0);
    } else {
      glp_set_row_bnds(lp.get(), static_cast<int>(k + 1), GLP_DB, -m0, static_cast<double>(ps.capacity) - m0);
    }
  }
  for (std::size_t t = 0; t < transitions; ++t) glp_set_col_bnds(lp.get(), static_cast<int>(t + 1), GLP_LO, 0.0, 0.0);
  // the incidence, one entry per (place slot, transition) that changes the slot
  const Incidence c = incidenceMatrix(net);
  std::vector<int> ia{0}, ja{0};
  std::vector<double> ar{0.0};
  for (TransitionId t = 0; t < transitions; ++t) {
    for (const auto& [ps, v] : c.by_transition[t]) {
      ia.push_back(static_cast<int>(ps + 1));
      ja.push_back(static_cast<int>(t + 1));
      ar.push_back(static_cast<double>(v));
    }
  }
  glp_load_matrix(lp.get(), static_cast<int>(ar.size() - 1), ia.data(), ja.data(), ar.data());
  glp_smcp parm;
  glp_init_smcp(&parm);
  parm.msg_lev = GLP_MSG_OFF;
  parm.presolve = GLP_OFF;  // keep the basis from one program to the next
  std::size_t previous = places;
  for (std::size_t k = 0; k < places && k < wanted.size(); ++k) {
    if (!wanted[k]) continue;
    if (options.deadline && std::chrono::steady_clock::now() >= *options.deadline) break;
    if (previous < places) {
      for (const auto& [t, v] : c.by_place[previous]) glp_set_obj_coef(lp.get(), static_cast<int>(t + 1), 0.0);
    }
    previous = k;
    // maximise C_k · x; M(k) = M0(k) + that
    for (const auto& [t, v] : c.by_place[k]) glp_set_obj_coef(lp.get(), static_cast<int>(t + 1), static_cast<double>(v));
    const std::int64_t m0 = net.placeSlots()[k].initial;
    if (c.by_place[k].empty()) {
      out[k] = m0;
      continue;
    }
    if (glp_simplex(lp.get(), &parm) != 0) {
      // a numerical difficulty: start again from the standard basis once
      glp_std_basis(lp.get());
      if (glp_simplex(lp.get(), &parm) != 0) continue;
    }
    if (glp_get_status(lp.get()) != GLP_OPT) continue;  // unbounded (or, with M0 >= 0 feasible, nothing else)
    const double best = static_cast<double>(m0) + glp_get_obj_val(lp.get());
    if (best < 9e18) out[k] = static_cast<std::int64_t>(std::floor(best + 1e-6));
  }
  return out;
}

}  // namespace gdpn::net
