// Names of selection kinds.

#include "gdpn/ide/selection.h"

namespace gdpn::ide {

const char* selectionKindName(SelectionKind kind) {
  switch (kind) {
    case SelectionKind::None: return "none";
    case SelectionKind::Node: return "node";
    case SelectionKind::Place: return "place";
    case SelectionKind::Transition: return "transition";
    case SelectionKind::Instance: return "instance";
  }
  return "none";
}

}  // namespace gdpn::ide
