// The plant side of a hybrid net: rates read the plant, amounts drive its fields.

#include "fluid_plant.h"

#include <cmath>

#include "gdpn/core/text.h"
#include "gdpn/model/simulation.h"
#include "gdpn/physics/world.h"

namespace gdpn::model {

std::unique_ptr<FluidPlant> FluidPlant::create(Simulation& sim, core::Diagnostics& diags) {
  std::unique_ptr<FluidPlant> plant(new FluidPlant(sim));
  const net::Fluid* fluid = sim.net().fluid();
  if (!fluid) return plant;
  const net::Net& net = sim.net();
  for (const auto& read : fluid->reads) {
    std::string why = "the model has no scene";
    std::optional<Probe> probe;
    if (sim.plant()) probe = nodeProbe(sim, read.node, read.of, why);
    if (probe && probe->width() != 1) {
      probe.reset();
      why = "'" + read.of + "' gives three numbers; a rate reads one (`" + read.of + ".z`)";
    }
    if (!probe) diags.error(read.loc, "continuous transition '" + net.transitionName(read.transition) + "' reads '" +
                                          read.node + "': " + why);
    plant->reads_.push_back(std::move(probe));
  }
  for (const auto& fp : fluid->places) {
    for (const auto& d : fp.drives) {
      const std::string what = "continuous place '" + net.placeName(fp.place) + "' drives '" + d.node + "'";
      scene::Node* node = sim.plant() ? sim.plant()->find(d.node) : nullptr;
      if (!node) {
        diags.error(d.loc, what + ": no such node in the scene");
        continue;
      }
      Driven driven;
      driven.place = fp.place;
      driven.node = node->handle();
      driven.scale = d.scale;
      driven.offset = d.offset;
      std::string field = d.field;
      if (const auto dot = field.rfind('.'); dot != std::string::npos && dot + 2 == field.size() &&
                                               field[dot + 1] >= 'x' && field[dot + 1] <= 'z') {
        driven.component = field[dot + 1] - 'x';
        field.resize(dot);
      }
      const int index = node->type().fieldIndex(field);
      const auto kind = index < 0 ? scene::FieldKind::String : node->type().fields[static_cast<std::size_t>(index)]->kind;
      const bool fits = driven.component < 0 ? kind == scene::FieldKind::Float
                                             : kind == scene::FieldKind::Vec3;
      if (index < 0 || !fits) {
        diags.error(d.loc, what + ": a " + node->type().name + " has no number field '" + d.field + "'" +
                               (driven.component < 0 ? "" : " (a vector field's component: `size.z`)"));
        continue;
      }
      driven.field = static_cast<std::size_t>(index);
      plant->drives_.push_back(driven);
    }
  }
  if (diags.hasErrors()) return nullptr;
  return plant;
}

void FluidPlant::feed() {
  for (std::size_t i = 0; i < reads_.size(); ++i) {
    double v = 0.0;
    if (reads_[i] && !readProbe(sim_, *reads_[i], &v)) v = 0.0;  // its node was deleted
    sim_.kernel().setFluidInput(i, v);
  }
}

void FluidPlant::drive() {
  for (auto& d : drives_) {
    const double amount = sim_.kernel().amount(d.place);
    if (amount == d.last) continue;
    scene::Node* node = sim_.plant() ? sim_.plant()->resolve(d.node) : nullptr;
    if (!node) continue;  // deleted
    d.last = amount;
    const double v = d.offset + d.scale * amount;
    scene::FieldValue value = v;
    if (d.component >= 0) {
      auto vec = std::get<std::array<double, 3>>(node->value(d.field));
      vec[static_cast<std::size_t>(d.component)] = v;
      value = vec;
    }
    // a value the field refuses (a size of 0) leaves it as it was
    (void)physics::assignField(*node, d.field, value, sim_.model().settings.angles, sim_.physics());
  }
}

}  // namespace gdpn::model
