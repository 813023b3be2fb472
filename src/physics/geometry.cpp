// The geometry of shapes: what each shape node is made as in ODE (sized by
// scene::shapeExtent), meshes read from files, terrain from elevation files, and where each
// geometry goes (on its body, or fixed in the world).

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "gdpn/scene/mesh.h"
#include "gdpn/scene/terrain.h"
#include "convex_hull.h"
#include "ode_convert.h"
#include "world_impl.h"

namespace gdpn::physics {

using core::Pose;
using core::Quat;
using core::Vec3;
using scene::Node;
using scene::NodeKind;

Primitive boxPrimitive(Vec3 extent, Vec3 scale) {
  Primitive p;
  p.form = Form::Box;
  p.box = extent.times(scale);
  return p;
}

Primitive spherePrimitive(Vec3 extent, Vec3 scale) {
  Primitive p;
  p.form = Form::Sphere;
  p.radius = extent.x * 0.5 * std::max({scale.x, scale.y, scale.z});
  return p;
}

Primitive cylinderPrimitive(Vec3 extent, Vec3 scale, bool cone) {
  Primitive p;
  p.form = Form::Cylinder;
  p.radius = extent.x * 0.5 * std::max(scale.x, scale.y) * (cone ? 0.5 : 1.0);
  p.height = extent.z * scale.z;
  return p;
}

Primitive shapePrimitive(const Node& n) {
  Primitive p;
  switch (n.kind()) {
    case NodeKind::Cube: return boxPrimitive(scene::shapeExtent(n), n.world_scale);
    case NodeKind::Sphere: return spherePrimitive(scene::shapeExtent(n), n.world_scale);
    case NodeKind::Cylinder: return cylinderPrimitive(scene::shapeExtent(n), n.world_scale, false);
    case NodeKind::Cone: return cylinderPrimitive(scene::shapeExtent(n), n.world_scale, true);
    case NodeKind::Mesh: p.form = Form::Mesh; return p;
    case NodeKind::Plane: p.form = Form::Plane; return p;
    case NodeKind::Terrain: p.form = Form::Terrain; return p;
    // no shapes
    case NodeKind::Group:
    case NodeKind::Transform:
    case NodeKind::Material:
    case NodeKind::Light:
    case NodeKind::Camera:
    case NodeKind::Fog:
    case NodeKind::World:
    case NodeKind::Body:
    case NodeKind::Joint:
    case NodeKind::Conveyor:
    case NodeKind::GradientField:
    case NodeKind::Region:
    case NodeKind::RangeFinder:
    case NodeKind::GradientSensor:
    case NodeKind::KeyboardSensor:
    case NodeKind::MouseSensor:
    case NodeKind::ColorCamera:
    case NodeKind::DepthCamera:
    case NodeKind::LaserScan:
    case NodeKind::Imu:
    case NodeKind::Gps:
    case NodeKind::Contact:
    case NodeKind::ForceTorque:
    case NodeKind::TimeSensor: return p;
  }
  return p;
}

const World::Impl::MeshGeometry* World::Impl::meshOf(Node& n, const std::string& dir, core::Diagnostics& diags) {
  if (auto it = meshes.find(n.handle()); it != meshes.end()) return &it->second;
  using F = scene::field::Mesh;
  const std::string file = n.text(F::File);
  const auto at = n.fieldLoc(F::File);
  const auto path = (std::filesystem::path(dir) / file).string();
  std::string why;
  auto data = file.empty() ? nullptr : scene::loadMesh(path, why);
  if (!data) {
    diags.error(at.line > 0 ? at : n.loc, "cannot read the mesh file '" + file + "': " + (file.empty() ? "no file given" : why));
    return nullptr;
  }
  const auto part = n.number(F::Part);
  if (part >= static_cast<double>(data->parts.size())) {
    const auto ploc = n.fieldLoc(F::Part);
    diags.error(ploc.line > 0 ? ploc : n.loc, "the mesh file '" + file + "' has " + std::to_string(data->parts.size()) +
                                                  " parts: 'part' must be below that, or -1 for all");
    return nullptr;
  }
  MeshGeometry geo;
  const Vec3 s = n.vec3(F::Scale).times(n.world_scale);
  for (std::size_t i = 0; i < data->parts.size(); ++i) {
    if (part >= 0 && static_cast<std::size_t>(part) != i) continue;
    const auto& p = data->parts[i];
    const auto base = static_cast<dTriIndex>(geo.points.size() / 3);
    for (std::size_t k = 0; k + 2 < p.positions.size(); k += 3) {
      const Vec3 v = Vec3{static_cast<double>(p.positions[k]), static_cast<double>(p.positions[k + 1]),
                           static_cast<double>(p.positions[k + 2])}
                          .times(s);
      geo.points.insert(geo.points.end(), {v.x, v.y, v.z});
      geo.box.add(v);
    }
    for (auto idx : p.indices) geo.indices.push_back(base + static_cast<dTriIndex>(idx));
  }
  convexHull(geo.points, geo.planes, geo.hull_points, geo.polygons);
  return &(meshes[n.handle()] = std::move(geo));
}

dGeomID World::Impl::terrainGeom(Node& n, const std::string& dir, core::Diagnostics& diags) {
  using F = scene::field::Terrain;
  const Vec3 s = n.world_scale;
  const std::string file = n.text(F::File);
  const auto at = n.fieldLoc(F::File);
  const auto path = (std::filesystem::path(dir) / file).string();
  std::string why;
  auto grid = scene::loadHeightGrid(path, why);
  if (!grid) {
    diags.error(at.line > 0 ? at : n.loc, "cannot read the elevation file '" + file + "': " + why);
    return nullptr;
  }
  // ODE's heightfield is Y-up: x along width, z along depth (rows), heights along +y.
  // Turned a quarter about x, its depth runs towards -y, so row 0 (north) lands at +y.
  heightfields.push_back(std::move(grid->height));
  dHeightfieldDataID data = dGeomHeightfieldDataCreate();
  dGeomHeightfieldDataBuildDouble(data, heightfields.back().data(), 0, n.number(F::Width) * s.x,
                                  n.number(F::Depth) * s.y, grid->nx, grid->ny, n.number(F::HeightScale) * s.z,
                                  0.0, 1.0, 0);
  heightfield_data.push_back(data);
  dGeomID g = dCreateHeightfield(space, data, 1);
  const Pose pose = n.world * Pose{{}, Quat::axisAngle({1, 0, 0}, M_PI / 2)};
  const dQuaternion q = {pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z};
  dGeomSetPosition(g, pose.position.x, pose.position.y, pose.position.z);
  dGeomSetQuaternion(g, q);
  return g;
}

bool World::Impl::addGeom(Node& n, const scene::TraversalState& st, const std::string& dir, core::Diagnostics& diags) {
  const Primitive prim = shapePrimitive(n);
  if (prim.form == Form::None) return true;  // not a shape
  Body* body = owner(n);
  dGeomID g = nullptr;
  Pose geom_pose = n.world;  // where the geometry goes (a mesh's box sits on the mesh's centre)
  switch (prim.form) {
    case Form::Box:
      if (prim.box.x <= 0 || prim.box.y <= 0 || prim.box.z <= 0) return true;
      g = dCreateBox(space, prim.box.x, prim.box.y, prim.box.z);
      break;
    case Form::Sphere:
      if (prim.radius <= 0) return true;
      g = dCreateSphere(space, prim.radius);
      break;
    case Form::Cylinder:
      if (prim.radius <= 0 || prim.height <= 0) return true;
      g = dCreateCylinder(space, prim.radius, prim.height);
      break;
    case Form::Plane: {
      if (body) {
        diags.error(n.loc, "a Plane is endless ground and cannot be part of the Body '" + body->node->path() + "'");
        return false;
      }
      const Vec3 normal = n.world.rotation.rotate(n.vec3(scene::field::Plane::Normal)).normalized();
      g = dCreatePlane(space, normal.x, normal.y, normal.z, normal.dot(n.world.position));
      break;
    }
    case Form::Terrain:
      if (body) {
        diags.error(n.loc, "a Terrain is ground and cannot be part of the Body '" + body->node->path() + "'");
        return false;
      }
      g = terrainGeom(n, dir, diags);
      if (!g) return false;
      break;
    case Form::Mesh: {
      const auto mesh = meshOf(n, dir, diags);
      if (!mesh) return false;
      const auto kind = n.choice<scene::MeshCollision>(scene::field::Mesh::Collision);
      if (kind == scene::MeshCollision::Box || mesh->points.size() < 12 ||
          (kind == scene::MeshCollision::Convex && mesh->planes.empty())) {
        const Vec3 size = mesh->box.hi - mesh->box.lo;
        if (size.x <= 0 || size.y <= 0 || size.z <= 0) return true;
        g = dCreateBox(space, size.x, size.y, size.z);
        geom_pose = n.world * Pose{(mesh->box.lo + mesh->box.hi) * 0.5, {}};
      } else if (kind == scene::MeshCollision::Convex) {
        g = dCreateConvex(space, mesh->planes.data(), static_cast<unsigned>(mesh->planes.size() / 4),
                          mesh->hull_points.data(), static_cast<unsigned>(mesh->hull_points.size() / 3),
                          mesh->polygons.data());
      } else {
        dTriMeshDataID data = dGeomTriMeshDataCreate();
        dGeomTriMeshDataBuildDouble(data, mesh->points.data(), 3 * sizeof(double),
                                    static_cast<int>(mesh->points.size() / 3), mesh->indices.data(),
                                    static_cast<int>(mesh->indices.size()), 3 * sizeof(dTriIndex));
        dGeomTriMeshDataPreprocess2(data, 1U << dTRIDATAPREPROCESS_BUILD_FACE_ANGLES, nullptr);
        trimesh_data.push_back(data);
        g = dCreateTriMesh(space, data, nullptr, nullptr, nullptr);
      }
      break;
    }
    // a shape is never made as a cone (shapePrimitive: a Cone collides as a cylinder)
    case Form::None:
    case Form::Cone:
    case Form::Ray: return true;
  }
  // what the geometry brings to contacts: the material in effect, a conveyor beside it
  surfaces.push_back(surfaceFor(n, st, body));
  dGeomSetData(g, reinterpret_cast<void*>(surfaces.size()));  // 1-based: 0 means none
  geom_of[n.handle()] = g;
  shapes.push_back(g);
  shapes_changed = true;
  // ground is placed as made
  if (prim.form == Form::Plane || prim.form == Form::Terrain) return true;
  const Pose& at = geom_pose;
  const dQuaternion q = {at.rotation.w, at.rotation.x, at.rotation.y, at.rotation.z};
  if (body) {
    dGeomSetBody(g, body->id);
    dGeomSetOffsetWorldPosition(g, at.position.x, at.position.y, at.position.z);
    dGeomSetOffsetWorldQuaternion(g, q);
  } else {
    dGeomSetPosition(g, at.position.x, at.position.y, at.position.z);
    dGeomSetQuaternion(g, q);
  }
  return true;
}

}  // namespace gdpn::physics
