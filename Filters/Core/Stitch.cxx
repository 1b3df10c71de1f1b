#include "Stitch.h"

#include "Clean.h"
#include "HugePages.h"
#include "NearMisses.h"
#include "Predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <new>
#include <string>

namespace osm
{

OverlayEdges compactOverlay(Triangulation& mesh, RunContext& run)
{
  // The core's peak memory is here, where the slots and their compact copy
  // both live, and nothing else should: a slot's mark (the cavity search's stamp, unused from here
  // on) holds its compact index, and the compact vertex links come once the slots are gone.
  OverlayEdges ov;
  // Triangles in the order of their smallest vertex (a counting sort): with
  // vertices in spatial order, neighbours in the mesh are near in memory.
  const auto lowest = [&](int t) {
    return std::min({ mesh.tri[t].v[0], mesh.tri[t].v[1], mesh.tri[t].v[2] });
  };
  Array<int> start;
  start.assign(mesh.points.size() + 1, 0);
  // Four passes over the triangles, each polling for an abort.
  const double slots = mesh.slots();
  auto poll = [&](int pass, int t) {
    run.tickWith([&] { return (pass + t / slots) / 4; }, 1u << 16);
  };
  for (int t = 0; t < mesh.slots(); ++t)
  {
    poll(0, t);
    if (mesh.alive(t))
      ++start[lowest(t) + 1];
  }
  for (std::size_t v = 0; v + 1 < start.size(); ++v)
    start[v + 1] += start[v];
  // Stitching makes the intact triangles and their adjacency out of tris and
  // nbr in place, and completion appends to them: room now (untouched, it
  // costs only address space) spares copying them then.
  const std::size_t n = start.back(), room = n + n / 2 + 64;
  try
  {
    ov.tris.reserve(room);
    ov.nbr.reserve(room);
  }
  catch (const std::bad_alloc&)
  {}
  ov.tris.resize(n);
  for (int t = 0; t < mesh.slots(); ++t)
  {
    poll(1, t);
    if (!mesh.alive(t))
      continue;
    const int c = start[lowest(t)]++;
    mesh.tri[t].mark = static_cast<std::uint32_t>(c);
    ov.tris[c] = mesh.tri[t].v;
  }
  Array<int>().swap(start);
  ov.nbr.resize(ov.tris.size());
  for (int t = 0; t < mesh.slots(); ++t)
  {
    poll(2, t);
    if (!mesh.alive(t))
      continue;
    std::array<int, 3>& nbr = ov.nbr[mesh.tri[t].mark];
    for (int i = 0; i < 3; ++i)
    {
      const int u = mesh.tri[t].n[i];
      nbr[i] = u < 0 ? -1 : static_cast<int>(mesh.tri[u].mark);
    }
  }
  mesh.releaseTriangles();
  // In this order, near in space, vtri is written near in memory too.
  ov.vtri.assign(mesh.points.size(), -1);
  for (int c = 0; c < static_cast<int>(ov.tris.size()); ++c)
  {
    poll(3, c);
    for (int v : ov.tris[c])
      ov.vtri[v] = c;
  }
  return ov;
}

int OverlayEdges::twin(int c, int i) const
{
  const int u = nbr[c][i];
  if (u < 0)
    return -1;
  const std::array<int, 3>& back = nbr[u];
  return 3 * u + (back[0] == c ? 0 : back[1] == c ? 1 : 2);
}

void keepFirstOfEachPair(Array<SegmentCrossing>& sc)
{
  std::stable_sort(sc.begin(), sc.end(), [](const SegmentCrossing& x, const SegmentCrossing& y) {
    return x.a < y.a || (x.a == y.a && x.b < y.b);
  });
  sc.erase(
    std::unique(sc.begin(), sc.end(),
      [](const SegmentCrossing& x, const SegmentCrossing& y) { return x.a == y.a && x.b == y.b; }),
    sc.end());
}

namespace
{

double cross(double ax, double ay, double bx, double by)
{
  return ax * by - ay * bx;
}

/// Calls f(piece index) for every piece, in segment order and along each
/// segment: the order the walks would have made them in index order.
template <typename F>
void forEachPieceInSegmentOrder(const Walk& walk, F&& f)
{
  for (std::size_t s = 0; s < walk.firstPiece.size(); ++s)
    for (int k = walk.firstPiece[s];
         k >= 0 && k < static_cast<int>(walk.pieces.size()) && walk.pieces[k].segment == int(s);
         ++k)
      f(k);
}

class Walker
{
public:
  Walker(const OverlayEdges& ov, const Overlay& overlay, const Array<Segment>& segments,
    double sinTheta1, NearMissSearch search, double memoryBytes, Walk& out)
    : ov(ov)
    , P(overlay.mesh.points)
    , isInput(overlay.isInput)
    , segments(segments)
    , sinTheta1(sinTheta1)
    , dangling(ov, P, segments, search)
    , out(out)
  {
    // Below so many crossings any machine holds the mesh: its memory is
    // asked only beyond them (askMemory), which small inputs never reach.
    setLimits(memoryBytes < 0 ? kBytesUncheckedAgainstMemory : memoryBytes);
    memoryAsked = memoryBytes >= 0;
  }

  void walk(int segment, int a, int b);
  void findSegmentCrossings(const Array<int>* rank);
  /// After the walks: the near misses between ends, and one per end.
  void finishNearMisses()
  {
    dangling.findAtEnds(out.nearMisses);
    dangling.keepNearest(out.nearMisses);
  }

private:
  int firstStep(int cur, int b, int& l, int& r, int& tri);
  /// How near a segment, in units of rounding, the walk takes vertex v onto
  /// it. A Steiner point: twice the 8 that stitching allows a crossing from
  /// an edge's end (tooClose), so that the walk leaves no crossing stitching
  /// cannot tell from it (a review: one 1.39e-15 off a segment at 0.75
  /// passed the walk's 1.35e-15, and its crossing, 1.33e-15 from it, failed
  /// stitching's 1.34e-15). An input point (or crossing) stays at 8: a wider
  /// reach would take segments onto other segments' points.
  double onSegmentUlps(int v) const { return isInput[v] ? 8 : 16; }
  bool ahead(const Point& from, const Point& x, const Point& B) const;
  void addCrossing(int edge, int piece, const Point& A, const Point& B);
  void refuseCrossings(const Crossing& c);
  void markDuplicates(const Array<int>* rank);
  bool overlapThrough(int a, int b) const;
  void addSegmentCrossing(int a, int b, const Point& p);
  void countSegmentCrossings();
  void refuseSegmentCrossings(std::size_t count);
  void setLimits(double memory);
  bool askMemory();

  const OverlayEdges& ov;
  const Array<Point>& P;
  const Array<char>& isInput;
  const Array<Segment>& segments;
  const double sinTheta1;
  DanglingEnds dangling;
  Walk& out;
  /// This machine's memory (0: unknown, no limit), the points it holds in a
  /// mesh (Overlay.h's meshPointsMemoryHolds), and a
  /// quarter of them: at most so many pairs of segments may cross, counted
  /// again when the records reach nextCount. Until memoryAsked, the memory
  /// of kPointsUncheckedAgainstMemory points.
  double memoryBytes = 0;
  bool memoryAsked = true;
  std::size_t pointsMemoryHolds = 0;
  std::size_t maxSegmentCrossings = 0;
  std::size_t nextCount = 0;
  int walking = -1;                    ///< the segment being walked
  int segmentStart = -1;               ///< first vertex of the segment being walked
  double segmentLength = 0;            ///< its length (addCrossing's A to B)
  Array<std::pair<int, int>> triPiece; ///< (overlay triangle, piece) traversed
  /// (Steiner vertex, segment, piece ending there) passing through it
  Array<std::array<int, 3>> steinerHits;
};

/// x lies strictly further along the segment than from, and not beyond B. The
/// direction is the segment's own, fixed for the whole walk, so the walk only
/// ever advances and cannot cycle.
bool Walker::ahead(const Point& from, const Point& x, const Point& B) const
{
  const Point& A = P[segmentStart];
  const double dx = B.x - A.x, dy = B.y - A.y;
  const double step = (x.x - from.x) * dx + (x.y - from.y) * dy;
  const double rest = (B.x - x.x) * dx + (B.y - x.y) * dy;
  return step > 0 && rest >= 0;
}

/// From vertex cur towards b: returns the next vertex if the segment runs along
/// an overlay edge (setting tri to that edge's id), or -1 and the triangle it
/// enters, with l, r the vertices left and right of the segment.
int Walker::firstStep(int cur, int b, int& l, int& r, int& tri)
{
  const Point& A = P[segmentStart];
  const Point& C = P[cur];
  const Point& B = P[b];
  // A neighbour u ahead that accepts(u): the segment runs along the edge to it.
  int next = -1;
  auto alongEdge = [&](auto accepts) {
    return ov.aroundVertex(cur, [&](int t, int i) {
      const int u = ov.tris[t][(i + 1) % 3];
      if (!ahead(C, P[u], B) || !accepts(u))
        return false;
      tri = ov.edgeId(t, (i + 2) % 3);
      next = u;
      return true;
    }) >= 0;
  };
  // First look for a neighbour on the way to b (within rounding): go there.
  if (alongEdge([&](int u) {
        return onLineWithinRounding(
          orient2d(A, B, P[u]), P[u], std::sqrt(dist2(C, P[u])), segmentLength, onSegmentUlps(u));
      }))
    return next;
  // Otherwise b lies strictly inside the angle of one incident triangle.
  tri = ov.aroundVertex(cur, [&](int t, int i) {
    const int u = ov.tris[t][(i + 1) % 3], w = ov.tris[t][(i + 2) % 3];
    if (orientSign(C, P[u], B) <= 0 || orientSign(C, P[w], B) >= 0)
      return false;
    r = u;
    l = w;
    return true;
  });
  if (tri >= 0)
    return -1;
  // Or b lies exactly beyond a neighbour u, on no triangle's inside: cur
  // was taken onto the segment, a few units of rounding off its line, and u
  // lies on the line from cur to b but outside its own reach of the line
  // (a review: 55 of 1,968 such inputs ended in the error below). The
  // chain's detour from the line is no larger than cur's.
  if (alongEdge([&](int u) { return orientSign(C, P[u], B) == 0; }))
    return next;
  throw Stop{ "internal error: cannot leave vertex " + std::to_string(cur) + " while stitching" };
}

/// Where the line through E with direction (dx, dy) crosses the edge p0 p1,
/// as a fraction of the edge from p0 (in [0, 1]). The subtractions from E
/// round by about machine epsilon times the largest coordinate of E, p0 and
/// p1, and the direction only relatively, so the point is off by a few of
/// those rounding errors (over the sine of the crossing angle, at most 3 for
/// a kept crossing). resolved: that error is well below the edge's length.
double crossingFraction(const Point& E, double dx, double dy, const Point& p0, const Point& p1,
  double edgeLength, bool& resolved)
{
  const double d0 = cross(dx, dy, p0.x - E.x, p0.y - E.y);
  const double d1 = cross(dx, dy, p1.x - E.x, p1.y - E.y);
  const double s = d0 / (d0 - d1);
  const double scale = std::max({ std::fabs(E.x), std::fabs(E.y), std::fabs(p0.x), std::fabs(p0.y),
    std::fabs(p1.x), std::fabs(p1.y) });
  resolved = edgeLength >= 64 * std::numeric_limits<double>::epsilon() * scale;
  return std::min(1.0, std::max(0.0, std::isfinite(s) ? s : 0.5));
}

void Walker::addCrossing(int edge, int piece, const Point& A, const Point& B)
{
  const Segment ends = ov.ends(edge);
  const Point& p0 = P[ends[0]];
  const Point& p1 = P[ends[1]];
  const double dx = B.x - A.x, dy = B.y - A.y, ex = p1.x - p0.x, ey = p1.y - p0.y;
  const double edgeLength = std::hypot(ex, ey);
  Crossing c;
  c.edge = edge;
  c.piece = piece;
  c.s = crossingFraction(A, dx, dy, p0, p1, edgeLength, c.resolved);
  // Far from A, among features that A's coordinates do not resolve (a
  // segment reaching into a tiny cluster at its other end), measure from B.
  if (!c.resolved)
    c.s = crossingFraction(B, dx, dy, p0, p1, edgeLength, c.resolved);
  c.p = { p0.x + c.s * ex, p0.y + c.s * ey };
  // On a horizontal or vertical segment the point takes the segment's own
  // coordinate: placed along the overlay edge it is off the segment by
  // rounding (y = -8.9e-16 on y = 0), which a user selecting y == 0 misses.
  if (A.y == B.y)
    c.p.y = A.y;
  if (A.x == B.x)
    c.p.x = A.x;
  const double sine = std::fabs(cross(dx, dy, ex, ey)) / (segmentLength * edgeLength);
  c.good = sine > sinTheta1;
  out.crossings.push_back(c);
  if (out.crossings.size() > pointsMemoryHolds && pointsMemoryHolds > 0)
    refuseCrossings(c);
  // A segment passing a hair from a vertex crosses the vertex's edges, so
  // near misses cost nothing to find here.
  dangling.crossedNear(ends[0], walking, out.nearMisses);
  dangling.crossedNear(ends[1], walking, out.nearMisses);
}

void Walker::setLimits(double memory)
{
  memoryBytes = memory;
  pointsMemoryHolds =
    memory > 0 ? std::max<std::size_t>(1, std::size_t(meshPointsMemoryHolds(memory))) : 0;
  maxSegmentCrossings = pointsMemoryHolds > 0 ? std::max<std::size_t>(1, pointsMemoryHolds / 4) : 0;
  nextCount = out.segmentCrossings.size() + maxSegmentCrossings;
}

/// The limits from this machine's memory, where not yet asked: false if
/// they were already so.
bool Walker::askMemory()
{
  if (memoryAsked)
    return false;
  memoryAsked = true;
  setLimits(physicalMemoryBytes());
  return true;
}

/// Every crossing of an overlay edge kept is a point of the mesh. Segments
/// far longer than the spacing of the input points they pass cross a dense
/// overlay there: a streamline circling a limit cycle, 70,000 points a hair
/// apart, took 350 s and 17.5 GB to cross it in its first round (a review). As
/// many crossings as the memory holds points end the run, with a word of why.
void Walker::refuseCrossings(const Crossing& c)
{
  if (askMemory() && (pointsMemoryHolds == 0 || out.crossings.size() <= pointsMemoryHolds))
    return;
  Stop stop{ "the segments cross more than " + std::to_string(pointsMemoryHolds) +
    " edges of the overlay, e.g." };
  stop.tail = ": as many as this machine's memory (" + roughNumber(memoryBytes / 1e9) +
    " GB) holds points in a mesh, and each crossing kept is one; segments far longer than the "
    "spacing of the input points they pass (as a streamline circling a limit cycle passes its own "
    "earlier points a hair apart) cross a dense overlay there: trim or coarsen such lines before "
    "meshing";
  stop.segments = { walking, -1 };
  stop.located = true;
  stop.at = c.p;
  throw stop;
}

void Walker::walk(int segment, int a, int b)
{
  const Point& A = P[a];
  const Point& B = P[b];
  walking = segment;
  segmentStart = a;
  segmentLength = std::hypot(B.x - A.x, B.y - A.y);
  int cur = a;
  for (std::size_t pieces = 0; cur != b; ++pieces)
  {
    if (pieces > P.size())
      throw Stop{ "internal error: a stitching walk does not advance" };
    const int piece = static_cast<int>(out.pieces.size());
    out.pieces.push_back({ cur, -1, segment, -1, static_cast<int>(out.crossings.size()), 0 });
    int l = -1, r = -1, t = -1;
    int next = firstStep(cur, b, l, r, t);
    if (next >= 0)
    {
      out.pieces[piece].overlayEdge = t;
    }
    else
    {
      // Cross triangle after triangle until a vertex lies on the segment. The
      // edge to cross next is the one opposite the vertex it does not touch.
      int across = cornerOf(ov.tris[t], cur);
      triPiece.push_back({ t, piece });
      for (std::size_t guard = 0; next < 0; ++guard)
      {
        if (guard > ov.tris.size())
          throw Stop{ "internal error: a stitching walk does not terminate" };
        addCrossing(ov.edgeId(t, across), piece, A, B);
        t = ov.nbr[t][across];
        if (t < 0)
          throw Stop{ "internal error: a segment left the overlay while stitching" };
        triPiece.push_back({ t, piece });
        const int il = cornerOf(ov.tris[t], l), ir = cornerOf(ov.tris[t], r);
        const int x = ov.tris[t][3 - il - ir];
        const double o = orient2d(A, B, P[x]);
        const double local = std::sqrt(std::max(dist2(P[x], P[l]), dist2(P[x], P[r])));
        if (o == 0 ||
          (onLineWithinRounding(o, P[x], local, segmentLength, onSegmentUlps(x)) &&
            ahead(P[cur], P[x], B)))
          next = x;
        else if (o > 0)
        {
          across = il; // the edge (x, r) is opposite l
          l = x;
        }
        else
        {
          across = ir;
          r = x;
        }
      }
    }
    out.pieces[piece].v1 = next;
    out.pieces[piece].crossingCount =
      static_cast<int>(out.crossings.size()) - out.pieces[piece].firstCrossing;
    if (next != b && isInput[next])
    {
      ++out.splitsAtInputVertices;
      dangling.passesThrough(next, segment);
    }
    else if (next != b)
      steinerHits.push_back({ next, segment, piece });
    cur = next;
  }
}

bool properlyCross(const Point& a, const Point& b, const Point& c, const Point& d)
{
  const int o1 = orientSign(a, b, c), o2 = orientSign(a, b, d);
  if (o1 == 0 || o2 == 0 || o1 == o2)
    return false;
  const int o3 = orientSign(c, d, a), o4 = orientSign(c, d, b);
  return o3 != 0 && o4 != 0 && o3 != o4;
}

/// Where segments ab and cd (which properly cross) cross, placed along the
/// shorter one from how far each of its ends lies from the other's line. Both
/// distances are exact up to rounding and of opposite signs, so the point is
/// within rounding of both lines however long the other segment is (measured
/// along a segment 10^8 times longer, the point landed 10^-9 of the short
/// one's length off it, and the short segment bent there).
Point intersection(const Point& a, const Point& b, const Point& c, const Point& d)
{
  if (dist2(a, b) > dist2(c, d))
    return intersection(c, d, a, b);
  const double da = orient2dAccurate(c, d, a), db = orient2dAccurate(c, d, b);
  const double t = da / (da - db);
  const double s = std::isfinite(t) ? std::min(1.0, std::max(0.0, t)) : 0.5;
  Point p{ a.x + s * (b.x - a.x), a.y + s * (b.y - a.y) };
  // On a horizontal or vertical segment the point can lie exactly on it.
  for (const auto& [u, v] : { std::pair{ a, b }, std::pair{ c, d } })
  {
    if (u.y == v.y)
      p.y = u.y;
    if (u.x == v.x)
      p.x = u.x;
  }
  return p;
}

void Walker::markDuplicates(const Array<int>* rank)
{
  // Overlapping collinear segments were split at each other's endpoints, so
  // their shared parts are identical pieces: keep the first in rank order.
  Array<std::array<int, 4>> keys;
  keys.reserve(out.pieces.size());
  for (int i = 0; i < static_cast<int>(out.pieces.size()); ++i)
  {
    const Piece& p = out.pieces[i];
    const int r = rank ? (*rank)[p.segment] : p.segment;
    keys.push_back({ std::min(p.v0, p.v1), std::max(p.v0, p.v1), r, i });
  }
  std::sort(keys.begin(), keys.end());
  for (std::size_t k = 1; k < keys.size(); ++k)
  {
    if (keys[k][0] == keys[k - 1][0] && keys[k][1] == keys[k - 1][1])
    {
      out.pieces[keys[k][3]].duplicate = true;
      out.overlaps.push_back({ out.pieces[keys[k - 1][3]].segment, out.pieces[keys[k][3]].segment,
        keys[k][0], keys[k][1] });
    }
  }
}

/// A pair of crossing segments is recorded once per triangle or edge where
/// it is found (a streamline circling a limit cycle: over 2.6e8 records of
/// 8.6e6 pairs, which outgrew 12 GB):
/// the records are reduced to one per pair each time they grow by the cap.
void Walker::addSegmentCrossing(int a, int b, const Point& p)
{
  out.segmentCrossings.push_back({ std::min(a, b), std::max(a, b), p });
  if (maxSegmentCrossings > 0 && out.segmentCrossings.size() >= nextCount)
    countSegmentCrossings();
}

void Walker::countSegmentCrossings()
{
  keepFirstOfEachPair(out.segmentCrossings);
  ++out.segmentCrossingsReduced;
  nextCount = out.segmentCrossings.size() + maxSegmentCrossings;
  refuseSegmentCrossings(out.segmentCrossings.size());
}

/// Every crossing split is a point of the next round's mesh. A streamline
/// circling a limit cycle crosses itself some 10^8 times, and their list
/// alone outgrew memory (a review): more than a quarter of the points the
/// memory holds in a mesh end the run, with a word of why.
void Walker::refuseSegmentCrossings(std::size_t count)
{
  if (maxSegmentCrossings == 0 || count <= maxSegmentCrossings)
    return;
  if (askMemory() && (maxSegmentCrossings == 0 || count <= maxSegmentCrossings))
    return;
  const SegmentCrossing& first = out.segmentCrossings.front();
  Stop stop{ "the input segments cross each other more than " +
    std::to_string(maxSegmentCrossings) + " times, e.g." };
  stop.tail = ": a quarter of the points this machine's memory (" + roughNumber(memoryBytes / 1e9) +
    " GB) holds in a mesh, and each crossing split is one; lines that cross many others, or "
    "themselves over and over (a streamline circling a limit cycle), cross as often as the square "
    "of their length: trim them before meshing";
  stop.segments = { first.a, first.b };
  stop.located = true;
  stop.at = first.p;
  throw stop;
}

/// The walks whose pieces a and b end at the same Steiner vertex (each then
/// goes on with the next piece) reach it from, and leave it towards, the same
/// two vertices.
bool Walker::overlapThrough(int a, int b) const
{
  const auto around = [&](int piece) {
    const int before = out.pieces[piece].v0, after = out.pieces[piece + 1].v1;
    return std::make_pair(std::min(before, after), std::max(before, after));
  };
  return around(a) == around(b);
}

void Walker::findSegmentCrossings(const Array<int>* rank)
{
  markDuplicates(rank);
  auto record = [&](int pa, int pb, const Point& p) {
    addSegmentCrossing(out.pieces[pa].segment, out.pieces[pb].segment, p);
  };
  // Two segments that cross share an overlay triangle...
  std::sort(triPiece.begin(), triPiece.end());
  triPiece.erase(std::unique(triPiece.begin(), triPiece.end()), triPiece.end());
  // A triangle's pieces in segment order (they are few), as walks in index
  // order would have numbered them.
  auto bySegment = [&](const std::pair<int, int>& x, const std::pair<int, int>& y) {
    const int sx = out.pieces[x.second].segment, sy = out.pieces[y.second].segment;
    return sx != sy ? sx < sy : x.second < y.second;
  };
  for (std::size_t k = 0; k < triPiece.size();)
  {
    std::size_t end = k;
    while (end < triPiece.size() && triPiece[end].first == triPiece[k].first)
      ++end;
    if (end - k > 1)
      std::sort(triPiece.begin() + k, triPiece.begin() + end, bySegment);
    for (std::size_t i = k; i < end; ++i)
    {
      const Piece& p = out.pieces[triPiece[i].second];
      if (p.duplicate)
        continue;
      for (std::size_t j = i + 1; j < end; ++j)
      {
        const Piece& q = out.pieces[triPiece[j].second];
        if (q.duplicate || q.segment == p.segment)
          continue;
        if (properlyCross(P[p.v0], P[p.v1], P[q.v0], P[q.v1]))
          record(triPiece[i].second, triPiece[j].second,
            intersection(P[p.v0], P[p.v1], P[q.v0], P[q.v1]));
      }
    }
    k = end;
  }
  // ...or one crosses an overlay edge along which the other runs.
  Array<std::pair<int, int>> edgePiece; // (overlay edge, piece along it)
  for (int i = 0; i < static_cast<int>(out.pieces.size()); ++i)
    if (out.pieces[i].overlayEdge >= 0 && !out.pieces[i].duplicate)
      edgePiece.push_back({ out.pieces[i].overlayEdge, i });
  std::sort(edgePiece.begin(), edgePiece.end());
  forEachPieceInSegmentOrder(out, [&](int piece) {
    const Piece& p = out.pieces[piece];
    if (p.duplicate)
      return;
    for (int k = p.firstCrossing; k < p.firstCrossing + p.crossingCount; ++k)
    {
      const Crossing& c = out.crossings[k];
      // The last piece along the edge (there is one: two along the same edge
      // are duplicates), as an array over the edges would keep.
      const auto after = std::upper_bound(edgePiece.begin(), edgePiece.end(),
        std::make_pair(c.edge, std::numeric_limits<int>::max()));
      if (after != edgePiece.begin() && std::prev(after)->first == c.edge)
        record(c.piece, std::prev(after)->second, c.p);
    }
  });
  // ...or both pass exactly through the same Steiner vertex, unless they
  // overlap there: collinear segments along the same pieces on both sides
  // (a review: a hull edge along a longer segment, each through one Steiner
  // point, was split as a crossing).
  std::sort(steinerHits.begin(), steinerHits.end());
  for (std::size_t k = 1; k < steinerHits.size(); ++k)
  {
    const auto [v, s, piece] = steinerHits[k];
    const auto [u, t, other] = steinerHits[k - 1];
    if (v == u && s != t && !overlapThrough(piece, other))
      addSegmentCrossing(s, t, P[v]);
  }
  keepFirstOfEachPair(out.segmentCrossings);
  // Where two segments properly cross, their crossing is taken from their own
  // lines, not from the pieces, overlay edges or Steiner vertex that found it:
  // those lie up to onSegmentUlps off the segments, and a crossing that far
  // off bent the next round's pieces, and the chains stitched along them,
  // past the rounding a chain may have (a review: 27 units in the last place
  // at 1e8, meshed at its own coordinates).
  for (SegmentCrossing& c : out.segmentCrossings)
  {
    const Segment &s = segments[c.a], &t = segments[c.b];
    if (properlyCross(P[s[0]], P[s[1]], P[t[0]], P[t[1]]))
      c.p = intersection(P[s[0]], P[s[1]], P[t[0]], P[t[1]]);
  }
  refuseSegmentCrossings(out.segmentCrossings.size());
}

/// Segment indices by their smaller vertex, bucketed into as many classes as
/// segments (a counting sort, linear in time and memory; within a class, in
/// index order). Nearby vertex numbers are nearby in space.
Array<int> walkOrder(const Array<Segment>& segments, std::size_t vertexCount)
{
  const std::size_t m = segments.size();
  const double scale = vertexCount > 0 ? double(m) / double(vertexCount) : 0.0;
  auto bucket = [&](const Segment& s) {
    const auto b = static_cast<std::size_t>(double(std::min(s[0], s[1])) * scale);
    return std::min(b, m - 1);
  };
  Array<int> start;
  start.assign(m + 1, 0);
  for (const Segment& s : segments)
    ++start[bucket(s) + 1];
  for (std::size_t b = 0; b < m; ++b)
    start[b + 1] += start[b];
  Array<int> order(m);
  for (std::size_t i = 0; i < m; ++i)
    order[start[bucket(segments[i])]++] = static_cast<int>(i);
  return order;
}

} // namespace

Walk walkSegments(const OverlayEdges& ov, const Overlay& overlay, const Array<Segment>& segments,
  double sinTheta1, RunContext& run, const Array<int>* order, const Array<int>* rank,
  NearMissSearch nearMisses, double memoryBytes)
{
  Walk out;
  Walker walker(ov, overlay, segments, sinTheta1, nearMisses, memoryBytes, out);
  // In the order of their smaller vertex, which the overlay numbers along a
  // Hilbert curve: consecutive walks then touch nearby triangles. In index
  // order (random on a segment soup) each walk starts with cache misses:
  // stitch phase on random-segments 1.2e6 1.31 -> 0.97 s (median of 11 runs).
  const Array<int> spatial = order ? Array<int>() : walkOrder(segments, overlay.mesh.points.size());
  const Array<int>& walkIn = order ? *order : spatial;
  out.firstPiece.assign(segments.size(), -1);
  for (std::size_t k = 0; k < walkIn.size(); ++k)
  {
    const int s = walkIn[k];
    out.firstPiece[s] = static_cast<int>(out.pieces.size());
    walker.walk(s, segments[s][0], segments[s][1]);
    // A walk may cross thousands of triangles (a long segment).
    run.tick(double(k) / double(segments.size()), 16);
  }
  run.poll();
  walker.findSegmentCrossings(rank);
  walker.finishNearMisses();
  return out;
}

namespace
{

/// Crossings grouped by overlay edge in increasing edge order, each group
/// sorted along its edge. A comparison sort of the crossings alone: a
/// counting sort would need arrays over every overlay edge.
Array<int> crossingsByEdge(const Walk& walk)
{
  Array<int> order(walk.crossings.size());
  for (std::size_t i = 0; i < order.size(); ++i)
    order[i] = static_cast<int>(i);
  const Array<Crossing>& c = walk.crossings;
  // Ties (crossings at the same point, which stitching refuses) in segment
  // order, then along the segment: the same error whatever the walk order.
  const auto segment = [&](int x) { return walk.pieces[c[x].piece].segment; };
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return c[a].edge != c[b].edge ? c[a].edge < c[b].edge
      : c[a].s != c[b].s          ? c[a].s < c[b].s
      : segment(a) != segment(b)  ? segment(a) < segment(b)
                                  : a < b;
  });
  return order;
}

/// Two points on an overlay edge of the given length are indistinguishable
/// when closer than the rounding error of a computed crossing point.
bool tooClose(const Point& p, const Point& q, double edgeLength)
{
  const double scale = std::max({ std::fabs(p.x), std::fabs(p.y), edgeLength });
  const double tolerance = 8 * std::numeric_limits<double>::epsilon() * scale;
  return dist2(p, q) <= tolerance * tolerance;
}

/// A crossing p of segment on an overlay edge, within rounding of a crossing
/// of other, or of the edge's end v (-1: none). Where v is an input point of
/// the round, the stop is there: the segment passes it too near to say on
/// which side (a review: one segment and a point 8.6 epsilons off it were
/// said to be segments too close to each other).
Stop crossingTooClose(const PlanarGraph& g, const Point& p, int segment, int v, int other)
{
  Stop stop{ "input segments come closer to each other than double precision can separate", true, p,
    { segment, other }, Stop::Remedy::JoinSegments };
  if (v >= 0 && g.origin[v] == VertexOrigin::Input)
  {
    stop.at = g.points[v];
    stop.atPoint = true;
  }
  return stop;
}

/// Per overlay half-edge (both halves of an edge alike): crossed by a
/// segment, kept, and along an input segment.
enum HalfEdgeFlag : std::uint8_t
{
  HalfCrossed = 1,
  HalfKept = 2,
  HalfAlongInput = 4
};

/// Sets flag on edge id and on its other half, if any.
void flagEdge(const OverlayEdges& ov, Array<std::uint8_t>& flags, int id, std::uint8_t flag)
{
  flags[id] |= flag;
  if (const int other = ov.twin(id / 3, id % 3); other >= 0)
    flags[other] |= flag;
}

/// Per overlay triangle: its index among the triangles that no segment
/// crosses (faces of the stitched graph as they are), or -1.
Array<int> numberIntact(const Array<std::uint8_t>& flags, int& count)
{
  Array<int> intactIndex;
  intactIndex.assign(flags.size() / 3, -1);
  count = 0;
  for (std::size_t c = 0; c < intactIndex.size(); ++c)
    if (!((flags[3 * c] | flags[3 * c + 1] | flags[3 * c + 2]) & HalfCrossed))
      intactIndex[c] = count++;
  return intactIndex;
}

/// Lists the intact triangles in g.intact, with their adjacency among
/// themselves. Takes over ov.tris and ov.nbr: an intact triangle only ever
/// moves down, over a place already read, so both are filtered in place.
void listIntact(OverlayEdges& ov, const Array<std::uint8_t>& flags, const Array<int>& intactIndex,
  int count, const Walk& walk, PlanarGraph& g, RunContext& run)
{
  Array<Triangle> tris = std::move(ov.tris);
  Array<std::array<int, 3>> nbrs = std::move(ov.nbr);
  KnownAdjacency& known = g.intactAdjacency;
  known.constrained.reserve(static_cast<std::size_t>(count));
  for (std::size_t c = 0; c < tris.size(); ++c)
  {
    run.tickWith([&] { return 0.8 + 0.2 * double(c) / double(tris.size()); }, 1u << 16);
    const int k = intactIndex[c];
    if (k < 0)
      continue;
    std::array<int, 3> nbr;
    std::uint8_t constrained = 0;
    for (int i = 0; i < 3; ++i)
    {
      const int u = nbrs[c][i];
      nbr[i] = u < 0          ? -1
        : intactIndex[u] >= 0 ? intactIndex[u]
                              : KnownAdjacency::kUnknownNeighbour;
      constrained |= ((flags[3 * c + i] & HalfAlongInput) ? 1 : 0) << i;
    }
    tris[k] = tris[c];
    nbrs[k] = nbr;
    known.constrained.push_back(constrained);
  }
  tris.resize(count);
  nbrs.resize(count);
  // Completion appends its triangles to these, and carving the neighbours of
  // all of them: fewer than the half-edges it traces, which are the sides of
  // the other triangles' edges (split once per crossing) and of the input
  // subsegments (split at crossings too). Usually the room is there already.
  const std::size_t others = intactIndex.size() - count;
  const std::size_t bound = count + 3 * others + 4 * walk.crossings.size() + 2 * walk.pieces.size();
  tris.reserve(bound);
  nbrs.reserve(bound);
  g.intact = std::move(tris);
  known.nbr = std::move(nbrs);
}

/// The graph's overlay vertices (input or Steiner), with room for every
/// stitch vertex and edge stitching adds, so that appending never copies.
PlanarGraph startGraph(
  Array<Point> points, const Array<char>& isInput, std::size_t overlayEdgeIds, const Walk& walk)
{
  PlanarGraph g;
  // Each crossing may add a stitch vertex, and each overlay edge, crossing
  // and piece at most two edges.
  const std::size_t nc = walk.crossings.size();
  const std::size_t overlayVertices = points.size();
  g.points = std::move(points);
  g.points.reserve(overlayVertices + nc);
  g.origin.reserve(overlayVertices + nc);
  g.origin.resize(overlayVertices);
  g.stitchSegment.reserve(nc);
  g.firstStitch = overlayVertices;
  const std::size_t edgeBound = overlayEdgeIds / 2 + 2 * nc + walk.pieces.size();
  g.edges.reserve(edgeBound);
  g.constrained.reserve(edgeBound);
  g.openSides.reserve(edgeBound);
  for (std::size_t v = 0; v < g.points.size(); ++v)
    g.origin[v] = isInput[v] ? VertexOrigin::Input : VertexOrigin::Overlay;
  return g;
}

void addEdge(PlanarGraph& g, int a, int b, bool constrained, std::uint8_t open)
{
  g.edges.push_back({ a, b });
  g.constrained.push_back(constrained);
  g.openSides.push_back(open);
}

/// Per overlay edge id: HalfCrossed, HalfKept and HalfAlongInput, from the
/// walk's crossings and pieces (a duplicate piece's left out); counts the
/// crossings. With alongSegment, the segment along each edge that is a piece.
Array<std::uint8_t> flagOverlayEdges(
  const OverlayEdges& ov, const Walk& walk, Statistics& stats, Array<int>* alongSegment)
{
  Array<std::uint8_t> flags;
  flags.assign(ov.idBound(), std::uint8_t{ 0 });
  for (const Crossing& c : walk.crossings)
  {
    if (walk.pieces[c.piece].duplicate)
      continue;
    flagEdge(ov, flags, c.edge, c.good ? HalfCrossed | HalfKept : HalfCrossed);
    ++(c.good ? stats.goodCrossings : stats.badCrossings);
  }
  stats.crossings = stats.goodCrossings + stats.badCrossings;
  if (alongSegment)
    alongSegment->assign(ov.idBound(), -1);
  for (const Piece& p : walk.pieces)
    if (p.overlayEdge >= 0 && !p.duplicate)
    {
      flagEdge(ov, flags, p.overlayEdge, HalfAlongInput);
      if (alongSegment)
        (*alongSegment)[ov.edgeId(p.overlayEdge / 3, p.overlayEdge % 3)] = p.segment;
    }
  return flags;
}

/// A kept crossed edge from ends[0] to ends[1]: one stitch vertex per
/// crossing (order[first, next), in order along it) and the edges between.
void stitchKeptEdge(PlanarGraph& g, const Walk& walk, const Array<int>& order, std::size_t first,
  std::size_t next, const Segment& ends, Array<int>& stitchVertex)
{
  const double edgeLength = std::sqrt(dist2(g.points[ends[0]], g.points[ends[1]]));
  int prev = ends[0];
  int prevSegment = -1; // the segment of the crossing at prev, if any
  for (std::size_t k = first; k < next; ++k)
  {
    const Crossing& c = walk.crossings[order[k]];
    if (walk.pieces[c.piece].duplicate)
      continue;
    const int segment = walk.pieces[c.piece].segment;
    if (!c.resolved)
      throw Stop{ "a segment passes input points closer together than double precision "
                  "resolves at the coordinates of both its ends (features below about "
                  "1e-14 of them)",
        true, c.p, { segment, -1 }, Stop::Remedy::MergePoints };
    // Crossings within rounding of each other (or of the edge's ends) cannot
    // be told apart: the segments meet at an angle below double precision.
    if (tooClose(c.p, g.points[prev], edgeLength))
      throw crossingTooClose(g, c.p, segment, prevSegment < 0 ? prev : -1, prevSegment);
    if (tooClose(c.p, g.points[ends[1]], edgeLength))
      throw crossingTooClose(g, c.p, segment, ends[1], -1);
    prevSegment = segment;
    const int v = static_cast<int>(g.points.size());
    g.points.push_back(c.p);
    g.origin.push_back(VertexOrigin::Stitch);
    g.stitchSegment.push_back(segment);
    stitchVertex[order[k]] = v;
    addEdge(g, prev, v, false, OpenBoth);
    prev = v;
  }
  addEdge(g, prev, ends[1], false, OpenBoth);
}

/// Input subsegments: each piece, split at its kept crossings. A piece along
/// an uncrossed overlay edge is that edge, added already.
void addSubsegments(PlanarGraph& g, const Walk& walk, const Array<std::uint8_t>& flags,
  const Array<int>& stitchVertex, Array<Edge>* inspect)
{
  forEachPieceInSegmentOrder(walk, [&](int piece) {
    const Piece& p = walk.pieces[piece];
    if (p.duplicate || (p.overlayEdge >= 0 && !(flags[p.overlayEdge] & HalfCrossed)))
      return;
    int prev = p.v0;
    for (int k = p.firstCrossing; k < p.firstCrossing + p.crossingCount; ++k)
    {
      if (stitchVertex[k] < 0)
        continue;
      addEdge(g, prev, stitchVertex[k], true, OpenBoth);
      if (inspect)
        inspect->push_back({ prev, stitchVertex[k], EdgeInput, p.segment });
      prev = stitchVertex[k];
    }
    addEdge(g, prev, p.v1, true, OpenBoth);
    if (inspect && p.overlayEdge < 0)
      inspect->push_back({ prev, p.v1, EdgeInput, p.segment });
  });
}

} // namespace

PlanarGraph stitch(OverlayEdges ov, Array<Point> points, const Array<char>& isInput,
  const Walk& walk, Array<Edge>* inspect, Statistics& stats, RunContext& run)
{
  // This round's counts: a round meshed again (a size bound, region areas,
  // crossings split) counts afresh (a review: KeptEdges added up over rounds).
  stats.goodCrossings = stats.badCrossings = stats.uncrossedEdges = 0;
  stats.keptEdges = stats.discardedEdges = 0;
  const std::size_t ne = ov.idBound();
  const std::size_t overlayVertices = points.size();
  PlanarGraph g = startGraph(std::move(points), isInput, ne, walk);
  run.poll();
  Array<int> alongSegment; // for inspection
  const Array<std::uint8_t> flags =
    flagOverlayEdges(ov, walk, stats, inspect ? &alongSegment : nullptr);
  run.poll();
  int intactCount = 0;
  const Array<int> intactIndex = numberIntact(flags, intactCount);
  // The faces still to trace lie on the sides of an edge whose triangle there
  // is not intact; an edge's id names the triangle on its left.
  auto openSides = [&](int id) {
    const int u = ov.nbr[id / 3][id % 3];
    return static_cast<std::uint8_t>(
      (intactIndex[id / 3] < 0 ? OpenLeft : 0) | (u >= 0 && intactIndex[u] < 0 ? OpenRight : 0));
  };

  run.poll();
  const Array<int> order = crossingsByEdge(walk);
  run.poll();
  std::size_t next = 0; // the first crossing, in order, of the edges still to come
  Array<int> stitchVertex(walk.crossings.size(), -1);
  for (int e = 0; e < static_cast<int>(ne); ++e)
  {
    run.tickWith([&] { return 0.8 * e / double(ne); }, 1u << 16);
    if (!ov.isEdge(e))
      continue;
    // This edge's crossings are order[first, next).
    const std::size_t first = next;
    while (next < order.size() && walk.crossings[order[next]].edge == e)
      ++next;
    const Segment ends = ov.ends(e);
    const bool alongInput = flags[e] & HalfAlongInput;
    std::uint8_t edgeFlags = EdgeOverlay;
    if (!(flags[e] & HalfCrossed))
    {
      ++stats.uncrossedEdges;
      edgeFlags |= EdgeKept | (alongInput ? EdgeInput : 0);
      const std::uint8_t open = openSides(e);
      if (alongInput || open)
        addEdge(g, ends[0], ends[1], alongInput, open);
    }
    else if (flags[e] & HalfKept)
    {
      ++stats.keptEdges;
      edgeFlags |= EdgeKept | EdgeCrossed;
      stitchKeptEdge(g, walk, order, first, next, ends, stitchVertex);
    }
    else
    {
      ++stats.discardedEdges;
      edgeFlags |= EdgeDiscarded | EdgeCrossed;
    }
    if (inspect)
      inspect->push_back({ ends[0], ends[1], edgeFlags, alongSegment[e] });
  }
  listIntact(ov, flags, intactIndex, intactCount, walk, g, run);
  stats.stitchVertices = g.points.size() - overlayVertices;
  addSubsegments(g, walk, flags, stitchVertex, inspect);
  return g;
}

} // namespace osm
