// The region kept for the net view: the integration wires the diagram module in here.

#include "../views.h"

namespace gdpn::ide {

void drawNetView(App& /*app*/, const Rect& at, nlohmann::json& report) {
  beginPanel("##net", at, "Net view");
  endPanel();
  report = {{"placeholder", true}, {"rect", {at.x, at.y, at.w, at.h}}};
}

}  // namespace gdpn::ide
