#include "Clean.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>

namespace osm
{

std::string formatPoint(const Point& p)
{
  char buf[80];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

namespace
{

std::string checkFinite(const std::vector<Point>& pts, const char* what)
{
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y))
      return std::string(what) + " " + std::to_string(i) + " has a non-finite coordinate " +
        formatPoint(pts[i]);
  return {};
}

/// Merge exactly equal points; the first occurrence represents them.
void mergeDuplicates(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings)
{
  const std::size_t n = in.points.size();
  std::vector<int> order(n);
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](int a, int b) {
    return in.points[a] < in.points[b] || (in.points[a] == in.points[b] && a < b);
  });
  std::vector<int> representative(n);
  int example = -1;
  for (std::size_t k = 0; k < n; ++k)
  {
    const bool same = k > 0 && in.points[order[k]] == in.points[order[k - 1]];
    representative[order[k]] = same ? representative[order[k - 1]] : order[k];
    if (same)
    {
      ++stats.duplicatePointsMerged;
      if (example < 0)
        example = order[k];
    }
  }
  out.pointOf.assign(n, -1);
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
      std::to_string(representative[example]) + " at " + formatPoint(in.points[example]));
}

std::string mapSegments(const Pslg& in, CleanPslg& out, Statistics& stats,
  std::vector<std::string>& warnings)
{
  const long long n = static_cast<long long>(in.points.size());
  std::vector<std::pair<Segment, int>> segs;
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

std::string cleanPslg(
  const Pslg& in, CleanPslg& out, Statistics& stats, std::vector<std::string>& warnings)
{
  out = CleanPslg{};
  if (std::string e = checkFinite(in.points, "point"); !e.empty())
    return e;
  if (std::string e = checkFinite(in.holes, "hole point"); !e.empty())
    return e;
  mergeDuplicates(in, out, stats, warnings);
  return mapSegments(in, out, stats, warnings);
}

} // namespace osm
