// Which input polygon holds each region of a mesh, for carrying polygon data
// (a polygon cell's values) to the triangles inside it. The polygons' edges
// are segments of the mesh, so every region lies inside or outside each
// polygon as a whole: one point of it decides, by the even-odd rule with
// exact orientation tests.
#ifndef osm_RegionPolygons_h
#define osm_RegionPolygons_h

#include "Mesher.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace osm
{

/// Input polygons as loops of Pslg point indices, without the closing repeat
/// of the first point: loop i is points[first[i]] .. points[first[i + 1] - 1].
struct PolygonLoops
{
  std::vector<int> points;
  std::vector<std::size_t> first{ 0 };

  /// Appends a loop of n >= 3 points.
  void add(const int* ids, std::size_t n)
  {
    points.insert(points.end(), ids, ids + n);
    first.push_back(points.size());
  }
  std::size_t size() const { return first.size() - 1; }
};

/// For each region of result's mesh (Result::regionId), the index of the
/// innermost loop around it, or -1 in none. The innermost is the smallest: by
/// the area of the mesh inside the loops (nested polygons keep their order
/// whatever holes remove, and a self-crossing loop counts all its lobes),
/// then by the loop's own area; a tie keeps the first loop.
/// poll(fraction done) is asked now and then (about every 2^16 loop points
/// and 2^20 orientation tests); when it returns true the work stops and the
/// function returns false.
bool innermostPolygons(const Pslg& pslg, const Result& result, const PolygonLoops& loops,
  std::vector<int>& regionPolygon, const std::function<bool(double)>& poll);

} // namespace osm

#endif
