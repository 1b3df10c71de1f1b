#include "InputWarnings.h"

#include "Clean.h"
#include "Predicates.h"
#include "Series.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>

namespace osm
{

/// Segment s of a round (the input's, then the hull's) as the user numbers it.
std::string segmentName(const Work& w, int s)
{
  return s < static_cast<int>(w.segments.size())
    ? "input segment " + std::to_string(w.segmentOrigin[s])
    : std::string("an edge of the convex hull");
}

namespace
{

/// The input point (a working vertex) nearest p other than `except`, or -1.
/// A scan: the notes below run once, on the way out.
int nearestInputPoint(const Work& w, const Array<int>& pointOf, const Point& p, int except)
{
  int nearest = -1;
  double best = std::numeric_limits<double>::infinity();
  for (int q : pointOf)
    if (q >= 0 && q != except && dist2(p, w.points[q]) < best)
      best = dist2(p, w.points[q]), nearest = q;
  return nearest;
}

/// "point N at (x, y)": working vertex v as the user numbers and places it.
std::string userPoint(
  const Pslg& input, const Array<int>& pointOf, int v, const PointFormat& format)
{
  return namePoint(input, firstInputPoint(pointOf, v), format);
}

} // namespace

std::string nearestPointsNote(const Work& w, const Point& at, const Pslg& input,
  const Array<int>& pointOf, const PointFormat& format)
{
  const int a = nearestInputPoint(w, pointOf, at, -1);
  const int b = a >= 0 ? nearestInputPoint(w, pointOf, w.points[a], a) : -1;
  if (b < 0)
    return "";
  // Only a pair below what the error speaks of, at the place it names (points
  // a hair apart elsewhere are not the cause: crossings may be).
  const Point &pa = w.points[a], &pb = w.points[b];
  const double magnitude = std::max({ std::fabs(pa.x), std::fabs(pa.y), std::fabs(pb.x),
    std::fabs(pb.y), std::fabs(at.x), std::fabs(at.y) });
  if (!(dist2(pa, pb) <= std::pow(1e-12 * magnitude, 2) &&
        dist2(pa, at) <= std::pow(1e-9 * magnitude, 2)))
    return "";
  const auto user = [&](int q) { return userPoint(input, pointOf, q, format); };
  // Their distance as given, like their coordinates (hypot: no square to
  // overflow or underflow at 1e200 or 1e-300).
  const Point &ua = input.points[firstInputPoint(pointOf, a)],
              &ub = input.points[firstInputPoint(pointOf, b)];
  const double apart = std::hypot(ua.x - ub.x, ua.y - ub.y);
  return "; the input points nearest there are " + user(std::min(a, b)) + " and " +
    user(std::max(a, b)) + ", " + roughNumber(apart) + " apart";
}

std::string sharedEndNote(const Work& w, int a, int b, const Pslg& input, const Array<int>& pointOf,
  const Frame& frame, double reach, const PointFormat& format)
{
  const auto segments = static_cast<int>(w.segments.size());
  if (a < 0 || b < 0 || a >= segments || b >= segments)
    return "";
  const Segment &s = w.segments[a], &t = w.segments[b];
  const int end = s[0] == t[0] || s[0] == t[1] ? s[0] : s[1] == t[0] || s[1] == t[1] ? s[1] : -1;
  if (end < 0)
    return "";
  const Point& p = w.points[end];
  const Point& u = w.points[s[0] == end ? s[1] : s[0]];
  const Point& v = w.points[t[0] == end ? t[1] : t[0]];
  // The tolerance that would bend one segment onto the other's far end.
  const double apart =
    std::ldexp(std::min(distanceToSegment(u, p, v), distanceToSegment(v, p, u)), frame.exponent);
  if (!(apart > reach))
    return "";
  const double ux = u.x - p.x, uy = u.y - p.y, vx = v.x - p.x, vy = v.y - p.y;
  const double degrees =
    std::fabs(std::atan2(ux * vy - uy * vx, ux * vx + uy * vy)) * 180 / series::kPi;
  const int nearest = nearestInputPoint(w, pointOf, p, end);
  const auto user = [&](int q) { return userPoint(input, pointOf, q, format); };
  std::string note = "; " + segmentName(w, a) + " and " + segmentName(w, b) + " meet at " +
    user(end) + " at an angle of " + roughNumber(degrees) + " degrees";
  if (nearest >= 0)
    note += ", and " + user(nearest) + " lies " +
      roughNumber(std::ldexp(std::sqrt(dist2(p, w.points[nearest])), frame.exponent)) +
      " from there: the mesh there is as fine as that distance, too fine to separate the two "
      "segments in double precision";
  return note +
    ". A wider angle, or the nearby points farther away, let it mesh; a merge "
    "tolerance would have to be " +
    roughNumber(apart) + ", which bends one segment onto the other's far end";
}

/// "input segment A and input segment B cross near (x, y)", in user coordinates.
std::string describeCrossing(
  const Work& w, const SegmentCrossing& c, const Frame& frame, const PointFormat& format)
{
  const Point p = frame.toUser(c.p);
  return segmentName(w, c.a) + " and " + segmentName(w, c.b) + " cross near " +
    formatPoint(p, format);
}

std::string crossingError(const Work& w, const Array<SegmentCrossing>& crossings,
  const Frame& frame, const PointFormat& format)
{
  std::string msg = describeCrossing(w, crossings.front(), frame, format);
  // At least: segments through one point are found as pairs in a chain, not
  // every pair of them.
  if (crossings.size() > 1)
    msg += " (and at least " + std::to_string(crossings.size() - 1) + " more crossing pair(s))";
  return msg;
}

/// Why the auto domain meshed the hull where the segments look meant to
/// enclose a region (a user review: an outline that missed closing by 1e-9,
/// or by its last segment, was meshed as its hull without a word): two
/// segment ends that meet no other segment (of at most 1,000 such), joined
/// by a path of two or more segments, lie within 1e-6 of the extent of each
/// other, so that joining them closes a loop; or the segments form one open
/// chain of three or more that is not straight. Names the user's points; ""
/// otherwise.
std::string openOutlineWarning(
  const Work& w, const Pslg& input, const Array<int>& pointOf, const PointFormat& format)
{
  Array<int> degree(w.points.size(), 0);
  for (const Segment& s : w.segments)
    ++degree[s[0]], ++degree[s[1]];
  // Ends are named by input point: a split crossing, which has none, has 2 or
  // more segments.
  Array<std::uint8_t> isInput(w.points.size(), 0);
  for (int v : pointOf)
    if (v >= 0 && static_cast<std::size_t>(v) < isInput.size())
      isInput[v] = 1;
  Array<int> ends;
  std::size_t touched = 0;
  for (std::size_t v = 0; v < degree.size(); ++v)
  {
    touched += degree[v] > 0;
    if (degree[v] == 1 && isInput[v])
      ends.push_back(static_cast<int>(v));
  }
  const auto name = [&](int v) { return userPoint(input, pointOf, v, format); };
  const std::string hull = ": the segments enclose no region, so the auto domain meshes the "
                           "convex hull of the points (the hull domain does so without this "
                           "warning)";
  // A soup of segments, not an outline: the search would cost a few percent.
  if (ends.size() > 1000)
    return "";
  // The segments' connected components (union-find).
  Array<int> parent(w.points.size());
  for (std::size_t v = 0; v < parent.size(); ++v)
    parent[v] = static_cast<int>(v);
  const auto root = [&](int v) {
    while (parent[v] != v)
      v = parent[v] = parent[parent[v]];
    return v;
  };
  for (const Segment& s : w.segments)
    parent[root(s[0])] = root(s[1]);
  // The nearest two ends within reach that a path of two or more segments
  // joins (not the two ends of one segment), by cells of that size.
  Array<int> adjacentEnd(w.points.size(), -1); // an isolated segment's other end
  for (const Segment& s : w.segments)
    if (degree[s[0]] == 1 && degree[s[1]] == 1)
      adjacentEnd[s[0]] = s[1], adjacentEnd[s[1]] = s[0];
  const Bounds b = boundsOf(w.points);
  const double reach = 1e-6 * std::max(b.width(), b.height());
  std::unordered_map<std::uint64_t, Array<int>> cells;
  const auto cell = [&](const Point& p, int dx, int dy) {
    const auto i = static_cast<std::int64_t>((p.x - b.lo.x) / reach) + dx; // at most 1e6 + 1
    const auto j = static_cast<std::int64_t>((p.y - b.lo.y) / reach) + dy;
    return static_cast<std::uint64_t>(i + 1) << 32 | static_cast<std::uint64_t>(j + 1);
  };
  int bestA = -1, bestB = -1;
  double best = reach;
  for (int v : ends)
  {
    const Point& p = w.points[v];
    for (int dx = -1; reach > 0 && dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        if (const auto it = cells.find(cell(p, dx, dy)); it != cells.end())
          for (int u : it->second)
            if (const double d = std::sqrt(dist2(p, w.points[u]));
                d <= best && root(u) == root(v) && adjacentEnd[u] != v)
              best = d, bestA = u, bestB = v;
    if (reach > 0)
      cells[cell(p, 0, 0)].push_back(v);
  }
  if (bestA >= 0)
  {
    const Point& p = input.points[firstInputPoint(pointOf, bestA)];
    const Point& q = input.points[firstInputPoint(pointOf, bestB)];
    return "segment ends at " + name(bestA) + " and " + name(bestB) + " meet no other segment, " +
      formatNumber(std::hypot(p.x - q.x, p.y - q.y)) +
      " apart, and joined they would close a loop" + hull +
      "; a merge tolerance that large joins them (osm-mesh --merge-tolerance, the filter's "
      "MergeTolerance)";
  }
  const bool oneChain = ends.size() == 2 && w.segments.size() >= 3 &&
    w.segments.size() + 1 == touched &&
    std::all_of(degree.begin(), degree.end(), [](int d) { return d <= 2; });
  const auto straight = [&] {
    const Point &a = w.points[ends[0]], &c = w.points[ends[1]];
    return std::all_of(w.segments.begin(), w.segments.end(), [&](const Segment& s) {
      return orient2d(a, c, w.points[s[0]]) == 0 && orient2d(a, c, w.points[s[1]]) == 0;
    });
  };
  if (oneChain && !straight())
    return "the segments form one open chain, from " + name(ends[0]) + " to " + name(ends[1]) +
      hull;
  return "";
}

/// Why regions meant to be parted are one (a workflow review: isolines in
/// floats end 1e-8 short of the boundary they were cut from, and a band
/// meshed as its neighbour's, with no word): the input segment ends the walk
/// found within reach of an input segment they do not touch. Names the
/// nearest; "" if none. walked: the walk's segments (overlay vertices).
std::string nearMissWarning(const Work& w, const Walk& walk, const Array<Segment>& walked,
  const Pslg& input, const Array<int>& pointOf, const Frame& frame, const PointFormat& format)
{
  if (walk.nearMisses.empty())
    return "";
  const std::size_t count = walk.nearMisses.size();
  const NearMiss* nearest = &*std::min_element(walk.nearMisses.begin(), walk.nearMisses.end(),
    [](const NearMiss& a, const NearMiss& b) { return a.distance < b.distance; });
  const int end =
    w.segments[nearest->endSegment][walked[nearest->endSegment][0] == nearest->end ? 0 : 1];
  const int user = firstInputPoint(pointOf, end);
  const std::string gap = formatNumber(std::ldexp(nearest->distance, frame.exponent));
  return std::to_string(count) +
    " segment end(s) stop a hair short of a segment they do not reach (within 1e-6 of the "
    "extent, or, where every coordinate is a float, within float rounding), e.g. " +
    namePoint(input, user, format) + ", " + gap + " from " + segmentName(w, nearest->segment) +
    ": they do not meet it, and regions they were meant to part are meshed as one; a merge "
    "tolerance above the gap joins them (osm-mesh --merge-tolerance, the filter's "
    "MergeTolerance)";
}

/// Why the mesh grades down to a hair somewhere (a review: a float slice of
/// a sphere had points one float step apart, and gave 50 times the triangles
/// with no word). A point's nearest neighbour is joined to it in a Delaunay
/// triangulation, and the refinement puts no Steiner point nearer: the
/// overlay's edges find the pairs. Crossing points are the mesher's own.
Array<ClosePair> closePointPairs(const Work& w, const Overlay& overlay, const OverlayEdges& ov,
  const NearMissSearch& search, const Pslg& input, const Array<int>& pointOf)
{
  const Array<Point>& P = overlay.mesh.points;
  Array<Segment> near; // overlay vertices: rarely any
  for (std::size_t h = 0; h < ov.idBound(); ++h)
  {
    if (!ov.isEdge(static_cast<int>(h)))
      continue;
    const auto [a, b] = ov.ends(static_cast<int>(h));
    const double reach = search.at(P[a]);
    if (overlay.isInput[a] && overlay.isInput[b] && dist2(P[a], P[b]) < reach * reach)
      near.push_back({ a, b });
  }
  Array<ClosePair> pairs;
  if (near.empty())
    return pairs;
  Array<int> pointAt(P.size(), -1); // overlay vertex -> working point
  for (std::size_t i = 0; i < overlay.inputVertex.size(); ++i)
    pointAt[overlay.inputVertex[i]] = static_cast<int>(i);
  // Working point -> its first input point, once: a search per pair took
  // 80 s on 200,000 points a hair apart along a line (a review).
  Array<int> firstOf(w.points.size(), -1);
  for (std::size_t k = pointOf.size(); k-- > 0;)
    if (pointOf[k] >= 0 && static_cast<std::size_t>(pointOf[k]) < firstOf.size())
      firstOf[pointOf[k]] = static_cast<int>(k);
  for (const auto& [u, v] : near)
  {
    const int i = pointAt[u], j = pointAt[v];
    if (i < 0 || j < 0 || w.isCrossingPoint[i] || w.isCrossingPoint[j])
      continue;
    const int a = firstOf[i], b = firstOf[j];
    if (a < 0 || b < 0)
      continue;
    // From the user's coordinates: the working ones are translated, rounded.
    pairs.push_back(
      { std::min(a, b), std::max(a, b), std::sqrt(dist2(input.points[a], input.points[b])) });
  }
  return pairs;
}

std::string closePointsWarning(const Array<ClosePair>& pairs, const Array<int>& inputVertex,
  const Pslg& input, const PointFormat& format)
{
  std::size_t count = 0;
  const ClosePair* nearest = nullptr;
  for (const ClosePair& q : pairs)
    if (inputVertex[q.a] >= 0 && inputVertex[q.b] >= 0 && ++count &&
      (!nearest || q.distance < nearest->distance))
      nearest = &q;
  if (!nearest)
    return "";
  return std::to_string(count) +
    " pair(s) of input points in the mesh lie a hair apart (within 1e-6 of the extent, or, where "
    "every coordinate is a float, within float rounding), e.g. " +
    namePoint(input, nearest->a, format) + " and point " + std::to_string(nearest->b) + ", " +
    formatNumber(nearest->distance) +
    " apart: the mesh grades down to their distance around them; if they are meant as one "
    "point, a merge tolerance above it merges them (osm-mesh --merge-tolerance, the filter's "
    "MergeTolerance)";
}

/// A merge tolerance to try where segments meet closer than double precision
/// separates (a workflow review: a figure-eight through the origin failed,
/// and the message gave no value to type): 1e-9 of the input's extent,
/// far below any feature meant, far above the rounding. "" where the
/// tolerance given is that already.
double toleranceSuggested(const Bounds& input)
{
  return 1e-9 * std::max(input.width(), input.height());
}

std::string toleranceToTry(const Bounds& input, double given)
{
  const double suggested = toleranceSuggested(input);
  if (!(suggested > given))
    return "";
  return " (try about 1e-9 of the input's extent: " + roughNumber(suggested) + ")";
}

} // namespace osm
