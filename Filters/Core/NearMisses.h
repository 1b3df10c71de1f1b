// Internal: segment ends that dangle a hair short of a segment they do not
// reach (Walk::nearMisses), as isolines cut in floats end short of their
// boundary. Found during the stitching walks and after them.
#ifndef osm_NearMisses_h
#define osm_NearMisses_h

#include "Stitch.h"

#include <utility>

namespace osm
{

/// The near misses of one set of walks. A segment passing a hair from a
/// dangling end crosses the end's overlay edges, so the walker reports the
/// ends of the edges it crosses (crossedNear) and the input vertices it
/// passes through (passesThrough); after the walks, findAtEnds adds the ends
/// a hair from another segment's end, and keepNearest filters them.
class DanglingEnds
{
public:
  DanglingEnds(const OverlayEdges& ov, const Array<Point>& P, const Array<Segment>& segments,
    NearMissSearch search);

  bool searching() const { return search.reach > 0; }
  /// Segment s crossed an overlay edge ending at vertex v.
  void crossedNear(int v, int s, Array<NearMiss>& out) const
  {
    if (searching() && endOf[v] >= 0 && endOf[v] != s)
      add(v, s, out);
  }
  /// Segment s passes through input vertex v: an end there meets it.
  void passesThrough(int v, int s)
  {
    if (searching())
      passes.push_back({ v, s });
  }
  void findAtEnds(Array<NearMiss>& out) const;
  void keepNearest(Array<NearMiss>& out);

private:
  void add(int end, int s, Array<NearMiss>& out) const;
  bool alongItsChain(const NearMiss& m, const Array<std::pair<int, int>>& ends, Array<double>& best,
    Array<int>& touched) const;

  const OverlayEdges& ov;
  const Array<Point>& P;
  const Array<Segment>& segments;
  const NearMissSearch search;
  /// Per overlay vertex: the one segment that ends there (s >= 0), or of
  /// several the first, an input segment where there is one (-2 - s), or
  /// none (-1).
  Array<int> endOf;
  /// (input vertex, segment passing through it): such an end meets that segment.
  Array<std::pair<int, int>> passes;
};

} // namespace osm

#endif
