// The working PSLG of one meshing round, and the frame of its coordinates:
// what the mesher's rounds and the splitting of crossings share.
#ifndef osm_Work_h
#define osm_Work_h

#include "Geometry.h"
#include "HugePages.h"

#include <array>
#include <cmath>

namespace osm
{

/// The working PSLG of one meshing round, in scaled coordinates.
struct Work
{
  Array<Point> points;
  Array<char> isCrossingPoint;
  Array<Segment> segments;
  Array<int> segmentOrigin; ///< the user's segment index, -1 for hull edges
  /// Per segment: the ends of the piece of the input (after snapping) it is
  /// part of, which a join may move it off by at most the merge tolerance.
  Array<std::array<Point, 2>> piece;
  Array<Point> holes;
  Array<Point> regionSeeds;
};

/// The working coordinates of the rounds: the user's, less origin, scaled by
/// 2^-exponent (normalise).
struct Frame
{
  int exponent = 0;
  Point origin{ 0, 0 };

  /// A working point in the user's coordinates (rounded, for messages).
  Point toUser(const Point& p) const
  {
    return addOrigin({ std::ldexp(p.x, exponent), std::ldexp(p.y, exponent) });
  }
  /// p + origin, where a coordinate of -0 stays -0 when the origin's is 0
  /// (-0 + 0 is +0): input vertices come back bit for bit.
  Point addOrigin(const Point& p) const
  {
    return { origin.x != 0 ? p.x + origin.x : p.x, origin.y != 0 ? p.y + origin.y : p.y };
  }
};

} // namespace osm

#endif
