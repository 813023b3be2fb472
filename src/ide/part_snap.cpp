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
constexpr double kSpan = 0.01;  // wider than a part by this on each side: across it, m

Vec3 centreOf(const Aabb& b) { return (b.lo + b.hi) * 0.5; }
Vec3 halfOf(const Aabb& b) { return (b.hi - b.lo) * 0.5; }

/// `v` tidied for the file: whole nanometres, and never -0.
double tidy(double v) {
  const double r = std::round(v * 1e9) / 1e9;
  return r == 0 ? 0.0 : r;
}

/// `v` on the grid of `step` (none when 0).
double onGrid(double v, double step) { return step > 0 ? tidy(std::round(v / step) * step) : tidy(v); }

/// The place at `local` (the dropped part's origin in `n`'s frame), turned as `n` is and by
/// `turn` degrees more.
DropPlace placedBy(const PartFootprint& n, const Vec3& local, SnapKind kind, double turn = 0) {
  const Vec3 p = poseAboutZ(n.position, n.angle).apply(local);
  const double angle = std::remainder(n.angle + turn, 360.0);
  return {{tidy(p.x), tidy(p.y), tidy(p.z)}, tidy(angle == -180.0 ? 180.0 : angle), kind, n.name};
}

/// The part the ray enters first, and where (in that part's frame).
struct FirstHit {
  const PartFootprint* part = nullptr;
  Vec3 local;  // where the ray enters its box, in its frame
};

FirstHit firstHit(const DropQuery& q) {
  FirstHit first;
  double nearest = std::numeric_limits<double>::infinity();
  for (const auto& n : q.neighbours) {
    if (n.box.empty()) continue;
    const core::Pose inv = poseAboutZ(n.position, n.angle).inverse();
    const core::Ray local{inv.apply(q.ray.origin), inv.rotation.rotate(q.ray.direction)};
    const double t = core::intersect(local, n.box);
    if (t < 0 || t >= nearest) continue;
    nearest = t;
    first = {&n, local.origin + local.direction * t};
  }
  return first;
}

/// On top of the part the ray enters first through its top face, when the dropped box fits
/// inside its footprint.
/// True when the ray enters the part it meets first through that part's top face.
bool throughTop(const FirstHit& first) {
  return first.part != nullptr && std::abs(first.local.z - first.part->box.hi.z) <= 1e-6;
}

std::optional<DropPlace> onTop(const DropQuery& q, const FirstHit& first, const Aabb& box) {
  if (!q.loose || !throughTop(first)) return std::nullopt;
  const Aabb& a = first.part->box;
  const Vec3 size = box.hi - box.lo, room = a.hi - a.lo;
  if (!(size.x < room.x - 1e-6 && size.y < room.y - 1e-6)) return std::nullopt;
  const Vec3 c = centreOf(box);
  const double x = std::clamp(onGrid(first.local.x - c.x, q.grid), a.lo.x - box.lo.x, a.hi.x - box.hi.x);
  const double y = std::clamp(onGrid(first.local.y - c.y, q.grid), a.lo.y - box.lo.y, a.hi.y - box.hi.y);
  return placedBy(*first.part, {x, y, a.hi.z}, SnapKind::OnTop);
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

Aabb turnedAboutZ(const Aabb& box, double angle) {
  if (box.empty() || angle == 0) return box;
  Aabb out = box.transformed(poseAboutZ({0, 0, 0}, angle));
  // whole nanometres, so that a quarter turn's sines of 1e-17 leave no trace in the file
  for (Vec3* c : {&out.lo, &out.hi}) *c = {tidy(c->x), tidy(c->y), tidy(c->z)};
  return out;
}

std::optional<DropPlace> placeDrop(const DropQuery& q) {
  // a part with no shapes is a point at its origin
  const Aabb box = q.box.empty() ? Aabb{{0, 0, 0}, {0, 0, 0}} : q.box;
  const auto first = firstHit(q);
  if (auto top = onTop(q, first, box)) return top;

  // what is under the pointer (the top of the part it points at, else the floor) holds the
  // box's centre
  Vec3 p;
  if (throughTop(first)) {
    p = poseAboutZ(first.part->position, first.part->angle).apply(first.local);
  } else if (q.ray.direction.z < -kEps) {
    p = q.ray.origin + q.ray.direction * (-q.ray.origin.z / q.ray.direction.z);
  } else {
    return std::nullopt;
  }
  const Vec3 bc = centreOf(box), bh = halfOf(box);

  // the part whose box comes nearest that box captures it, within `capture`
  const PartFootprint* best = nullptr;
  double best_gap = 0, best_area = 0, best_distance = 0;
  Vec3 at;  // the pointer in the best part's frame
  for (const auto& n : q.neighbours) {
    if (n.box.empty()) continue;
    const Vec3 c = poseAboutZ(n.position, n.angle).inverse().apply(p);
    const Vec3 ac = centreOf(n.box), ah = halfOf(n.box);
    const double gap_x = std::max(0.0, std::abs(c.x - ac.x) - (ah.x + bh.x));
    const double gap_y = std::max(0.0, std::abs(c.y - ac.y) - (ah.y + bh.y));
    const double gap = std::max(gap_x, gap_y);
    const double distance = std::hypot(c.x - ac.x, c.y - ac.y);
    const double area = 4 * ah.x * ah.y;
    if (gap > q.capture + kEps) continue;
    const bool tie = std::abs(gap - best_gap) <= kEps;
    if (best == nullptr || gap < best_gap - kEps || (tie && area > best_area + kEps) ||
        (tie && std::abs(area - best_area) <= kEps && distance < best_distance)) {
      best = &n;
      best_gap = gap;
      best_area = area;
      best_distance = distance;
      at = c;
    }
  }
  if (best == nullptr) return DropPlace{{onGrid(p.x - bc.x, q.grid), onGrid(p.y - bc.y, q.grid), 0.0}, 0.0, SnapKind::Floor, {}};

  // wider than the part and pointed at on it: across it, on its centre line (a photo-eye's
  // posts or a portal over a belt)
  const Aabb& a = best->box;
  const Vec3 ac = centreOf(a), ah = halfOf(a);
  const Vec3 d = at - ac;
  const double x = onGrid(at.x - bc.x, q.grid);
  // (how far the pointer lies beyond its ends and beyond its sides: negative inside)
  const double beyond_x = std::abs(d.x) - ah.x, beyond_y = std::abs(d.y) - ah.y;
  if (box.lo.y < a.lo.y - kSpan && box.hi.y > a.hi.y + kSpan && beyond_x <= kEps && beyond_y <= kEps) {
    return placedBy(*best, {x, 0.0, 0.0}, SnapKind::CentreLine);
  }
  // the side of its box nearest the pointer: the one it lies beyond, or nearest inside
  const bool along_x = beyond_x >= beyond_y;
  if (along_x) {
    // end to end, centre lines aligned
    const bool plus = d.x >= 0;
    const double end = plus ? a.hi.x - box.lo.x : a.lo.x - box.hi.x;
    return placedBy(*best, {end, ac.y - bc.y, 0.0}, plus ? SnapKind::EndPlusX : SnapKind::EndMinusX);
  }
  const bool plus = d.y >= 0;
  // a part that reaches over from one side to its origin (a proximity sensor's head on an arm
  // from a post beside a belt: its box passes its origin by no more than the part's half
  // width): its origin on the centre line, its post on the side pointed at, turned half round
  // for the other side
  const bool hangs_plus = box.lo.y < -ah.y && box.hi.y > kSpan && box.hi.y <= ah.y;
  const bool hangs_minus = box.hi.y > ah.y && box.lo.y < -kSpan && box.lo.y >= -ah.y;
  if (hangs_plus || hangs_minus) {
    const bool other = beyond_y > kEps && plus == hangs_plus;
    const double across = onGrid(at.x - centreOf(other ? turnedAboutZ(box, 180) : box).x, q.grid);
    return placedBy(*best, {across, 0.0, 0.0}, SnapKind::CentreLine, other ? 180.0 : 0.0);
  }
  // side by side, sliding along it on the grid; a part drawn on one side of its origin (a
  // pusher, a diffuse photo-eye) faces the part: on its other side it is turned half round
  const bool faces_plus = box.hi.y <= kSpan && box.lo.y < -kSpan;
  const bool faces_minus = box.lo.y >= -kSpan && box.hi.y > kSpan;
  const bool turn = (plus && faces_plus) || (!plus && faces_minus);
  const Aabb b = turn ? Aabb{{-box.hi.x, -box.hi.y, box.lo.z}, {-box.lo.x, -box.lo.y, box.hi.z}} : box;
  const double along = onGrid(at.x - centreOf(b).x, q.grid);
  const double y = plus ? a.hi.y - b.lo.y : a.lo.y - b.hi.y;
  const double half_turn = turn ? 180.0 : 0.0;
  if (std::abs(y) <= q.centre_line) return placedBy(*best, {along, 0.0, 0.0}, SnapKind::CentreLine, half_turn);
  return placedBy(*best, {along, y, 0.0}, plus ? SnapKind::SidePlusY : SnapKind::SideMinusY, half_turn);
}

bool looseMachine(const scene::Node& frame) {
  bool any = false, loose = true;
  for (const auto& child : frame.children()) {
    scene::traverse(*child, [&](scene::Node& n, const scene::TraversalState&) {
      if (n.type().category != scene::Category::Shape) return;
      any = true;
      bool in_body = false;
      for (const scene::Node* up = n.parent(); up != nullptr && up != &frame && !in_body; up = up->parent()) {
        in_body = up->kind() == scene::NodeKind::Body;
      }
      loose = loose && in_body;
    }, {}, scene::Templates::Skip);
  }
  return any && loose;
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
