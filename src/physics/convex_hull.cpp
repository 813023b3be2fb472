// The convex hull of a point cloud, for convex collision meshes.

#include "convex_hull.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "gdpn/core/math.h"

namespace gdpn::physics {

using core::Vec3;

void convexHull(const std::vector<double>& points, std::vector<double>& planes, std::vector<double>& out_points,
                std::vector<unsigned>& polygons) {
  const std::size_t n = points.size() / 3;
  auto P = [&](std::size_t i) { return Vec3{points[3 * i], points[3 * i + 1], points[3 * i + 2]}; };
  if (n < 4) return;
  core::Aabb box;
  for (std::size_t i = 0; i < n; ++i) box.add(P(i));
  const Vec3 extent = box.hi - box.lo;
  const double eps = 1e-9 * std::max({extent.x, extent.y, extent.z, 1e-12});
  // a first tetrahedron: two far points, the farthest from their line, the farthest from their plane
  std::size_t a = 0, b = 0;
  for (std::size_t i = 0; i < n; ++i) {
    if (P(i).x < P(a).x) a = i;
    if (P(i).x > P(b).x) b = i;
  }
  if ((P(b) - P(a)).length() <= eps) {
    for (std::size_t i = 0; i < n; ++i) {
      if ((P(i) - P(a)).length() > (P(b) - P(a)).length()) b = i;
    }
  }
  std::size_t c = a, d = a;
  double best = eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double dist = (P(i) - P(a)).cross(P(b) - P(a)).length();
    if (dist > best) best = dist, c = i;
  }
  if (c == a) return;
  Vec3 normal = (P(b) - P(a)).cross(P(c) - P(a)).normalized();
  best = eps;
  for (std::size_t i = 0; i < n; ++i) {
    const double dist = std::abs(normal.dot(P(i) - P(a)));
    if (dist > best) best = dist, d = i;
  }
  if (d == a) return;
  struct Face {
    std::size_t v[3];
    Vec3 normal;
    double offset;
    bool alive = true;
  };
  std::vector<Face> faces;
  const Vec3 inside = (P(a) + P(b) + P(c) + P(d)) * 0.25;
  auto add = [&](std::size_t i, std::size_t j, std::size_t k) {
    Face f{{i, j, k}, (P(j) - P(i)).cross(P(k) - P(i)).normalized(), 0.0};
    if (f.normal.dot(inside - P(i)) > 0) {  // face the outside
      std::swap(f.v[1], f.v[2]);
      f.normal = -f.normal;
    }
    f.offset = f.normal.dot(P(f.v[0]));
    faces.push_back(f);
  };
  add(a, b, c), add(a, b, d), add(a, c, d), add(b, c, d);
  for (std::size_t p = 0; p < n; ++p) {
    const Vec3 x = P(p);
    std::vector<std::size_t> seen;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      if (faces[f].alive && faces[f].normal.dot(x) - faces[f].offset > eps) seen.push_back(f);
    }
    if (seen.empty()) continue;
    // the horizon: edges of seen faces whose reverse is not an edge of another seen face
    std::map<std::pair<std::size_t, std::size_t>, int> edges;
    for (auto f : seen) {
      for (int e = 0; e < 3; ++e) edges[{faces[f].v[e], faces[f].v[(e + 1) % 3]}] += 1;
      faces[f].alive = false;
    }
    for (const auto& [edge, count] : edges) {
      if (edges.count({edge.second, edge.first}) != 0) continue;
      Face f{{edge.first, edge.second, p}, (P(edge.second) - P(edge.first)).cross(x - P(edge.first)).normalized(), 0.0};
      f.offset = f.normal.dot(P(edge.first));
      faces.push_back(f);
    }
  }
  std::map<std::size_t, unsigned> index;
  for (const auto& f : faces) {
    if (!f.alive) continue;
    planes.insert(planes.end(), {f.normal.x, f.normal.y, f.normal.z, f.offset});
    polygons.push_back(3);
    for (auto v : f.v) {
      auto [it, added] = index.emplace(v, static_cast<unsigned>(index.size()));
      if (added) out_points.insert(out_points.end(), {P(v).x, P(v).y, P(v).z});
      polygons.push_back(it->second);
    }
  }
}

}  // namespace gdpn::physics
