// Best-fitting plane of 3D points and the 2D frame in it: lets the mesher,
// which works in a plane, take coplanar points given in 3D.
#ifndef osm_Plane_h
#define osm_Plane_h

#include "Geometry.h"
#include "HugePages.h"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

namespace osm
{

struct Vec3
{
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
};

/// An orthonormal, right-handed frame (u, v, normal) at origin.
struct PlaneFrame
{
  Vec3 origin;
  Vec3 u{ 1, 0, 0 };
  Vec3 v{ 0, 1, 0 };
  Vec3 normal{ 0, 0, 1 };
  /// A normal whose z is at most this counts as horizontal, the plane as
  /// containing the z direction: a float Slice's vertical plane tilts its
  /// normal by rounding, about 1e-5 (see PlaneMap::choose).
  double vertical = 1e-9;

  /// 2D coordinates of the orthogonal projection of p onto the plane.
  Point toPlane(const Vec3& p) const;
  /// The 3D point of the plane with 2D coordinates q.
  Vec3 fromPlane(const Point& q) const;
  /// Signed distance of p from the plane (along the normal).
  double distance(const Vec3& p) const;
  /// 2D coordinates of the point of the plane straight above or below (x, y)
  /// along z; for a plane that contains the z direction (normal's z at most
  /// vertical), of the orthogonal projection of (x, y, origin.z) instead.
  Point liftXY(double x, double y) const;
};

struct PlaneFit
{
  /// False when there are no points or a coordinate is not finite.
  bool ok = false;
  PlaneFrame frame;
  /// The point farthest from the plane, and its (unsigned) distance.
  std::size_t farthest = 0;
  double maxDistance = 0.0;
  /// Length of the diagonal of the points' axis-aligned bounding box.
  double diagonal = 0.0;
  /// True when the points do not fix the plane (fewer than 3 distinct points,
  /// or all on one line): the frame is then the plane through them whose
  /// normal is closest to the z axis.
  bool degenerate = false;

  /// All points within relativeTolerance * diagonal of the plane, plus
  /// rounding (PlaneMap::choose: the coordinates' rounding as stored).
  bool coplanar(double relativeTolerance, double rounding = 0.0) const
  {
    return maxDistance <= relativeTolerance * diagonal + rounding;
  }
};

/// Least-squares plane through the centroid (the normal is the eigenvector of
/// the smallest eigenvalue of the points' scatter matrix). The frame is
/// oriented deterministically: the normal points up (+z; for a plane within
/// 1e-9 of vertical +y, or +x); u is the projection of the world axis least
/// aligned with the normal (the first of equal ones); v = normal x u. Points
/// in a plane z = c thus get u = x, v = y. Works at any finite magnitude
/// (coordinates are rescaled by a power of two before squaring).
PlaneFit fitPlane(const Array<Vec3>& points);

/// "(x, y, z)", each by formatNumber (round-trip, no more digits), for messages.
std::string formatPoint3(const Vec3& p);

/// How 3D input points become the mesher's 2D points, and output points come
/// back: as they are in a plane z = constant, projected onto XY when asked, or
/// through the best-fitting plane when the points are coplanar in a tilted
/// plane. Input points come back with their original coordinates, bit for bit.
class PlaneMap
{
public:
  /// Points are coplanar when within this fraction of their bounding-box
  /// diagonal from their best-fitting plane.
  static constexpr double relativeTolerance = 1e-9;

  /// Chooses the mapping for points (kept by reference until the map is done
  /// with). Returns an error message naming the farthest point when they are
  /// not coplanar and projectToXY is off, or "". roundoff: the unit roundoff
  /// of the coordinates as the caller stored them (2^-24 for floats; 0 for
  /// doubles, whose rounding the relative tolerance covers): points of a plane
  /// that storing moved off it by rounding are coplanar.
  std::string choose(const Array<Vec3>& points, bool projectToXY, double roundoff = 0.0);

  bool isFitted() const { return fitted; }
  bool isProjected() const { return projected; }
  /// The output z when not fitted: the input's constant z, or the mean z when projected.
  double z() const { return planeZ; }

  Point toPlane(const Vec3& p) const { return fitted ? frame.toPlane(p) : Point{ p.x, p.y }; }
  /// A hole seed given as (x, y): moved along z onto a fitted plane.
  Point seedXY(double x, double y) const { return fitted ? frame.liftXY(x, y) : Point{ x, y }; }
  /// Whether seedXY names one point: not in a plane that contains the z
  /// direction (x = c, y = c), where (x, y) leaves the height undefined.
  bool seedXYDefined() const { return !fitted || std::fabs(frame.normal.z) > frame.vertical; }

  /// Remembers which 2D points are the input's (the first of equal ones), so
  /// that toSpace() returns their original coordinates.
  void indexInputPoints(const Array<Point>& planar);
  /// The 3D point of output vertex q; inputIndex is the input point it is, or
  /// -1 to look it up by its exact 2D coordinates.
  Vec3 toSpace(const Point& q, long long inputIndex = -1) const;

private:
  using Key = std::pair<std::uint64_t, std::uint64_t>;
  struct KeyHash
  {
    std::size_t operator()(const Key& k) const;
  };
  static Key keyOf(const Point& p);

  const Array<Vec3>* input = nullptr;
  bool fitted = false;
  bool projected = false;
  double planeZ = 0.0;
  PlaneFrame frame;
  std::unordered_map<Key, std::size_t, KeyHash> inputOf;
};

} // namespace osm

#endif
