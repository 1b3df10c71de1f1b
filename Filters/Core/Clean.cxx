#include "Clean.h"

#include "HugePages.h"
#include "Snap.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <unordered_map>

namespace osm
{

std::string formatPoint(const Point& p)
{
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

std::string formatNumber(double x)
{
  char buf[40];
  for (int digits = 15; digits <= 17; ++digits)
  {
    std::snprintf(buf, sizeof buf, "%.*g", digits, x);
    if (std::strtod(buf, nullptr) == x)
      break;
  }
  return buf;
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
/// grid of cell size tol finds the candidates in the 3 x 3 cells around it.
Array<int> nearRepresentatives(const Array<Point>& pts, double tol)
{
  std::unordered_map<std::uint64_t, Array<int>> grid;
  auto key = [](std::int64_t x, std::int64_t y) {
    return (static_cast<std::uint64_t>(x) << 32) ^ static_cast<std::uint64_t>(y & 0xffffffff);
  };
  Array<int> representative(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i)
  {
    const auto cx = static_cast<std::int64_t>(std::floor(pts[i].x / tol));
    const auto cy = static_cast<std::int64_t>(std::floor(pts[i].y / tol));
    int found = -1;
    for (std::int64_t dx = -1; dx <= 1 && found < 0; ++dx)
      for (std::int64_t dy = -1; dy <= 1 && found < 0; ++dy)
      {
        const auto it = grid.find(key(cx + dx, cy + dy));
        if (it == grid.end())
          continue;
        for (int j : it->second)
          if (dist2(pts[i], pts[j]) <= tol * tol)
          {
            found = j;
            break;
          }
      }
    representative[i] = found >= 0 ? found : static_cast<int>(i);
    if (found < 0)
      grid[key(cx, cy)].push_back(static_cast<int>(i));
  }
  return representative;
}

/// Merge equal (or, with a tolerance, close) points into their representative.
void mergeDuplicates(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double tol, const PointFormat& format)
{
  const std::size_t n = in.points.size();
  const Array<int> representative =
    tol > 0 ? nearRepresentatives(in.points, tol) : exactRepresentatives(in.points);
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
    warnings.push_back("merged " + std::to_string(stats.duplicatePointsMerged) +
      " duplicate point(s), e.g. point " + std::to_string(example) + " with point " +
      std::to_string(representative[example]) + " at " + formatPoint(in.points[example], format));
}

/// The segments on the merged points; with a tolerance, split at the points
/// within it (Snap.h); zero-length and duplicate ones dropped.
std::string mapSegments(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double tol, const PointFormat& format)
{
  const long long n = static_cast<long long>(in.points.size());
  Array<std::pair<Segment, int>> segs;
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
  SnapExample snapped;
  stats.pointsSnappedOntoSegments = snapPointsOntoSegments(out.points, segs, tol, snapped);
  if (stats.pointsSnappedOntoSegments > 0)
  {
    const auto first = std::find(out.pointOf.begin(), out.pointOf.end(), snapped.point);
    warnings.push_back("split segments at " + std::to_string(stats.pointsSnappedOntoSegments) +
      " point(s) within the merge tolerance of them, e.g. segment " +
      std::to_string(snapped.segment) + " at point " + std::to_string(first - out.pointOf.begin()) +
      " " + formatPoint(out.points[snapped.point], format));
  }
  std::sort(segs.begin(), segs.end());
  int dupExample = -1;
  for (std::size_t k = 0; k < segs.size(); ++k)
  {
    if (k > 0 && segs[k].first == segs[k - 1].first)
    {
      ++stats.duplicateSegmentsMerged;
      if (dupExample < 0)
        dupExample = segs[k].second;
      continue;
    }
    out.segments.push_back(segs[k].first);
    out.segmentOrigin.push_back(segs[k].second);
  }
  if (dupExample >= 0)
    warnings.push_back("merged " + std::to_string(stats.duplicateSegmentsMerged) +
      " duplicate segment(s), e.g. segment " + std::to_string(dupExample));
  return {};
}

} // namespace

std::string cleanPslg(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings, double mergeTolerance, const PointFormat& format)
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
  }
  mergeDuplicates(in, out, stats, warnings, mergeTolerance, format);
  return mapSegments(in, out, stats, warnings, mergeTolerance, format);
}

} // namespace osm
