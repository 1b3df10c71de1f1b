#include "Clean.h"

#include "Geometry.h"
#include "HugePages.h"
#include "NumberText.h"
#include "Predicates.h"
#include "Snap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>
#include <utility>

namespace osm
{

std::string formatPoint(const Point& p)
{
  return "(" + formatNumber(p.x) + ", " + formatNumber(p.y) + ")";
}

std::string formatNumber(double x)
{
  std::string text;
  for (int digits = 15; digits <= 17; ++digits)
  {
    text = generalText(x, digits);
    if (cLocaleReal(text) == x)
      break;
  }
  return text;
}

std::string roughNumber(double x)
{
  return generalText(x, 2);
}

namespace
{

std::string checkFinite(const Array<Point>& pts, const char* what)
{
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y))
      return std::string(what) + " " + std::to_string(i) + " has a non-finite coordinate " +
        formatPoint(pts[i]);
  return {};
}

/// For each point, the first point (in input order) equal to it.
Array<int> exactRepresentatives(const Array<Point>& pts)
{
  // Sorting the points with their indices, not indices alone, keeps the
  // comparisons in cache.
  struct Indexed
  {
    Point p;
    int i;
  };
  const std::size_t n = pts.size();
  Array<Indexed> sorted(n);
  for (std::size_t k = 0; k < n; ++k)
    sorted[k] = { pts[k], static_cast<int>(k) };
  std::sort(sorted.begin(), sorted.end(),
    [](const Indexed& a, const Indexed& b) { return a.p < b.p || (a.p == b.p && a.i < b.i); });
  Array<int> representative(n);
  for (std::size_t k = 0; k < n; ++k)
  {
    const bool same = k > 0 && sorted[k].p == sorted[k - 1].p;
    representative[sorted[k].i] = same ? representative[sorted[k - 1].i] : sorted[k].i;
  }
  return representative;
}

/// For each point, the first earlier kept point within tol, or itself. A hash
/// grid of cells at least tol wide finds the candidates in the 3 x 3 cells
/// around it. Cells are also at least 2^-60 of the extent wide, counted from
/// its corner: a cell index of x / tol overflowed 64 bits (1e6 at 1e-13),
/// and the wrapped keys made the search quadratic.
Array<int> nearRepresentatives(const Array<Point>& pts, double tol, const JoinFilter& mayJoin)
{
  using Cell = std::pair<std::int64_t, std::int64_t>;
  struct CellHash
  {
    std::size_t operator()(const Cell& c) const
    {
      return static_cast<std::size_t>(static_cast<std::uint64_t>(c.first) * 0x9E3779B97F4A7C15ull ^
        static_cast<std::uint64_t>(c.second));
    }
  };
  const Bounds bounds = boundsOf(pts);
  const double cell = std::max(tol, std::ldexp(std::max(bounds.width(), bounds.height()), -60));
  // An extent that overflows (coordinates the mesher refuses) leaves every
  // point in cell 0: slow but defined.
  auto index = [&](double v, double lo) {
    const double c = std::floor((v - lo) / cell);
    return std::isfinite(c) ? static_cast<std::int64_t>(c) : std::int64_t{ 0 };
  };
  std::unordered_map<Cell, Array<int>, CellHash> grid;
  Array<int> representative(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    const std::int64_t cx = index(pts[i].x, bounds.lo.x), cy = index(pts[i].y, bounds.lo.y);
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy)
      {
        const auto it = grid.find({ cx + dx, cy + dy });
        if (it == grid.end())
          continue;
        for (int j : it->second)
          if (dist2(pts[i], pts[j]) <= tol * tol && (!mayJoin || mayJoin(static_cast<int>(i), j)))
          {
            found = j;
            break;
          }
      }
    representative[i] = found >= 0 ? found : static_cast<int>(i);
    if (found < 0)
      grid[{ cx, cy }].push_back(static_cast<int>(i));
  }
  return representative;
}

/// Merge equal (or, with a tolerance, close) points into their representative.
void mergeDuplicates(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double tol, const PointFormat& format,
  const JoinFilter& mayJoin)
{
  const std::size_t n = in.points.size();
  const Array<int> representative =
    tol > 0 ? nearRepresentatives(in.points, tol, mayJoin) : exactRepresentatives(in.points);
  int example = -1;
  for (std::size_t i = 0; i < n; ++i)
    if (representative[i] != static_cast<int>(i))
    {
      ++stats.duplicatePointsMerged;
      if (example < 0)
        example = static_cast<int>(i);
    }
  out.pointOf.assign(n, -1);
  out.points.reserve(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    const int r = representative[i];
    if (out.pointOf[r] < 0)
    {
      out.pointOf[r] = static_cast<int>(out.points.size());
      out.points.push_back(in.points[r]);
    }
    out.pointOf[i] = out.pointOf[r];
  }
  if (stats.duplicatePointsMerged > 0)
  {
    // A merge within a tolerance moves the point: give both positions then.
    const Point &moved = in.points[example], &kept = in.points[representative[example]];
    warnings.push_back("merged " + std::to_string(stats.duplicatePointsMerged) +
      " duplicate point(s), e.g. point " + std::to_string(example) +
      (moved == kept ? "" : " at " + formatPoint(moved, format)) + " with point " +
      std::to_string(representative[example]) + " at " + formatPoint(kept, format));
  }
}

/// Sorts the segments and drops repeats of one (the first in input order
/// stays): how many, and the input segment of one dropped.
std::pair<std::size_t, int> dropDuplicates(Array<OriginSegment>& segs)
{
  std::sort(segs.begin(), segs.end());
  std::size_t kept = 0, dropped = 0;
  int example = -1;
  for (std::size_t k = 0; k < segs.size(); ++k)
  {
    if (kept > 0 && segs[k].first == segs[kept - 1].first)
    {
      ++dropped;
      if (example < 0)
        example = segs[k].second;
      continue;
    }
    segs[kept++] = segs[k];
  }
  segs.resize(kept);
  return { dropped, example };
}

/// How far past a segment's ends in x a point within tol of it along and
/// across may lie: tol (|ux| + |uy|) for its direction u, at most tol sqrt(2)
/// (a review: a seed beyond a diagonal segment's end was missed with tol).
double reachInX(double tol)
{
  return tol * std::sqrt(2.0);
}

/// Hole and region seeds within tol of a segment that snapping bent may now
/// lie on its other side (its region and theirs swapped): say so, as the
/// mesh shows no trace of it. Seeds by the split segments: both are few.
void warnAboutSeedsBesideBends(const Pslg& in, const Array<Point>& points,
  const Array<OriginSegment>& split, double tol, std::vector<std::string>& warnings)
{
  const std::size_t holes = in.holes.size(), seedCount = holes + in.regions.size();
  if (split.empty() || seedCount == 0)
    return;
  // Seeds by x, each with its index (holes first, then regions): each segment looks
  // at those within its x range only (a review: 10,000 bricks with a region
  // seed each took 2.5 s here, comparing every seed with every segment).
  Array<std::pair<Point, std::size_t>> seeds;
  for (std::size_t k = 0; k < seedCount; ++k)
    seeds.push_back({ k < holes ? in.holes[k] : in.regions[k - holes].seed, k });
  std::sort(seeds.begin(), seeds.end());
  // Per seed: the first split segment it lies beside, or -1.
  Array<int> besideSegment(seedCount, -1);
  const double reach = reachInX(tol);
  for (std::size_t k = 0; k < split.size(); ++k)
  {
    const Point &a = points[split[k].first[0]], &b = points[split[k].first[1]];
    const SegmentFrame frame(a, b);
    auto it = std::lower_bound(seeds.begin(), seeds.end(), std::min(a.x, b.x) - reach,
      [](const std::pair<Point, std::size_t>& seed, double x) { return seed.first.x < x; });
    for (; it != seeds.end() && it->first.x <= std::max(a.x, b.x) + reach; ++it)
    {
      const double along = frame.along(it->first);
      if (besideSegment[it->second] < 0 && along >= -tol && along <= frame.length + tol &&
        std::fabs(frame.off(it->first)) <= tol)
        besideSegment[it->second] = static_cast<int>(k);
    }
  }
  const auto first =
    std::find_if(besideSegment.begin(), besideSegment.end(), [](int k) { return k >= 0; });
  if (first == besideSegment.end())
    return;
  const std::size_t seed = static_cast<std::size_t>(first - besideSegment.begin());
  const auto count =
    std::count_if(besideSegment.begin(), besideSegment.end(), [](int k) { return k >= 0; });
  warnings.push_back(std::to_string(count) +
    " hole or region seed(s) lie within the merge tolerance of a segment that was split at "
    "points near it, and may now lie on its other side: e.g. " +
    (seed < holes ? "hole " + std::to_string(seed) : "region " + std::to_string(seed - holes)) +
    " lies within the merge tolerance of segment " + std::to_string(split[*first].second));
}

/// Hole and region seeds that merging moved a segment across, or whose
/// segment it collapsed to a point (a small hole's outline): their region may
/// have changed, and the mesh shows no trace of it, so say so. Merging moves
/// a point by at most tol, so a seed can change sides only within tol of the
/// merged segment; seeds sorted by x give the candidates.
void warnAboutSeedsAcrossMerges(const Pslg& in, const CleanPslg& out, double tol,
  const PointFormat& format, std::vector<std::string>& warnings)
{
  if (tol <= 0 || (in.holes.empty() && in.regions.empty()))
    return;
  struct Seed
  {
    Point p;
    const char* kind;
    std::size_t index;
    bool moved = false;
  };
  Array<Seed> seeds;
  for (std::size_t h = 0; h < in.holes.size(); ++h)
    seeds.push_back({ in.holes[h], "hole", h });
  for (std::size_t r = 0; r < in.regions.size(); ++r)
    seeds.push_back({ in.regions[r].seed, "region", r });
  std::sort(seeds.begin(), seeds.end(), [](const Seed& a, const Seed& b) { return a.p < b.p; });
  std::size_t count = 0;
  std::string example;
  for (std::size_t s = 0; s < in.segments.size(); ++s)
  {
    const Point &a0 = in.points[in.segments[s][0]], &b0 = in.points[in.segments[s][1]];
    const Point &a = out.points[out.pointOf[in.segments[s][0]]],
                &b = out.points[out.pointOf[in.segments[s][1]]];
    if ((a0 == a && b0 == b) || a0 == b0)
      continue;
    const bool collapsed = a == b;
    const SegmentFrame frame(a, collapsed ? Point{ a.x + 1, a.y } : b);
    const double length = collapsed ? 0.0 : frame.length;
    auto it = std::lower_bound(seeds.begin(), seeds.end(), std::min(a.x, b.x) - reachInX(tol),
      [](const Seed& seed, double x) { return seed.p.x < x; });
    for (; it != seeds.end() && it->p.x <= std::max(a.x, b.x) + reachInX(tol); ++it)
    {
      const Point& q = it->p;
      const double along = frame.along(q);
      if (it->moved || along < -tol || along > length + tol || std::fabs(frame.off(q)) > tol)
        continue;
      if (!collapsed && orientSign(a0, b0, q) == orientSign(a, b, q))
        continue;
      it->moved = true;
      if (count++ == 0)
        example = std::string(it->kind) + " " + std::to_string(it->index) + " at " +
          formatPoint(q, format) + " and segment " + std::to_string(s);
    }
  }
  if (count > 0)
    warnings.push_back(std::to_string(count) +
      " hole or region seed(s) lie where merging points within the merge tolerance moved a "
      "segment across them or collapsed it to a point, so they may now lie in another region: "
      "e.g. " +
      example);
}

/// The segments on the merged points; with a tolerance, split at the points
/// within it (Snap.h); zero-length and duplicate ones dropped.
std::string mapSegments(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double tol, const PointFormat& format, bool snap)
{
  const long long n = static_cast<long long>(in.points.size());
  Array<OriginSegment> segs;
  segs.reserve(in.segments.size());
  int zeroExample = -1;
  for (std::size_t s = 0; s < in.segments.size(); ++s)
  {
    const Segment& seg = in.segments[s];
    for (int e : seg)
      if (e < 0 || e >= n)
        return "segment " + std::to_string(s) + " refers to point " + std::to_string(e) +
          ", but there are " + std::to_string(n) + " points";
    int a = out.pointOf[seg[0]], b = out.pointOf[seg[1]];
    if (a == b)
    {
      ++stats.zeroLengthSegmentsDropped;
      if (zeroExample < 0)
        zeroExample = static_cast<int>(s);
      continue;
    }
    segs.push_back({ { std::min(a, b), std::max(a, b) }, static_cast<int>(s) });
  }
  if (zeroExample >= 0)
    warnings.push_back("dropped " + std::to_string(stats.zeroLengthSegmentsDropped) +
      " zero-length segment(s), e.g. segment " + std::to_string(zeroExample));
  // Duplicates in the input are counted as such; pieces that snapping makes
  // coincide (a segment and a copy of part of it) are said with the snaps.
  const auto [duplicates, dupExample] = dropDuplicates(segs);
  stats.duplicateSegmentsMerged = duplicates;
  if (duplicates > 0)
    warnings.push_back("merged " + std::to_string(duplicates) +
      " duplicate segment(s), e.g. segment " + std::to_string(dupExample));
  SnapExample snapped;
  Array<OriginSegment> split;
  stats.pointsSnappedOntoSegments =
    snap ? snapPointsOntoSegments(out.points, segs, tol, snapped, &split) : 0;
  if (stats.pointsSnappedOntoSegments > 0)
  {
    const std::size_t coincide = dropDuplicates(segs).first;
    warnings.push_back("split segments " + std::to_string(stats.pointsSnappedOntoSegments) +
      " time(s) at points within the merge tolerance of them" +
      (coincide > 0
          ? " (" + std::to_string(coincide) + " of the pieces then coincided and were merged)"
          : std::string()) +
      ", e.g. segment " + std::to_string(snapped.segment) + " at point " +
      std::to_string(firstInputPoint(out.pointOf, snapped.point)) + " " +
      formatPoint(out.points[snapped.point], format));
  }
  for (const auto& [segment, origin] : segs)
  {
    out.segments.push_back(segment);
    out.segmentOrigin.push_back(origin);
  }
  warnAboutSeedsAcrossMerges(in, out, tol, format, warnings);
  warnAboutSeedsBesideBends(in, out.points, split, tol, warnings);
  return {};
}

} // namespace

int firstInputPoint(const Array<int>& pointOf, int v)
{
  return static_cast<int>(std::find(pointOf.begin(), pointOf.end(), v) - pointOf.begin());
}

std::string cleanPslg(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double mergeTolerance, const PointFormat& format, bool snap,
  const JoinFilter& mayJoin)
{
  out = CleanPslg{};
  if (std::string e = checkFinite(in.points, "point"); !e.empty())
    return e;
  if (std::string e = checkFinite(in.holes, "hole point"); !e.empty())
    return e;
  for (std::size_t r = 0; r < in.regions.size(); ++r)
  {
    const RegionAttribute& region = in.regions[r];
    if (!std::isfinite(region.seed.x) || !std::isfinite(region.seed.y))
      return "region " + std::to_string(r) + " has a non-finite coordinate " +
        formatPoint(region.seed);
    if (!std::isfinite(region.attribute))
      return "region " + std::to_string(r) + " has a non-finite attribute";
    // An infinite area bounds nothing, as 0 or a negative one; NaN is no number.
    if (std::isnan(region.maxArea))
      return "region " + std::to_string(r) + " has a maximum area that is not a number";
  }
  mergeDuplicates(in, out, stats, warnings, mergeTolerance, format, mayJoin);
  return mapSegments(in, out, stats, warnings, mergeTolerance, format, snap);
}

} // namespace osm
