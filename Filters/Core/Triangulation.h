// An index-based 2D triangulation with Delaunay (Bowyer-Watson) insertion.
//
// Triangles live in slots: vertices v[0..2] counter-clockwise and neighbours
// n[i] across edge i, the edge opposite vertex i, i.e. from v[i+1] to v[i+2].
// -1 marks the hull. Half-edge 3t + i names edge i of slot t. Deleted slots
// are recycled.
#ifndef osm_Triangulation_h
#define osm_Triangulation_h

#include "Geometry.h"
#include "HugePages.h"

#include <array>
#include <cstdint>
#include <vector>

namespace osm
{

class Triangulation
{
public:
  /// One triangle slot. Vertices, neighbours and the cavity search's stamp
  /// side by side, in half a cache line: a search or an insertion touching a
  /// triangle needs all of them, and separate arrays cost a miss each.
  struct alignas(32) Slot
  {
    std::array<int, 3> v; ///< vertices (v[0] == -1: a free slot)
    std::array<int, 3> n; ///< neighbours
    mutable std::uint32_t mark;
    int info; ///< the user's, -1 in a new triangle (the refinement keeps a list head here)
  };

  Array<Point> points;
  Array<Slot> tri;

  int addPoint(const Point& p);
  int newTriangle(int a, int b, int c);
  void freeTriangle(int t);
  bool alive(int t) const { return tri[t].v[0] >= 0; }
  int slots() const { return static_cast<int>(tri.size()); }
  /// The neighbour across half-edge e = 3t + i.
  int across(int e) const { return tri[e / 3].n[e % 3]; }
  int liveTriangles() const { return slots() - static_cast<int>(freeSlots.size()); }
  /// Room for this many points and triangle slots. Untouched capacity costs
  /// only address space; growing by doubling instead touches (page faults)
  /// and copies about twice the final size.
  void reserve(std::size_t pointCount, std::size_t triangleCount);
  /// Drops every triangle and gives its memory back, keeping the points.
  void releaseTriangles();
  /// Gives back the scratch memory insertion keeps between calls (an array
  /// over the vertices): once insertions are over, it only adds to the peak.
  /// A later insertion allocates it again.
  void releaseInsertionScratch();
  const Point& vertex(int t, int i) const { return points[tri[t].v[i]]; }

  /// Set the neighbour links of two triangles sharing the edge (a, b).
  void link(int t, int u);
  /// Local index (0..2) of vertex v in triangle t, or -1.
  int localIndex(int t, int v) const;

  /// Walk from triangle start towards p. Returns a triangle whose closure
  /// contains p, or -1 if p is outside the hull; then exitEdge holds the
  /// triangle and local edge through which the walk left (3t + i). Returns -2
  /// if the walk exceeds one step per triangle (never on a valid Delaunay mesh).
  int locate(const Point& p, int start, int* exitEdge = nullptr) const;

  /// A Bowyer-Watson cavity: the triangles whose circumcircle strictly
  /// contains a point, in search order, and the edges (3t + i) on its
  /// boundary, found during the same search.
  struct Cavity
  {
    Array<int> triangles;
    Array<int> boundary;
  };

  /// The cavity of p, searched from a triangle containing p. Returns false if
  /// p coincides with a vertex of the start triangle.
  bool cavityOf(const Point& p, int containing, Cavity& cavity) const;

  /// Replace the cavity by a fan around the new vertex v (a point already added).
  /// Returns false, changing nothing, if the cavity is not star-shaped from v.
  /// created receives the new triangles in counter-clockwise order around v,
  /// each with v as its vertex 2.
  bool insertIntoCavity(int v, const Cavity& cavity, Array<int>& created);

private:
  Array<int> freeSlots;
  // Scratch state kept between calls so insertion allocates nothing.
  mutable std::uint32_t markStamp = 0;
  struct FanTriangle
  {
    int a, b, outside; ///< edge (a, b) of the cavity boundary, triangle outside beyond it
    int outsideLink;   ///< the half-edge of outside that refers back across (a, b)
  };
  Array<FanTriangle> fan;
  static constexpr std::size_t kSmallFan = 16;
  Array<int> ordered;
  Array<int> fanByVertex;
};

/// Circumcenter of triangle (a, b, c) minus a: accurate even for a tiny
/// triangle far from the origin, where adding a back rounds it away.
/// (Inline: the refinement computes one per new triangle.)
inline Point circumcenterOffset(const Point& a, const Point& b, const Point& c)
{
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2.0 * (bx * cy - by * cx);
  return { (cy * b2 - by * c2) / d, (bx * c2 - cx * b2) / d };
}

/// Circumcenter of triangle (a, b, c), computed relative to a for accuracy.
inline Point circumcenter(const Point& a, const Point& b, const Point& c)
{
  const Point o = circumcenterOffset(a, b, c);
  return { a.x + o.x, a.y + o.y };
}

} // namespace osm

#endif
