#include "RegionPolygons.h"

#include "Predicates.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace osm
{
namespace
{

constexpr double kInf = std::numeric_limits<double>::infinity();

/// A loop's absolute signed area (the lobes of a self-crossing loop cancel),
/// its bounds, and the area of the mesh's regions inside it (even-odd).
struct LoopFacts
{
  double shoelace = 0.0;
  double box[4] = { kInf, -kInf, kInf, -kInf }; ///< x min, x max, y min, y max
  double inside = 0.0;
};

LoopFacts factsOf(const Pslg& pslg, const PolygonLoops& loops, std::size_t i)
{
  LoopFacts f;
  const std::size_t first = loops.first[i], n = loops.first[i + 1] - first;
  for (std::size_t k = 0; k < n; ++k)
  {
    const Point& a = pslg.points[static_cast<std::size_t>(loops.points[first + k])];
    const Point& b = pslg.points[static_cast<std::size_t>(loops.points[first + (k + 1) % n])];
    f.shoelace += a.x * b.y - a.y * b.x;
    f.box[0] = std::min(f.box[0], a.x);
    f.box[1] = std::max(f.box[1], a.x);
    f.box[2] = std::min(f.box[2], a.y);
    f.box[3] = std::max(f.box[3], a.y);
  }
  f.shoelace = std::fabs(0.5 * f.shoelace);
  return f;
}

/// The mesh's regions: per region a point inside it (the centroid of its
/// largest triangle, well away from the segments that bound the region; NaN
/// for a region without triangles), and its area.
struct Regions
{
  std::vector<Point> at;
  std::vector<double> area;
};

Regions regionPoints(const Result& result)
{
  const auto& v = result.mesh.vertices;
  Regions regions;
  std::vector<double> largest;
  for (std::size_t t = 0; t < result.mesh.triangles.size(); ++t)
  {
    const int r = t < result.regionId.size() ? result.regionId[t] : -1;
    if (r < 0)
      continue;
    const auto ri = static_cast<std::size_t>(r);
    if (ri >= regions.at.size())
    {
      regions.at.resize(ri + 1, { std::numeric_limits<double>::quiet_NaN(), 0 });
      largest.resize(ri + 1, -1.0);
      regions.area.resize(ri + 1, 0.0);
    }
    const Triangle& tri = result.mesh.triangles[t];
    const Point &a = v[tri[0]], &b = v[tri[1]], &c = v[tri[2]];
    const double area = std::fabs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    regions.area[ri] += 0.5 * area;
    if (area > largest[ri])
    {
      largest[ri] = area;
      regions.at[ri] = { (a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3 };
    }
  }
  return regions;
}

/// The points in buckets of a square grid over their bounds, about one per
/// bucket, so that those inside a loop's bounds are found without a scan.
class PointGrid
{
public:
  explicit PointGrid(const std::vector<Point>& points)
  {
    for (const Point& p : points)
    {
      lo.x = std::min(lo.x, p.x); // NaN (a region without a point) compares false: skipped
      lo.y = std::min(lo.y, p.y);
      hi.x = std::max(hi.x, p.x);
      hi.y = std::max(hi.y, p.y);
    }
    side = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(points.size())))));
    start.assign(static_cast<std::size_t>(side) * side + 1, 0);
    for (const Point& p : points)
      start[bucket(p) + 1] += std::isnan(p.x) ? 0 : 1;
    for (std::size_t b = 1; b < start.size(); ++b)
      start[b] += start[b - 1];
    items.resize(start.back());
    std::vector<std::size_t> next(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < points.size(); ++i)
      if (!std::isnan(points[i].x))
        items[next[bucket(points[i])]++] = static_cast<int>(i);
  }

  /// Calls visit(i) for every point i in the buckets that box (x min, x max,
  /// y min, y max) overlaps.
  template <typename Visit>
  void forEachNear(const double box[4], Visit&& visit) const
  {
    for (int row = index(box[2], lo.y, hi.y); row <= index(box[3], lo.y, hi.y); ++row)
      for (int column = index(box[0], lo.x, hi.x); column <= index(box[1], lo.x, hi.x); ++column)
      {
        const std::size_t b = static_cast<std::size_t>(row) * static_cast<std::size_t>(side) +
          static_cast<std::size_t>(column);
        for (std::size_t k = start[b]; k < start[b + 1]; ++k)
          visit(items[k]);
      }
  }

private:
  /// Clamped before the conversion: a loop's bounds may lie far beyond the
  /// points', where the quotient would not fit an int.
  int index(double v, double low, double high) const
  {
    const double f = high > low ? (v - low) / (high - low) * side : 0.0;
    return static_cast<int>(std::clamp(f, 0.0, side - 1.0));
  }
  std::size_t bucket(const Point& p) const
  {
    return std::isnan(p.x)
      ? 0
      : static_cast<std::size_t>(index(p.y, lo.y, hi.y)) * static_cast<std::size_t>(side) +
        static_cast<std::size_t>(index(p.x, lo.x, hi.x));
  }

  Point lo{ kInf, kInf };
  Point hi{ -kInf, -kInf };
  int side = 1;
  std::vector<std::size_t> start;
  std::vector<int> items;
};

/// Which of the candidates (y, region point index), sorted by y, lie inside
/// loop i: the parity of the loop's edges to their right (exact orientation
/// tests), each edge tested against the candidates in its span of y.
/// Costs the candidates in each edge's span of y: the number of candidates
/// times the edges a line across the loop meets (a comb of 16,000 teeth
/// around 32,000 regions: 3.1 s). tests counts the orientation tests, and
/// poll is asked every 2^20 of them; returns false when it says stop.
bool markInside(const Pslg& pslg, const PolygonLoops& loops, std::size_t i,
  const std::vector<Point>& points, const std::vector<std::pair<double, int>>& candidates,
  std::vector<unsigned char>& inside, std::size_t& tests, const std::function<bool()>& poll)
{
  inside.assign(candidates.size(), 0);
  const std::size_t first = loops.first[i], n = loops.first[i + 1] - first;
  for (std::size_t k = 0; k < n; ++k)
  {
    Point lo = pslg.points[static_cast<std::size_t>(loops.points[first + k])];
    Point hi = pslg.points[static_cast<std::size_t>(loops.points[first + (k + 1) % n])];
    if (lo.y == hi.y)
      continue;
    if (lo.y > hi.y)
      std::swap(lo, hi);
    // Half-open spans [lo.y, hi.y), so that a vertex at a point's y counts once.
    auto byY = [](const std::pair<double, int>& c, double y) { return c.first < y; };
    const auto from = std::lower_bound(candidates.begin(), candidates.end(), lo.y, byY);
    const auto to = std::lower_bound(from, candidates.end(), hi.y, byY);
    for (auto c = from; c != to; ++c)
    {
      if ((++tests & 0xfffff) == 0 && poll())
        return false;
      if (orient2d(lo, hi, points[static_cast<std::size_t>(c->second)]) > 0)
        inside[static_cast<std::size_t>(c - candidates.begin())] ^= 1;
    }
  }
  return true;
}

} // namespace

bool innermostPolygons(const Pslg& pslg, const Result& result, const PolygonLoops& loops,
  std::vector<int>& regionPolygon, const std::function<bool(double)>& poll)
{
  const Regions regions = regionPoints(result);
  const std::vector<Point>& points = regions.at;
  const PointGrid grid(points);
  regionPolygon.assign(points.size(), -1);
  std::vector<LoopFacts> facts;
  facts.reserve(loops.size());
  std::vector<std::pair<double, int>> candidates;
  std::vector<unsigned char> inside;
  const double total = static_cast<double>(loops.points.size());
  std::size_t nextPoll = 0x10000;
  std::size_t tests = 0;
  const std::function<bool()> pollHere = [&]() {
    return poll(static_cast<double>(loops.first[facts.size() - 1]) / total);
  };
  for (std::size_t i = 0; i < loops.size(); ++i)
  {
    facts.push_back(factsOf(pslg, loops, i));
    LoopFacts& f = facts.back();
    if (loops.first[i] >= nextPoll)
    {
      nextPoll = loops.first[i] + 0x10000;
      if (pollHere())
        return false;
    }
    candidates.clear();
    grid.forEachNear(f.box, [&](int r) {
      const Point& q = points[static_cast<std::size_t>(r)];
      if (q.x >= f.box[0] && q.x <= f.box[1] && q.y >= f.box[2] && q.y <= f.box[3])
        candidates.emplace_back(q.y, r);
    });
    std::sort(candidates.begin(), candidates.end());
    if (!markInside(pslg, loops, i, points, candidates, inside, tests, pollHere))
      return false;
    for (std::size_t k = 0; k < candidates.size(); ++k)
      f.inside += inside[k] ? regions.area[static_cast<std::size_t>(candidates[k].second)] : 0.0;
    for (std::size_t k = 0; k < candidates.size(); ++k)
    {
      int& of = regionPolygon[static_cast<std::size_t>(candidates[k].second)];
      const LoopFacts* owner = of >= 0 ? &facts[static_cast<std::size_t>(of)] : nullptr;
      if (inside[k] &&
        (!owner || f.inside < owner->inside ||
          (f.inside == owner->inside && f.shoelace < owner->shoelace)))
        of = static_cast<int>(i);
    }
  }
  return true;
}

} // namespace osm
