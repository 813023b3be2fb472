// Where a dropped part lands: on top of a part, snapped to a part's end or side, or on the floor.

#include "gdpn/ide/part_snap.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gdpn/scene/actions.h"

namespace gdpn::ide {

namespace {

using core::Aabb;
using core::Vec3;

constexpr double kEps = 1e-9;

Vec3 centreOf(const Aabb& b) { return (b.lo + b.hi) * 0.5; }
Vec3 halfOf(const Aabb& b) { return (b.hi - b.lo) * 0.5; }

/// `v` tidied for the file: whole nanometres, and never -0.
double tidy(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0 ? 0.0 : r;
}

/// `v` on the grid of `step` (none when 0).
double onGrid(double v, double step) { return step > 0 ? tidy(std::round(v / step) * step) : tidy(v); }

/// The place at `local` (the dropped part's origin in `n`'s frame), turned as `n` is.
DropPlace placedBy(const PartFootprint& n, const Vec3& local, SnapKind kind) {
  const Vec3 p = poseAboutZ(n.position, n.angle).apply(local);
  return {{tidy(p.x), tidy(p.y), tidy(p.z)}, tidy(n.angle), kind, n.name};
}

/// On top of the part whose top face the ray enters first, when the dropped box fits inside its
/// footprint.
std::optional<DropPlace> onTop(const DropQuery& q, const Aabb& box) {
  const PartFootprint* first = nullptr;
  double nearest = std::numeric_limits<double>::infinity();
  Vec3 hit;
  for (const auto& n : q.neighbours) {
    if (n.box.empty()) continue;
    const core::Pose inv = poseAboutZ(n.position, n.angle).inverse();
    const core::Ray local{inv.apply(q.ray.origin), inv.rotation.rotate(q.ray.direction)};
    const double t = core::intersect(local, n.box);
    if (t < 0 || t >= nearest) continue;
    nearest = t;
    first = &n;
    hit = local.origin + local.direction * t;
  }
  // the part seen first is entered through its top, and the dropped part fits inside it
  if (first == nullptr || std::abs(hit.z - first->box.hi.z) > 1e-6) return std::nullopt;
  const Vec3 size = box.hi - box.lo, room = first->box.hi - first->box.lo;
  if (!(size.x < room.x - 1e-6 && size.y < room.y - 1e-6)) return std::nullopt;
  const Vec3 c = centreOf(box);
  const double x = std::clamp(onGrid(hit.x - c.x, q.grid), first->box.lo.x - box.lo.x, first->box.hi.x - box.hi.x);
  const double y = std::clamp(onGrid(hit.y - c.y, q.grid), first->box.lo.y - box.lo.y, first->box.hi.y - box.hi.y);
  return placedBy(*first, {x, y, first->box.hi.z}, SnapKind::OnTop);
}

}  // namespace

const char* snapKindName(SnapKind kind) {
  switch (kind) {
    case SnapKind::Floor: return "floor";
    case SnapKind::OnTop: return "on top";
    case SnapKind::EndPlusX: return "end +x";
    case SnapKind::EndMinusX: return "end -x";
    case SnapKind::SidePlusY: return "side +y";
    case SnapKind::SideMinusY: return "side -y";
    case SnapKind::CentreLine: return "centre line";
  }
  return "?";
}

double angleAboutZ(const std::array<double, 4>& rotation) {
  const Vec3 axis{rotation[0], rotation[1], rotation[2]};
  const double l = axis.length();
  if (l < kEps || std::abs(std::abs(axis.z) / l - 1.0) > 1e-9) return 0.0;
  return axis.z > 0 ? rotation[3] : -rotation[3];
}

core::Pose poseAboutZ(const Vec3& position, double angle) {
  return {position, core::Quat::axisAngle({0, 0, 1}, core::radians(angle))};
}

std::optional<DropPlace> placeDrop(const DropQuery& q) {
  // a part with no shapes is a point at its origin
  const Aabb box = q.box.empty() ? Aabb{{0, 0, 0}, {0, 0, 0}} : q.box;
  if (auto top = onTop(q, box)) return top;

  // the floor under the pointer holds the dropped box's centre
  if (q.ray.direction.z > -kEps) return std::nullopt;
  const Vec3 p = q.ray.origin + q.ray.direction * (-q.ray.origin.z / q.ray.direction.z);
  const Vec3 bc = centreOf(box), bh = halfOf(box);

  // the part whose box comes nearest that box captures it, within `capture`
  const PartFootprint* best = nullptr;
  double best_gap = 0, best_distance = 0;
  Vec3 at;  // the pointer in the best part's frame
  for (const auto& n : q.neighbours) {
    if (n.box.empty()) continue;
    const Vec3 c = poseAboutZ(n.position, n.angle).inverse().apply(p);
    const Vec3 ac = centreOf(n.box), ah = halfOf(n.box);
    const double gap_x = std::max(0.0, std::abs(c.x - ac.x) - (ah.x + bh.x));
    const double gap_y = std::max(0.0, std::abs(c.y - ac.y) - (ah.y + bh.y));
    const double gap = std::max(gap_x, gap_y);
    const double distance = std::hypot(c.x - ac.x, c.y - ac.y);
    if (gap > q.capture + kEps) continue;
    if (best == nullptr || gap < best_gap - kEps || (std::abs(gap - best_gap) <= kEps && distance < best_distance)) {
      best = &n;
      best_gap = gap;
      best_distance = distance;
      at = c;
    }
  }
  if (best == nullptr) return DropPlace{{onGrid(p.x - bc.x, q.grid), onGrid(p.y - bc.y, q.grid), 0.0}, 0.0, SnapKind::Floor, {}};

  // the side of its box the pointer is on, split by the box's diagonals
  const Aabb& a = best->box;
  const Vec3 ac = centreOf(a), ah = halfOf(a);
  const Vec3 d = at - ac;
  const bool along_x = std::abs(d.x) * std::max(ah.y, kEps) >= std::abs(d.y) * std::max(ah.x, kEps);
  if (along_x) {
    // end to end, centre lines aligned
    const bool plus = d.x >= 0;
    const double x = plus ? a.hi.x - box.lo.x : a.lo.x - box.hi.x;
    return placedBy(*best, {x, ac.y - bc.y, 0.0}, plus ? SnapKind::EndPlusX : SnapKind::EndMinusX);
  }
  // side by side, sliding along it on the grid
  const bool plus = d.y >= 0;
  const double x = onGrid(at.x - bc.x, q.grid);
  // on the centre line the box spans the part's width (posts on both sides of a belt): there
  if (box.lo.y <= a.lo.y + kEps && box.hi.y >= a.hi.y - kEps) return placedBy(*best, {x, 0.0, 0.0}, SnapKind::CentreLine);
  const double y = plus ? a.hi.y - box.lo.y : a.lo.y - box.hi.y;
  if (std::abs(y) <= q.centre_line) return placedBy(*best, {x, 0.0, 0.0}, SnapKind::CentreLine);
  return placedBy(*best, {x, y, 0.0}, plus ? SnapKind::SidePlusY : SnapKind::SideMinusY);
}

core::Aabb localBox(const scene::Node& frame) {
  const core::Pose inverse = frame.framePose().inverse();
  Aabb box;
  for (const auto& child : frame.children()) {
    scene::traverse(*child, [&](scene::Node& n, const scene::TraversalState&) {
      if (n.type().category != scene::Category::Shape) return;
      const Aabb own = scene::shapeBounds(n);
      if (own.empty()) return;
      Aabb scaled;  // a negative scale swaps corners
      scaled.add(own.lo.times(n.world_scale));
      scaled.add(own.hi.times(n.world_scale));
      box.add(scaled.transformed(inverse * n.world));
    }, {}, scene::Templates::Skip);
  }
  return box;
}

}  // namespace gdpn::ide
