// An index-based 2D triangulation with Delaunay (Bowyer-Watson) insertion.
//
// Triangles live in flat arrays: vertices tv[3t..3t+2] counter-clockwise and
// neighbours tn[3t+i] across edge i, the edge opposite vertex i, i.e. from
// tv[3t+i+1] to tv[3t+i+2]. -1 marks the hull. Deleted slots are recycled.
#ifndef osm_Triangulation_h
#define osm_Triangulation_h

#include "Geometry.h"

#include <cstdint>
#include <vector>

namespace osm
{

class Triangulation
{
public:
  std::vector<Point> points;
  std::vector<int> tv;   ///< 3 vertices per triangle slot (-1: free slot)
  std::vector<int> tn;   ///< 3 neighbours per triangle slot
  std::vector<int> vtri; ///< one live triangle incident to each vertex

  int addPoint(const Point& p);
  int newTriangle(int a, int b, int c);
  void freeTriangle(int t);
  bool alive(int t) const { return tv[3 * t] >= 0; }
  int slots() const { return static_cast<int>(tv.size() / 3); }
  int liveTriangles() const { return slots() - static_cast<int>(freeSlots.size()); }
  /// Room for this many points and triangle slots. Untouched capacity costs
  /// only address space; growing by doubling instead touches (page faults)
  /// and copies about twice the final size.
  void reserve(std::size_t pointCount, std::size_t triangleCount);
  /// Drops every triangle and gives its memory back, keeping the points.
  void releaseTriangles();
  const Point& vertex(int t, int i) const { return points[tv[3 * t + i]]; }

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
    std::vector<int> triangles;
    std::vector<int> boundary;
  };

  /// The cavity of p, searched from a triangle containing p. Returns false if
  /// p coincides with a vertex of the start triangle.
  bool cavityOf(const Point& p, int containing, Cavity& cavity) const;

  /// Replace the cavity by a fan around the new vertex v (a point already added).
  /// Returns false, changing nothing, if the cavity is not star-shaped from v.
  /// created receives the new triangles in counter-clockwise order around v.
  bool insertIntoCavity(int v, const Cavity& cavity, std::vector<int>& created);

private:
  std::vector<int> freeSlots;
  // Scratch state kept between calls so insertion allocates nothing.
  mutable std::vector<std::uint32_t> mark;
  mutable std::uint32_t markStamp = 0;
  struct FanTriangle
  {
    int a, b, outside; ///< edge (a, b) of the cavity boundary, triangle outside beyond it
    int outsideLink;   ///< the slot of tn by which outside refers back across (a, b)
  };
  std::vector<FanTriangle> fan;
  std::vector<int> ordered;
  std::vector<int> fanByVertex;
};

/// Circumcenter of triangle (a, b, c) minus a: accurate even for a tiny
/// triangle far from the origin, where adding a back rounds it away.
Point circumcenterOffset(const Point& a, const Point& b, const Point& c);

/// Circumcenter of triangle (a, b, c), computed relative to a for accuracy.
inline Point circumcenter(const Point& a, const Point& b, const Point& c)
{
  const Point o = circumcenterOffset(a, b, c);
  return { a.x + o.x, a.y + o.y };
}

} // namespace osm

#endif
