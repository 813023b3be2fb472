// Gps: the position of its node, in the world's frame or as latitude, longitude and altitude
// on a georeferenced Terrain, at a rate.

#include <cmath>

#include "detail/sensor.h"
#include "gdpn/scene/actions.h"
#include "gdpn/scene/terrain.h"

namespace gdpn::sensors::detail {
namespace gps {  // named, not anonymous: the kinds share a unity build

namespace F = scene::field;

constexpr Channel kChannels[] = {
    // no one unit: metres, or degrees and metres
    {"position", ChannelType::Vector, "",
     "x, y, z (m) in the world's frame; with frame: geodetic, latitude and longitude (deg) and altitude (m)", false,
     false, 10},
    {"samples", ChannelType::Number, "", "samples taken so far"},
};

/// The Terrain a geodetic Gps reads: the one its `terrain` names, or the scene's first.
const scene::Node* terrainOf(const scene::Scene& scene, const scene::Node& gps) {
  const std::string& path = gps.text(F::Gps::Terrain);
  if (!path.empty()) {
    const scene::Node* t = scene.find(path);
    return t && t->kind() == scene::NodeKind::Terrain ? t : nullptr;
  }
  const scene::Node* first = nullptr;
  scene::traverse(scene.root(), [&](scene::Node& n, const scene::TraversalState&) {
    if (!first && n.kind() == scene::NodeKind::Terrain) first = &n;
  }, {}, scene::Templates::Skip);
  return first;
}

std::unique_ptr<scene::Geodesy> geodesyOf(const scene::Node& terrain, const std::string& dir, std::string& why) {
  const std::string& file = terrain.text(F::Terrain::File);
  const std::string path = file.empty() || file[0] == '/' ? file : dir + "/" + file;
  return scene::Geodesy::open(path, terrain.number(F::Terrain::Width), terrain.number(F::Terrain::Depth), why);
}

bool geodetic(const scene::Node& n) { return n.choice<scene::GpsFrame>(F::Gps::Frame) == scene::GpsFrame::Geodetic; }

/// A geodetic Gps needs a Terrain whose file gives latitudes.
bool check(const scene::Scene& scene, const scene::Node& n, core::Diagnostics& diags, const std::string& dir) {
  if (!geodetic(n)) return true;
  const scene::Node* t = terrainOf(scene, n);
  const auto& at = n.fieldLoc(F::Gps::Frame).line ? n.fieldLoc(F::Gps::Frame) : n.loc;
  std::string why;
  if (!t) {
    diags.error(at, "a geodetic Gps needs a georeferenced Terrain, but '" + n.path() + "' finds no Terrain" +
                        (n.text(F::Gps::Terrain).empty() ? "" : " at '" + n.text(F::Gps::Terrain) + "'"));
    return false;
  }
  if (!geodesyOf(*t, dir, why)) {
    diags.error(at, "a geodetic Gps needs a georeferenced Terrain, but the file of '" + t->path() +
                        "' cannot give latitudes: " + why);
    return false;
  }
  return true;
}

class Gps final : public SampledSensor {
 public:
  using SampledSensor::SampledSensor;

 protected:
  [[nodiscard]] Noise noise() const override { return noiseFields(node(), F::Gps::Noise); }
  [[nodiscard]] double rate() const override { return node().number(F::Gps::Rate); }
  void measure(Context& ctx, Reading& next) override {
    core::Vec3 p = node().world.position;
    const bool geo = geodetic(node());
    const scene::Geodesy* geodesy = nullptr;
    if (geo) {
      // its Terrain, found once (a path, or the first Terrain), resolved each sample
      if (terrain_ == 0) {
        const scene::Node* t = terrainOf(ctx.scene, node());
        terrain_ = t ? t->handle() : 0;
      }
      if (const scene::Node* t = terrain_ ? ctx.scene.resolve(terrain_) : nullptr) {
        std::string why;
        if (!geodesy_opened_) geodesy_ = geodesyOf(*t, ctx.model_dir, why);
        geodesy_opened_ = true;
        geodesy = geodesy_.get();
        p = t->world.inverse().apply(p);
      }
    }
    double x[3] = {p.x, p.y, p.z};
    addNoise(x, 3);
    // where the Terrain is gone (or its file no longer gives a georeference) the position
    // has no latitude: NaN, not metres read as degrees
    double lat = 0, lon = 0;
    if (geo && !(geodesy && geodesy->toGeodetic(x[0], x[1], lat, lon))) lat = lon = std::nan("");
    next.get<core::Vec3>(0) = geo ? core::Vec3{lat, lon, x[2]} : core::Vec3{x[0], x[1], x[2]};
    next.get<double>(1) = static_cast<double>(samples());
  }

 private:
  scene::NodeHandle terrain_ = 0;             // a geodetic Gps's Terrain, found at its first sample
  bool geodesy_opened_ = false;
  std::unique_ptr<scene::Geodesy> geodesy_;   // its georeference (null: the file gives none)
};

}  // namespace gps

const KindDef kGps{{scene::NodeKind::Gps, gps::kChannels, 1, "it took a sample now", Sampling::Rate},
                   gps::check,
                   makeSensor<gps::Gps>};

}  // namespace gdpn::sensors::detail
