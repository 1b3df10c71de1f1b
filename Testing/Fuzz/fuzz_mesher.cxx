// libFuzzer target: the whole mesher on small arbitrary PSLGs, with the
// independent validator as the oracle. Coordinates come mostly from a small
// integer grid so duplicates, collinear points, T-junctions, overlaps and
// crossings are frequent; some are raw doubles to reach extreme values.
#include "Clean.h"
#include "Geometry.h"
#include "Interpolation.h"
#include "Mesher.h"
#include "Validate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

namespace
{

class Bytes
{
public:
  Bytes(const std::uint8_t* d, std::size_t n)
    : data(d)
    , size(n)
  {}
  std::uint8_t byte() { return pos < size ? data[pos++] : 0; }
  double rawDouble()
  {
    double v = 0;
    std::uint8_t b[8] = {};
    for (std::uint8_t& x : b)
      x = byte();
    std::memcpy(&v, b, sizeof v);
    return v;
  }
  double coordinate()
  {
    const std::uint8_t kind = byte();
    if (kind < 200)
      return static_cast<double>(kind % 16); // grid: degeneracies
    if (kind < 240)
      return static_cast<double>(byte()) / 7.0; // rounded fractions
    return rawDouble();                         // anything, NaN included
  }

private:
  const std::uint8_t* data;
  std::size_t size;
  std::size_t pos = 0;
};

/// The input and options of the run in progress, written out on a failure
/// so that it can be reproduced without decoding the fuzzer's bytes.
const osm::Pslg* currentInput = nullptr;
const osm::Options* currentOptions = nullptr;

void fail(const char* what, const std::string& detail)
{
  std::fprintf(stderr, "fuzz_mesher: %s: %s\n", what, detail.c_str());
  if (const osm::Pslg* p = currentInput)
  {
    std::fprintf(stderr, "the input, as a .poly counting from 0:\n%zu 2 0 0\n", p->points.size());
    for (std::size_t i = 0; i < p->points.size(); ++i)
      std::fprintf(stderr, "%zu %.17g %.17g\n", i, p->points[i].x, p->points[i].y);
    std::fprintf(stderr, "%zu 0\n", p->segments.size());
    for (std::size_t i = 0; i < p->segments.size(); ++i)
      std::fprintf(stderr, "%zu %d %d\n", i, p->segments[i][0], p->segments[i][1]);
    std::fprintf(stderr, "%zu\n", p->holes.size());
    for (std::size_t i = 0; i < p->holes.size(); ++i)
      std::fprintf(stderr, "%zu %.17g %.17g\n", i, p->holes[i].x, p->holes[i].y);
    std::fprintf(stderr, "%zu\n", p->regions.size());
    for (std::size_t i = 0; i < p->regions.size(); ++i)
      std::fprintf(stderr, "%zu %.17g %.17g %.17g %.17g\n", i, p->regions[i].seed.x,
        p->regions[i].seed.y, p->regions[i].attribute, p->regions[i].maxArea);
  }
  if (const osm::Options* o = currentOptions)
    std::fprintf(stderr,
      "options: domain %d, minAngleDeg %.17g, maxEdgeLength %.17g, mergeTolerance %.17g, "
      "resolveCrossings %d, gapRatioOverlay %d, regionAreas %d, maxSteinerPoints %zu\n",
      static_cast<int>(o->domain), o->minAngleDeg, o->maxEdgeLength, o->mergeTolerance,
      o->resolveCrossings, o->gapRatioOverlay, o->regionAreas, o->maxSteinerPoints);
  std::abort();
}

/// The weights that carry input point data to the mesh (Interpolation.h):
/// every vertex once, convex terms on input points; a linear field (x/extent
/// + 2 y/extent, a function of the input's scale) reproduced to rounding
/// (and the distance a merge tolerance moves a segment from its vertices)
/// where every vertex lies within the input's hull: not with the box domain,
/// chosen or fallen back to (seen as vertices beyond the input's bounds).
void checkInterpolation(
  const osm::Pslg& p, const osm::Result& r, const osm::Options& o, double extent)
{
  std::vector<char> seen(r.mesh.vertices.size(), 0);
  const double scale = extent > 0 ? 1.0 / extent : 1.0;
  auto f = [scale](const osm::Point& q) { return scale * q.x + 2 * scale * q.y; };
  double x0 = p.points[0].x, x1 = x0, y0 = p.points[0].y, y1 = y0;
  for (const osm::Point& q : p.points)
    x0 = std::fmin(x0, q.x), x1 = std::fmax(x1, q.x), y0 = std::fmin(y0, q.y),
    y1 = std::fmax(y1, q.y);
  bool linear = std::isfinite(scale) && extent < 1e300;
  for (const osm::Point& v : r.mesh.vertices)
    linear = linear && v.x >= x0 && v.x <= x1 && v.y >= y0 && v.y <= y1;
  // Rounding, relative to the input's magnitude: a stitch vertex is some
  // units in the last place off its segment, which moves its weights by that
  // over the width of the triangles it falls in: more in a flat input (a
  // long thin box, by its aspect) and among points closer than its
  // magnitude (by their spread; points 1e-19 apart at 12 gave 3e-9, a box
  // 14 by 1.5e9 1e-6).
  double magnitude = 0, closest = 1e300;
  for (const osm::Point& q : p.points)
  {
    magnitude = std::fmax(magnitude, std::fmax(std::abs(q.x), std::abs(q.y)));
    for (const osm::Point& u : p.points)
      if (u != q)
        closest = std::fmin(closest, std::hypot(u.x - q.x, u.y - q.y));
  }
  const double aspect =
    std::fmax(x1 - x0, y1 - y0) / std::fmax(std::fmin(x1 - x0, y1 - y0), 1e-300);
  const double spread = magnitude / std::fmax(closest, 1e-300);
  const double rounding = (1e-9 + 1e-13 * (aspect + spread)) * scale * magnitude;
  // Each vertex by its kind: an input vertex takes its own value, exactly; a
  // vertex on a segment the value at its nearest point there (a merge
  // tolerance may move and bend the segment away from it), off by f's
  // gradient (√5 scale) times its distance to the segment; any other one a
  // convex combination of those within their hull, off by at most their
  // largest error.
  double knownError = 0;
  std::vector<double> otherError(r.mesh.vertices.size(), -1);
  auto check = [&](double error, double allowed, const osm::VertexTerms& t, const char* kind) {
    if (linear && error > allowed)
      fail("interpolation",
        "a linear field off by " + std::to_string(error) + " (allowed " + std::to_string(allowed) +
          ") at vertex " + std::to_string(t.vertex) + ", " + kind + " (origin " +
          std::to_string(static_cast<int>(r.vertexOrigin[t.vertex])) + ")");
  };
  osm::visitInputWeights(p, r, [&](const osm::VertexTerms& t) {
    if (t.vertex >= seen.size() || seen[t.vertex]++)
      fail(
        "interpolation", "vertex " + std::to_string(t.vertex) + " out of range or visited twice");
    double sum = 0, value = 0;
    for (int k = 0; k < t.count; ++k)
    {
      if (t.point[k] < 0 || t.point[k] >= static_cast<int>(p.points.size()) ||
        !(t.weight[k] > 0 && t.weight[k] <= 1 + 1e-12))
        fail("interpolation", "a bad term at vertex " + std::to_string(t.vertex));
      sum += t.weight[k];
      value += t.weight[k] * f(p.points[t.point[k]]);
    }
    if (t.count == 0 || std::abs(sum - 1) > 1e-9)
      fail("interpolation",
        "weights summing to " + std::to_string(sum) + " at vertex " + std::to_string(t.vertex));
    const osm::Point& v = r.mesh.vertices[t.vertex];
    const double error = std::abs(value - f(v));
    if (t.inputPoint >= 0)
      check(error, rounding, t, "an input vertex");
    else if (t.segment >= 0)
    {
      // Between its ends as merged: an end merged into an earlier point takes
      // that point's value and place.
      const osm::Segment& e = p.segments[static_cast<std::size_t>(t.segment)];
      auto kept = [&](int end) {
        const int at = r.inputVertex[static_cast<std::size_t>(end)];
        const auto first = std::find(r.inputVertex.begin(), r.inputVertex.end(), at);
        return at >= 0 ? p.points[static_cast<std::size_t>(first - r.inputVertex.begin())]
                       : p.points[static_cast<std::size_t>(end)];
      };
      const double off = osm::distanceToSegment(v, kept(e[0]), kept(e[1]));
      check(error, std::sqrt(5.0) * scale * off * (1 + 1e-9) + rounding, t, "on a segment");
    }
    else
      otherError[t.vertex] = error;
    if (t.inputPoint >= 0 || t.segment >= 0)
      knownError = std::fmax(knownError, error);
    return true;
  });
  for (std::size_t v = 0; v < otherError.size(); ++v)
    if (otherError[v] >= 0)
    {
      osm::VertexTerms t;
      t.vertex = v;
      check(otherError[v], knownError + rounding, t, "neither an input vertex nor on a segment");
    }
  if (std::count(seen.begin(), seen.end(), 1) != static_cast<long>(seen.size()))
    fail("interpolation", "not every vertex visited");
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  Bytes in(data, size);
  osm::Pslg p;
  const int n = 1 + in.byte() % 16, m = in.byte() % 16, holes = in.byte() % 3;
  for (int i = 0; i < n; ++i)
    p.points.push_back({ in.coordinate(), in.coordinate() });
  for (int s = 0; s < m; ++s)
    p.segments.push_back({ in.byte() % n, in.byte() % n });
  for (int h = 0; h < holes; ++h)
    p.holes.push_back({ in.coordinate(), in.coordinate() });
  osm::Options o;
  o.minAngleDeg = 20.0 + in.byte() % 11;
  o.domain = static_cast<osm::Domain>(in.byte() % 4);
  // A runaway becomes an error, never a hang; at 200,000 a mesh and its
  // validation took 6.7 s under the fuzzer's instrumentation, near its
  // 10 s time-out.
  o.maxSteinerPoints = 100000;
  o.keepVertexSegments = true; // for checkInterpolation
  // Last, so that older seeds decode as before: a size bound of 1/2 to 1/5
  // of the input's extent for a quarter of the inputs, or none (finer or more
  // bounds make meshes that the validator's brute-force overlap check takes
  // long over: 80,000 runs took 3 times as long with 1/2 to 1/7 on 3/4).
  double lo = p.points[0].x, hi = lo;
  for (const osm::Point& q : p.points)
    for (double c : { q.x, q.y })
      lo = std::fmin(lo, c), hi = std::fmax(hi, c);
  const double extent = std::isfinite(hi - lo) ? hi - lo : 0.0;
  if (const int parts = in.byte() % 16; parts >= 2 && parts <= 5)
    o.maxEdgeLength = extent / parts;
  // Then region seeds with area limits for a quarter of the inputs: seed k's
  // attribute is k + 1, so a triangle's attribute names the seed whose area
  // bounds it (the last seed of its region gives both).
  const int regions = in.byte() % 8;
  o.regionAreas = regions > 0 && regions <= 2;
  for (int k = 0; o.regionAreas && k < regions; ++k)
  {
    const osm::Point seed{ in.coordinate(), in.coordinate() };
    const int kind = in.byte() % 3;
    p.regions.push_back(
      { seed, double(k + 1), kind == 0 ? -1.0 : extent * extent / (kind == 1 ? 20.0 : 200.0) });
  }
  // Then a merge tolerance of 1e-1 to 1e-6 of the extent for an eighth of
  // the inputs: points merge, and segments bend onto points near them.
  if (const int digits = in.byte() % 48; digits >= 1 && digits <= 6)
    o.mergeTolerance = extent * std::pow(10.0, -digits);
  // Then the gap-ratio overlay for a quarter of the inputs. Its meshes grade
  // more slowly, up to 12 times larger: a tenth of the cap keeps their
  // validation as quick as the others'.
  o.gapRatioOverlay = in.byte() % 4 == 1;
  if (o.gapRatioOverlay)
    o.maxSteinerPoints = 10000;
  currentInput = &p;
  currentOptions = &o;
  const osm::Result r = osm::mesh(p, o);
  // Refused: the message is checked by the unit tests; but an internal error
  // is a defect of ours, whatever the input.
  if (!r.ok && r.error.find("internal error") != std::string::npos)
    fail("internal error", r.error);
  if (!r.ok)
    return 0;
  // Regions' areas bound their triangles, unless a warning says which edges
  // stay longer (on a segment, or where a region seed on a segment left the
  // refined side to the other: the warnings name both).
  bool longKept = false;
  for (const std::string& w : r.warnings)
    longKept = longKept || w.find("longer than the maximum edge length") != std::string::npos;
  for (std::size_t t = 0; !longKept && t < r.regionAttribute.size(); ++t)
  {
    const int k = static_cast<int>(r.regionAttribute[t]) - 1;
    if (k < 0 || !(p.regions[k].maxArea > 0))
      continue;
    const osm::Triangle& tri = r.mesh.triangles[t];
    const osm::Point &a = r.mesh.vertices[tri[0]], &b = r.mesh.vertices[tri[1]],
                     &c = r.mesh.vertices[tri[2]];
    const double area = 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    if (area > p.regions[k].maxArea * (1 + 1e-9))
      fail("triangle above its region's maximum area",
        "triangle " + std::to_string(t) + " of area " + std::to_string(area) + " > " +
          std::to_string(p.regions[k].maxArea));
  }
  // Validate against the input points that the domain kept (the rest are
  // warned about), each where it was merged to: within the tolerance.
  osm::Pslg present;
  std::vector<int> index(p.points.size(), -1);
  for (std::size_t i = 0; i < p.points.size(); ++i)
    if (r.inputVertex[i] >= 0)
    {
      const osm::Point& at = r.mesh.vertices[r.inputVertex[i]];
      if (!(at == p.points[i]) &&
        !(std::hypot(at.x - p.points[i].x, at.y - p.points[i].y) <= o.mergeTolerance))
        fail("input point moved", "point " + std::to_string(i));
      index[i] = static_cast<int>(present.points.size());
      present.points.push_back(at);
    }
  for (const osm::Segment& s : p.segments)
    if (index[s[0]] >= 0 && index[s[1]] >= 0 &&
      !(present.points[index[s[0]]] == present.points[index[s[1]]]))
      present.segments.push_back({ index[s[0]], index[s[1]] });
  osm::ValidationOptions vo;
  vo.snapTolerance = o.mergeTolerance;
  vo.maxAngleDeg = r.stats.predictedMaxAngleDeg + 1e-9;
  // Above the bound only where rounding explains it, and then with a warning
  // that says so (features thousands of units in the last place across).
  for (const std::string& w : r.warnings)
    if (w.find("exceed the largest-angle bound") != std::string::npos)
    {
      if (w.find("there rounding the points placed on segments") == std::string::npos)
        fail("angle above the bound", w);
      vo.maxAngleDeg = r.stats.maxAngleDeg + 1e-9;
    }
  // No edge longer than the size bound, unless a warning says which is.
  vo.maxEdgeLength = longKept ? 0.0 : o.maxEdgeLength;
  // Holes and the enclosed-regions domain remove whole regions, and with them
  // the parts of segments inside (a hole seed on a vertex picks one of its
  // regions): conformity is then checked only where every segment is meshed.
  vo.checkConformity =
    p.holes.empty() && (o.domain == osm::Domain::Box || o.domain == osm::Domain::Hull);
  // Crossings within the merge tolerance of a point or of each other join it,
  // so the segments' chains pass through points up to that far off their lines.
  if (r.stats.crossingsSplit > 0)
    vo.chainOffset = o.mergeTolerance;
  const osm::ValidationReport rep = osm::validate(present, r.mesh.vertices, r.mesh.triangles, vo);
  if (!rep.ok)
    fail("invalid mesh", rep.errors.empty() ? "" : rep.errors.front());
  // The domain, against the whole input (segments whose points it left out
  // bound it too): its boundary along the segments (or the hull's or box's
  // edges), and no hole seed covered unless a merge moved one across a segment.
  osm::ValidationOptions dom;
  dom.maxAngleDeg = 180;
  dom.checkConformity = false;
  dom.requireAllInputVertices = false;
  dom.bruteForceOverlapLimit = 0;
  dom.snapTolerance = o.mergeTolerance;
  dom.chainOffset = vo.chainOffset;
  dom.boundary = r.domain == osm::Domain::Enclosed ? osm::DomainBoundary::Segments
    : r.domain == osm::Domain::Hull                ? osm::DomainBoundary::SegmentsOrHull
                                                   : osm::DomainBoundary::SegmentsOrBox;
  dom.checkHoles = true;
  for (const std::string& w : r.warnings)
    dom.checkHoles =
      dom.checkHoles && w.find("seed(s) now lie on the other side") == std::string::npos;
  // Each point where merging put it, whether the domain kept it or not (a
  // merge moves a segment's end, and snapping then bends it by up to the
  // tolerance): cleaning's own merge, so that a segment whose end joined a
  // point outside the domain runs where the mesher saw it (CI's run found a
  // boundary edge 3.5 off a segment whose end had joined one 3.2 away).
  osm::Pslg whole = p;
  osm::CleanPslg merged;
  osm::Statistics ignored;
  std::vector<std::string> ignoredWarnings;
  if (!osm::cleanPslg(p, merged, ignored, ignoredWarnings, o.mergeTolerance).empty())
    fail("input refused by cleaning but meshed", "");
  for (std::size_t i = 0; i < p.points.size(); ++i)
    whole.points[i] = merged.points[merged.pointOf[i]];
  const osm::ValidationReport d = osm::validate(whole, r.mesh.vertices, r.mesh.triangles, dom);
  if (!d.ok)
    fail("mesh beyond or short of its domain", d.errors.empty() ? "" : d.errors.front());
  checkInterpolation(p, r, o, extent);
  return 0;
}
