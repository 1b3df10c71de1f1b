// osm::mesh: input cleaning, the three phases of Overlay Stitch Meshing, and
// the choice of domain, with statistics and progress.
#include "Mesher.h"

#include "Clean.h"
#include "Complete.h"
#include "CycleComponents.h"
#include "Domain.h"
#include "HugePages.h"
#include "InputWarnings.h"
#include "LongEdges.h"
#include "NumberText.h"
#include "Overlay.h"
#include "Predicates.h"
#include "RunContext.h"
#include "Series.h"
#include "SplitCrossings.h"
#include "Stitch.h"
#include "Work.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <new>
#include <string>
#include <vector>

namespace osm
{

double predictedMaxAngleDeg(double minAngleDeg)
{
  const double theta1 = minAngleDeg * series::kPi / 180.0;
  const double gamma = gammaForMinAngle(minAngleDeg);
  // The argument is at most 0.23 (at θ1 = 35°, the largest Options allows).
  const double theta2 = series::asin(1.0 / (2.0 * gamma * (2.0 * gamma + series::cos(theta1))));
  return 180.0 - theta2 * 180.0 / series::kPi;
}

EdgeClass edgeClass(std::uint8_t flags)
{
  if (flags & EdgeInput)
    return EdgeClass::Input;
  if (flags & EdgeDiscarded)
    return EdgeClass::Discarded;
  if (flags & EdgeCrossed)
    return EdgeClass::Kept;
  return EdgeClass::Uncrossed;
}

const char* edgeClassName(EdgeClass c)
{
  switch (c)
  {
    case EdgeClass::Kept:
      return "Kept";
    case EdgeClass::Discarded:
      return "Discarded";
    case EdgeClass::Input:
      return "Input";
    case EdgeClass::Uncrossed:
      break;
  }
  return "Uncrossed";
}

namespace
{

using Clock = std::chrono::steady_clock;

double since(Clock::time_point t0)
{
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Above 30 degrees (Γ below 1) Delaunay refinement of points is not proven to
/// end, and in practice the overlay grows fast and then does not end: us48.poly
/// takes 1.7, 3.5 and 12 times the triangles of 30 degrees at 31, 32 and 33,
/// spread 1e3 fails at 32.5, and 2e4 random points at 33.5.
std::string beyondGuaranteeWarning(double minAngleDeg)
{
  return "a minimum angle above 30 degrees (here " + generalText(minAngleDeg, 6) +
    ") has no guarantee: the overlay may grow several times larger, or its refinement not end";
}

/// An origin that subtracts exactly from every coordinate in [lo, hi] (x - c
/// is exact for c/2 <= x <= 2c), where the points lie far from 0 for their
/// spread: data at an offset (map coordinates) then keeps double precision
/// for its features, not for the offset (a review: a square 100 wide at 1e13
/// was bent through overlay points by 0.0176, 9 units in the last place
/// there, and one at 1e14 refused). 0 where that gains less than 4 bits.
double exactOrigin(double lo, double hi)
{
  if (lo > 0 && hi - lo <= hi / 16)
    return lo;
  if (hi < 0 && hi - lo <= -lo / 16)
    return hi;
  return 0;
}

/// Power-of-two scale bringing the largest coordinate of a point into
/// [0.5, 1), after subtracting exactOrigin per axis: both exact, so input
/// vertices come back bit for bit, and the predicates cannot overflow. Hole
/// and region seeds far beyond the points, outside every triangle, are moved
/// in to 16 (scaled), still outside: such a seed set the scale before, and a
/// seed at 1e100 made the points "too small".
std::string normalise(Work& w, const Pslg& input, const Array<int>& pointOf,
  const PointFormat& format, bool translate, Frame& frame)
{
  frame = Frame{};
  if (translate && !w.points.empty())
  {
    Point lo = w.points.front(), hi = lo;
    for (const Point& p : w.points)
    {
      lo = { std::min(lo.x, p.x), std::min(lo.y, p.y) };
      hi = { std::max(hi.x, p.x), std::max(hi.y, p.y) };
    }
    frame.origin = { exactOrigin(lo.x, hi.x), exactOrigin(lo.y, hi.y) };
    if (frame.origin.x != 0 || frame.origin.y != 0)
    {
      for (Point& p : w.points)
        p = { p.x - frame.origin.x, p.y - frame.origin.y };
      for (Point& p : w.holes)
        p = { p.x - frame.origin.x, p.y - frame.origin.y };
      for (Point& p : w.regionSeeds)
        p = { p.x - frame.origin.x, p.y - frame.origin.y };
    }
  }
  int& exponent = frame.exponent;
  double maxAbs = 0;
  for (const Point& p : w.points)
    maxAbs = std::max({ maxAbs, std::fabs(p.x), std::fabs(p.y) });
  if (maxAbs == 0)
    for (const Point& p : w.holes)
      maxAbs = std::max({ maxAbs, std::fabs(p.x), std::fabs(p.y) });
  if (maxAbs == 0)
    return {};
  // The padded box reaches about 5 times the largest coordinate: it must stay finite.
  if (maxAbs > std::numeric_limits<double>::max() / 16)
  {
    return "a coordinate of magnitude " + formatNumber(maxAbs) +
      " is too large: the mesher needs coordinates below 1.1e307 to pad the domain";
  }
  std::frexp(maxAbs, &exponent);
  // Multiplying by a normal power of two rounds exactly as ldexp does, without
  // a library call per coordinate; other exponents keep ldexp.
  const bool normalPower = std::abs(exponent) <= 1021;
  const double factor = std::ldexp(1.0, normalPower ? -exponent : 0);
  auto scale = [&](Point& p) {
    if (normalPower)
      p = { p.x * factor, p.y * factor };
    else
      p = { std::ldexp(p.x, -exponent), std::ldexp(p.y, -exponent) };
  };
  for (std::size_t i = 0; i < w.points.size(); ++i)
  {
    const Point before = w.points[i];
    scale(w.points[i]);
    const Point& p = w.points[i];
    // The exact incircle needs every nonzero coordinate above ~2^-216 of the largest.
    if ((before.x != 0 && std::fabs(p.x) < 0x1p-200) ||
      (before.y != 0 && std::fabs(p.y) < 0x1p-200))
    {
      const int user = firstInputPoint(pointOf, static_cast<int>(i));
      const Point& q = input.points[user];
      const double tiny = before.x != 0 && std::fabs(p.x) < 0x1p-200 ? q.x : q.y;
      return namePoint(input, user, format) + " has a coordinate (" + formatNumber(tiny) +
        ") too small next to the largest coordinate (" + formatNumber(maxAbs) +
        ") for exact arithmetic in double precision (nonzero coordinates must be above 2^-200 "
        "of the largest): round it to 0";
    }
  }
  const auto scaleSeed = [&](Point& p) {
    const auto in = [](double v) { return std::fabs(v) > 16 ? std::copysign(16.0, v) : v; };
    if (std::fabs(p.x) > std::ldexp(16.0, exponent) || std::fabs(p.y) > std::ldexp(16.0, exponent))
      p = { in(std::ldexp(p.x, -exponent)), in(std::ldexp(p.y, -exponent)) };
    else
      scale(p);
  };
  for (Point& p : w.holes)
    scaleSeed(p);
  for (Point& p : w.regionSeeds)
    scaleSeed(p);
  return {};
}

/// Appends the edges of hull (from hullBoundary) that no segment joins already.
/// hullBoundary lists every point on the hull's edges, so a segment along the
/// hull joins two consecutive hull points; walking it twice would find the
/// two copies crossing each other wherever rounding put it.
void appendHullEdges(const Array<int>& hull, Array<Segment>& segments)
{
  const std::size_t h = hull.size();
  const auto key = [](int a, int b) {
    return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
      static_cast<std::uint32_t>(std::max(a, b));
  };
  std::vector<std::pair<std::uint64_t, std::size_t>> edges(h);
  for (std::size_t i = 0; i < h; ++i)
    edges[i] = { key(hull[i], hull[(i + 1) % h]), i };
  std::sort(edges.begin(), edges.end());
  std::vector<char> joined(h, 0);
  for (const Segment& s : segments)
  {
    const auto it =
      std::lower_bound(edges.begin(), edges.end(), std::make_pair(key(s[0], s[1]), std::size_t(0)));
    for (auto e = it; e != edges.end() && e->first == key(s[0], s[1]); ++e)
      joined[e->second] = 1;
  }
  for (std::size_t i = 0; i < h; ++i)
    if (!joined[i])
      segments.push_back({ hull[i], hull[(i + 1) % h] });
}

/// Working points back in the user's coordinates. Scaling back is exact
/// unless a point falls among the subnormal numbers, where it would lose bits
/// and could flip triangles: refused instead. Adding the origin back is exact
/// for the input vertices (normalise) and rounds the others once, to the
/// nearest point in the user's coordinates.
class Unscaler
{
public:
  explicit Unscaler(const Frame& frame)
    : frame(frame)
    , normalPowers(std::abs(frame.exponent) <= 1021)
    , up(std::ldexp(1.0, normalPowers ? frame.exponent : 0))
    , down(std::ldexp(1.0, normalPowers ? -frame.exponent : 0))
  {}

  Point operator()(const Point& p) const
  {
    const Point u = scaleBy(p, frame.exponent, up);
    const Point back = scaleBy(u, -frame.exponent, down);
    if (back.x != p.x || back.y != p.y)
      throw Stop{ "the mesh needs points too close to zero for double precision at this "
                  "scale (coordinates below about 1e-290)",
        true, p };
    return frame.addOrigin(u);
  }

private:
  /// Multiplying by a normal power of two rounds exactly as ldexp does,
  /// without a library call per coordinate; other exponents keep ldexp.
  Point scaleBy(const Point& p, int e, double factor) const
  {
    return normalPowers ? Point{ p.x * factor, p.y * factor }
                        : Point{ std::ldexp(p.x, e), std::ldexp(p.y, e) };
  }

  const Frame& frame;
  const bool normalPowers;
  const double up, down;
};

class Mesher
{
public:
  /// translate: whether points far from 0 for their spread are meshed about
  /// an origin near them (exactOrigin); shrinkBound: whether that mesh meets
  /// the size bound less the rounding of adding the origin back.
  Mesher(const Pslg& input, const Options& options, Progress* progress, bool translate,
    bool shrinkBound = false)
    : input(input)
    , options(options)
    , run(progress)
    , translate(translate)
    , shrinkBound(shrinkBound)
  {}
  Result execute();
  /// The warnings collected so far (when a Stop ends the run, they still hold).
  std::vector<std::string> takeWarnings() { return std::move(res.warnings); }
  /// Whether the run stopped because adding the origin back to the mesh's
  /// points turned a triangle over, past the angle bound or an edge past the
  /// maximum edge length: mesh without it.
  bool translationRoundedBadly() const { return roundedBadly; }
  /// Whether the run stopped because adding the origin back stretched an
  /// edge past the size bound by that rounding alone: mesh again with the
  /// bound shrunk by it (shrinkBound).
  bool boundStretchedByTheOrigin() const { return boundStretched; }
  /// What the split crossings added to a mesh that outgrew a cap or memory,
  /// where they are over 10 times the input points ("" otherwise): a
  /// streamline circling a limit cycle crossed itself 8.6 million times (a
  /// review); a grid of k lines each way has k / 4 times.
  std::string grownByCrossings() const
  {
    if (res.stats.crossingsSplit <= 10 * input.points.size())
      return "";
    return "; the input segments cross each other: splitting them added " +
      std::to_string(res.stats.crossingsSplit) + " points so far to the input's " +
      std::to_string(input.points.size()) + " (e.g. " + firstCrossing +
      "), each a point of the mesh; lines that cross many others, or themselves over and over "
      "(a streamline circling a limit cycle), cross as often as the square of their length";
  }

private:
  void meshRounds(Work& w);
  void nameThePointPassed(Stop& stop, const Work& w) const;
  double originRounding() const;
  double boundBeforeTheOrigin() const;
  Domain chooseDomain(const Work& w, Array<int>& hull);
  void buildOutput(const Work& w, const PlanarGraph& g, Completion& c, Carving& carve,
    const Overlay& overlay, Array<Edge>& edges, Domain domain);
  Array<int> keepDomainTriangles(
    const PlanarGraph& g, Completion& c, Carving& carve, const Unscaler& unscale);
  void mapInputVertices(
    const Work& w, const Overlay& overlay, const Array<int>& newIndex, Domain domain);
  void checkOriginRounding();
  void keepEdgesForInspection(const Work& w, const PlanarGraph& g, Array<Edge>& edges,
    const Array<int>& newIndex, const Unscaler& unscale);
  OverlayOptions overlayOptionsFor(
    const Work& w, Domain domain, const Array<Segment>& segments, const Array<int>& hull);
  void splitRoundCrossings(Work& w, const Walk& walk);
  bool meshAgainAfterCarving(const Work& w, const PlanarGraph& g, const Completion& c,
    const Carving& carve, const Overlay& overlay, const OverlayOptions& oo, Domain domain);
  void warnAboutWalk(const Work& w, const Walk& walk, const Array<Segment>& segments,
    const Overlay& overlay, Domain domain);
  void warnAboutHoles(const Work& w, const Carving& carve, Domain domain);
  void warnAboutRegionSeeds(const Carving& carve);
  template <typename Unscale>
  void warnAboutDroppedSegments(const Work& w, const PlanarGraph& g, const Array<Segment>& dropped,
    Domain domain, const Unscale& unscale);
  Array<double> regionMaxEdges(const Carving& carve, double maxEdge) const;
  std::string longEdgesWarning(const LongEdges& split) const;
  void assignRegionAttributes(const Carving& carve);

  const Pslg& input;
  const Options& options;
  RunContext run;
  Result res;
  CleanPslg clean;
  const bool translate;
  const bool shrinkBound;
  bool roundedBadly = false;
  bool boundStretched = false;
  Frame frame;
  const int& exponent = frame.exponent;
  std::string firstCrossing;       ///< the first crossing split, for the warning
  std::size_t crossingsJoined = 0; ///< crossing points joined within the merge tolerance
  SeedsAcross seedsAcrossJoins;    ///< seeds that segments those joins bent crossed
  /// The auto domain found cycles of segments that enclose no area: hull.
  bool enclosesNothing = false;
  /// The pieces of the segments, split where they pass input points or
  /// overlap, form a cycle that the segments alone do not: enclosed.
  bool piecesEnclose = false;
  Array<ClosePair> closePairs; ///< the round's input points a hair apart
  /// No region the auto domain would enclose has an input point on its
  /// boundary and is more than a speck across (inputPointOnACycle), as where
  /// segments meant to meet at one point cross apart: hull.
  bool enclosesOnlyCrossings = false;
  int crossingRounds = 0;            ///< rounds that split crossings so far
  bool inputPointsOnSegments = true; ///< the last such round's walk met some
  /// The merge tolerance in the scaled coordinates of the rounds.
  double scaledTolerance() const { return std::ldexp(options.mergeTolerance, -exponent); }
  /// How near a segment a dangling end is a near miss (scaled): 1e-6 of the
  /// input's extent, or, where every input coordinate is a float, float
  /// rounding at the end's coordinates (2^-23 of the largest: a review,
  /// isolines at 1e6 end 0.0625 short), if that is more. Not for doubles: at
  /// 5e6 it would call gaps of a metre in map data rounding (a review).
  NearMissSearch nearMissSearch(const Work& w) const
  {
    const Bounds b = boundsOf(input.points);
    const auto isFloat = [](double x) {
      return std::fabs(x) <= std::numeric_limits<float>::max() && double(float(x)) == x;
    };
    // Whole numbers are floats too: then the data are integers (map metres,
    // CAD units), whose gaps of 1 are features (a review).
    const bool floats = std::all_of(input.points.begin(), input.points.end(),
                          [&](const Point& p) { return isFloat(p.x) && isFloat(p.y); }) &&
      std::any_of(input.points.begin(), input.points.end(),
        [](const Point& p) { return p.x != std::floor(p.x) || p.y != std::floor(p.y); });
    return { w.segments.size(),
      std::ldexp(kNearMissExtent * std::max(b.width(), b.height()), -exponent),
      floats ? 0x1p-23 : 0.0,
      { std::ldexp(frame.origin.x, -exponent), std::ldexp(frame.origin.y, -exponent) } };
  }
  /// The enclosed regions reached beyond the segments on cycles (closed by a
  /// segment ending on another, which only the walk splits): the size bound
  /// then applies within all the segments.
  bool sizeEverywhere = false;
  /// The regions with a maximum triangle area, once known (after a first
  /// round): their bound over the bounds of each of their triangles.
  Array<SizeBox> regionBoxes;
  bool regionSizesKnown = false;
  /// The maximum edge length applies only where a first round, without it,
  /// kept triangles (with regionBoxes): most of the bound's refinement would
  /// otherwise fall outside the domain (worthFindingTheDomainFirst).
  bool boundWhereKept = false;
  int regionRounds = 0; ///< rounds meshed again for regions found in another place
  /// Options::keepVertexSegments: per point of the planar graph, the input
  /// segment the walks found it on, else -1.
  Array<int> graphSegment;
  void findGraphSegments(const Walk& walk, const PlanarGraph& g, const Work& w);
  /// The walks' pieces that no crossing splits, (v0, v1, segment): a graph
  /// edge between two overlay vertices is one of them.
  Array<std::array<int, 3>> plainPieces;
};

template <typename Unscale>
void Mesher::warnAboutDroppedSegments(const Work& w, const PlanarGraph& g,
  const Array<Segment>& dropped, Domain domain, const Unscale& unscale)
{
  // Segments between enclosed regions (a river between two lakes) or in a
  // hole: their ends may be in the mesh while they are not (a review).
  if (dropped.empty())
    return;
  // Splitting long edges appended points past the stitch vertices (a review:
  // with a size bound, a segment in a hole went unreported).
  const std::size_t firstStitch = g.firstStitch;
  // The plain pieces by their ends, smaller first, found by binary search.
  std::vector<std::array<int, 3>> byEnds(plainPieces.begin(), plainPieces.end());
  for (auto& [v0, v1, s] : byEnds)
    if (v0 > v1)
      std::swap(v0, v1);
  std::sort(byEnds.begin(), byEnds.end());
  auto segmentOf = [&](const Segment& e) {
    for (int v : e)
      if (static_cast<std::size_t>(v) >= firstStitch &&
        static_cast<std::size_t>(v) - firstStitch < g.stitchSegment.size())
        return g.stitchSegment[v - firstStitch];
    const std::array<int, 3> key{ std::min(e[0], e[1]), std::max(e[0], e[1]), -1 };
    const auto it = std::lower_bound(byEnds.begin(), byEnds.end(), key);
    return it != byEnds.end() && (*it)[0] == key[0] && (*it)[1] == key[1] ? (*it)[2] : -1;
  };
  std::vector<int> inputs; // input segments, as the user numbers them
  int example = -1;
  for (const Segment& e : dropped)
  {
    const int s = segmentOf(e);
    if (s < 0 || s >= static_cast<int>(w.segments.size())) // a hull edge: no input
      continue;
    inputs.push_back(w.segmentOrigin[s]);
    if (example < 0)
      example = static_cast<int>(&e - dropped.data());
  }
  std::sort(inputs.begin(), inputs.end());
  inputs.erase(std::unique(inputs.begin(), inputs.end()), inputs.end());
  if (example < 0)
    return;
  // Named in the input segment's direction (a review: "segment 0 from (10, 0)
  // to (0, 0)" beside "cell 0 from point 0 to point 1"): pieces come either way.
  Segment e = dropped[example];
  const int origin = w.segmentOrigin[segmentOf(e)];
  const Point& a = input.points[input.segments[origin][0]];
  const Point& b = input.points[input.segments[origin][1]];
  const Point &p = g.points[e[0]], &q = g.points[e[1]];
  if ((q.x - p.x) * (b.x - a.x) + (q.y - p.y) * (b.y - a.y) < 0)
    std::swap(e[0], e[1]);
  res.warnings.push_back(std::to_string(inputs.size()) +
    " input segment(s) lie outside the meshed domain (outside every enclosed region or in a "
    "hole), wholly or in part, and are not in the mesh there, e.g. input segment " +
    std::to_string(origin) + " from " + formatPoint(unscale(g.points[e[0]]), options.pointFormat) +
    " to " + formatPoint(unscale(g.points[e[1]]), options.pointFormat) +
    (domain == Domain::Enclosed ? "; the hull or box domain keeps those outside every region"
                                : ""));
}

void Mesher::findGraphSegments(const Walk& walk, const PlanarGraph& g, const Work& w)
{
  // Walked segments past the working ones are the hull's edges: no input segment.
  auto inputSegment = [&w](int s) {
    return s < static_cast<int>(w.segmentOrigin.size()) ? w.segmentOrigin[s] : -1;
  };
  graphSegment.assign(g.points.size(), -1);
  for (const Piece& p : walk.pieces)
    if (!p.duplicate)
      for (int v : { p.v0, p.v1 })
        if (graphSegment[v] < 0)
          graphSegment[v] = inputSegment(p.segment);
  for (std::size_t k = 0; k < g.stitchSegment.size(); ++k)
    graphSegment[g.firstStitch + k] = inputSegment(g.stitchSegment[k]);
}

Result Mesher::execute()
{
  const auto t0 = Clock::now();
  Statistics& st = res.stats;
  st.inputPoints = input.points.size();
  st.inputSegments = input.segments.size();
  st.theta1Deg = options.minAngleDeg;
  if (!(options.minAngleDeg >= kMinAngleDegLowest && options.minAngleDeg <= kMinAngleDegHighest))
    throw Stop{ "the overlay minimum angle must be between 1 and 35 degrees, not " +
      formatNumber(options.minAngleDeg) };
  if (!(options.maxEdgeLength >= 0.0) || !std::isfinite(options.maxEdgeLength))
    throw Stop{ "the maximum edge length must be finite and at least 0" };
  // (A review: Domain(7) meshed, Domain(-1) dropped every point, both "ok".)
  if (options.domain < Domain::Auto || options.domain > Domain::Box)
    throw Stop{ "the domain must be Auto, Enclosed, Hull or Box, not " +
      std::to_string(static_cast<int>(options.domain)) };
  if (!(options.remeshAboveDeg >= 0.0 && options.remeshAboveDeg <= 180.0))
    throw Stop{ "the angle above which to mesh again must be between 0 (the bound) and 180 "
                "degrees, not " +
      formatNumber(options.remeshAboveDeg) };
  st.gamma = gammaForMinAngle(options.minAngleDeg);
  st.predictedMaxAngleDeg = predictedMaxAngleDeg(options.minAngleDeg);
  st.gapRatioOverlay = options.gapRatioOverlay;
  if (options.minAngleDeg > 30.0)
    res.warnings.push_back(beyondGuaranteeWarning(options.minAngleDeg));

  if (!(options.mergeTolerance >= 0.0) || !std::isfinite(options.mergeTolerance))
    throw Stop{ "the merge tolerance must be finite and at least 0" };
  run.phase("clean", 0.0, 0.02);
  if (std::string e =
        cleanPslg(input, clean, st, res.warnings, options.mergeTolerance, options.pointFormat);
      !e.empty())
    throw Stop{ e };
  Work w; // from here on only clean.pointOf is read
  w.points = std::move(clean.points);
  w.isCrossingPoint.assign(w.points.size(), 0);
  w.segments = std::move(clean.segments);
  w.segmentOrigin = std::move(clean.segmentOrigin);
  w.holes = input.holes;
  for (const RegionAttribute& region : input.regions)
    w.regionSeeds.push_back(region.seed);
  if (std::string e = normalise(w, input, clean.pointOf, options.pointFormat, translate, frame);
      !e.empty())
    throw Stop{ e };
  for (const Segment& s : w.segments)
    w.piece.push_back({ w.points[s[0]], w.points[s[1]] });
  st.secondsClean = since(t0);
  if (w.points.empty())
  {
    res.warnings.push_back("the input has no points: the mesh is empty");
    res.ok = true;
    return std::move(res);
  }
  try
  {
    meshRounds(w);
  }
  catch (Stop& stop)
  {
    const bool hullEdge = std::any_of(stop.segments.begin(), stop.segments.end(),
      [&w](int s) { return s >= static_cast<int>(w.segments.size()); });
    nameThePointPassed(stop, w);
    // Name the segments at fault as the user numbers them.
    std::string names;
    for (int s : stop.segments)
      if (s >= 0)
        names += (names.empty() ? "" : " and ") + segmentName(w, s);
    if (!names.empty())
      stop.reason += " (" + names + ")";
    if (stop.located)
      stop.reason += " near " + formatPoint(frame.toUser(stop.at), options.pointFormat);
    stop.reason += stop.tail;
    // Borders that two polygons share, digitised twice, differ by such gaps;
    // segments meant to meet at one point cross at points rounded apart.
    const std::string tolerance = std::string(options.mergeTolerance > 0 ? "larger " : "") +
      "merge tolerance (osm-mesh --merge-tolerance, the filter's MergeTolerance)";
    // Crossings split in an earlier round are points of the overlay too (a
    // review: nine segments nearly through one point were said to have input
    // points too close, the nearest 1.06 away; their crossings were).
    const std::string inputPoints = kPointsTooCloseSubject;
    const std::size_t at = stop.reason.find(inputPoints);
    const bool crossings = stop.remedy == Stop::Remedy::MergePoints && at != std::string::npos &&
      std::find(w.isCrossingPoint.begin(), w.isCrossingPoint.end(), 1) != w.isCrossingPoint.end();
    if (crossings)
      stop.reason.replace(
        at, inputPoints.size(), "input points, or points where input segments cross, are closer");
    if (stop.remedy == Stop::Remedy::MergePoints && stop.located)
      stop.reason += nearestPointsNote(w, stop.at, input, clean.pointOf, options.pointFormat);
    if (stop.remedy == Stop::Remedy::MergePoints)
      stop.reason += std::string("; if ") + (crossings ? "points or crossings" : "input points") +
        " there are meant to be one, a " + tolerance + " joins them";
    else if (const std::string shared = stop.remedy == Stop::Remedy::JoinSegments
               ? sharedEndNote(w, stop.segments[0], stop.segments[1], input, clean.pointOf, frame,
                   std::max(options.mergeTolerance, toleranceSuggested(boundsOf(input.points))),
                   options.pointFormat)
               : "";
             !shared.empty())
      stop.reason += shared;
    else if (stop.remedy == Stop::Remedy::JoinSegments)
      stop.reason += "; if segments there are meant to meet at one point, a " + tolerance +
        " joins their crossings and bends segments onto the points near them" +
        toleranceToTry(boundsOf(input.points), options.mergeTolerance);
    else if (stop.remedy == Stop::Remedy::BendOntoPoint)
      stop.reason += "; if the point is meant to lie on the segment, a " + tolerance +
        " bends the segment onto it" +
        toleranceToTry(boundsOf(input.points), options.mergeTolerance);
    // A review: of one segment with points within rounding of it, 29 in 600
    // were refused at a hull edge, 13 of them also with the tolerance; the
    // box domain meshed 1,199 in 1,200.
    if (hullEdge)
      stop.reason += "; the hull domain adds the convex hull's edges, the box domain (osm-mesh "
                     "--domain box, the filter's Domain) none";
    throw;
  }
  st.secondsTotal = since(t0);
  res.ok = true;
  return std::move(res);
}

/// A stop at a point of the round that a segment passes within rounding of
/// (Stop::atPoint): where it is an input point, not a crossing split in an
/// earlier round (segments are what come too close there), says so, naming
/// the point as the user numbers it.
void Mesher::nameThePointPassed(Stop& stop, const Work& w) const
{
  if (!stop.atPoint || stop.segments[0] < 0)
    return;
  const std::size_t at = static_cast<std::size_t>(
    std::find(w.points.begin(), w.points.end(), stop.at) - w.points.begin());
  if (at == w.points.size() || w.isCrossingPoint[at])
    return;
  const int user = firstInputPoint(clean.pointOf, static_cast<int>(at));
  if (user == static_cast<int>(clean.pointOf.size()))
    return;
  stop.reason = segmentName(w, stop.segments[0]) + " passes input point " + std::to_string(user) +
    " at " + formatPoint(frame.toUser(stop.at), options.pointFormat) +
    " closer than double precision can separate: within rounding of it, neither through it nor "
    "clear of it";
  stop.segments = { -1, -1 };
  stop.located = false;
  stop.remedy = Stop::Remedy::BendOntoPoint;
}

/// The sum of value[c] over the largest of boxes (by area) and the boxes not
/// within it: those within it may lie inside what it bounds.
double sumBesideLargest(const Array<Bounds>& boxes, const Array<double>& value)
{
  const auto extent = [](const Bounds& b) { return b.width() * b.height(); };
  std::size_t largest = 0;
  for (std::size_t c = 1; c < boxes.size(); ++c)
    if (extent(boxes[c]) > extent(boxes[largest]))
      largest = c;
  double sum = 0;
  for (std::size_t c = 0; c < boxes.size(); ++c)
    if (c == largest || !within(boxes[c], boxes[largest]))
      sum += value[c];
  return sum;
}

/// A lower bound of the domain's area where one is known cheaply, else -1:
/// with no hole seeds, the hull's area, or where each group of cycles is one
/// simple cycle, the area of the one with the largest bounds plus those of
/// the cycles outside those bounds (cycles within them may lie inside it).
/// cycles: those of segments (for the enclosed domain).
double domainAreaEstimate(const Work& w, const Array<Segment>& segments,
  const CycleComponents& cycles, const Array<int>& hull, Domain domain)
{
  if (!w.holes.empty())
    return -1.0;
  double area = 0;
  if (domain == Domain::Hull)
  {
    for (std::size_t i = 0; i < hull.size(); ++i)
    {
      const Point &a = w.points[hull[i]], &b = w.points[hull[(i + 1) % hull.size()]];
      area += 0.5 * (a.x * b.y - b.x * a.y);
    }
    return area;
  }
  const Array<double> areas = simpleCycleAreas(w.points, segments, cycles);
  if (areas.empty() || std::any_of(areas.begin(), areas.end(), [](double a) { return a < 0; }))
    return -1.0;
  return sumBesideLargest(cycleBounds(w.points, segments, cycles), areas);
}

/// Whether a first round without the maximum edge length, to find where the
/// domain lies, saves more than it costs: the bound's refinement outside the
/// domain against the quality overlay (about 5 points per input point).
/// domainArea: domainAreaEstimate; where it is unknown, half of the bounds
/// are taken to lie outside (on 8 of the 17 real inputs about half or more
/// do). Taking the first round where it was not needed costs a round without
/// the bound; leaving it out where it was costs up to the whole bound's
/// refinement outside the domain, so the estimate errs towards the former.
bool worthFindingTheDomainFirst(
  const OverlayOptions& oo, std::size_t inputPoints, double domainArea)
{
  if (!(oo.maxEdgeLength > 0))
    return false;
  // The area where the bound applies, boxes within the largest counted once.
  double area = oo.sizeWithin.width() * oo.sizeWithin.height();
  if (oo.sizeInBoxesOnly)
  {
    Array<Bounds> boxes;
    Array<double> areas;
    for (const SizeBox& s : oo.sizeBoxes)
    {
      boxes.push_back(s.box);
      areas.push_back(s.box.width() * s.box.height());
    }
    area = boxes.empty() ? 0.0 : sumBesideLargest(boxes, areas);
  }
  if (!(area > 0))
    return false;
  const double outside = domainArea < 0 ? 0.5 : std::max(0.0, 1.0 - domainArea / area);
  const double points = area / (0.8660254037844386 * oo.maxEdgeLength * oo.maxEdgeLength);
  return outside * points > 8.0 * double(inputPoints);
}

/// Only the domain's triangles are output, and the domain lies within the
/// bounds of the segments (Enclosed) or of the points (Hull): the overlay
/// need not refine the box around them, which on small inputs is most of its
/// triangles.
/// sizeOnCycles: apply the size bound only within the segments on cycles,
/// each group of them joined by cycles within its own bounds (else within all
/// of the segments, as quality refinement). cycles: those of segments, with a
/// maximum edge length in the enclosed domain.
void limitRefinement(OverlayOptions& oo, Domain domain, const Work& w,
  const Array<Segment>& segments, const CycleComponents& cycles, bool sizeOnCycles)
{
  if (domain == Domain::Box || (domain == Domain::Enclosed && segments.empty()))
    return;
  oo.limitRefinement = true;
  if (domain == Domain::Hull)
  {
    oo.refineWithin = oo.sizeWithin = boundsOf(w.points);
    return;
  }
  Array<Point> ends;
  ends.reserve(2 * segments.size());
  for (const Segment& s : segments)
    ends.insert(ends.end(), { w.points[s[0]], w.points[s[1]] });
  oo.refineWithin = oo.sizeWithin = boundsOf(ends);
  if (!sizeOnCycles || oo.maxEdgeLength == 0)
    return;
  // The enclosed regions lie within the segments on cycles: segments hanging
  // off them (a stray segment far away) or joining them (a path from an
  // island to the coast), which carving removes, need a quality overlay
  // around them for stitching, but not the size bound. Nor does the space
  // between separate cycles (islands): each group of cycles gets its box.
  // No cycle yet (segments that cross enclose regions once split): all of them.
  if (cycles.count == 0)
    return;
  const Array<Bounds> boxes = cycleBounds(w.points, segments, cycles);
  if (boxes.size() == 1)
  {
    oo.sizeWithin = boxes.front();
    return;
  }
  oo.sizeInBoxesOnly = true;
  for (const Bounds& b : boxes)
    oo.sizeBoxes.push_back({ b, oo.maxEdgeLength });
}

/// Whether every kept triangle (regionId >= 0) lies where the overlay applied
/// the size bound: within oo.sizeWithin, or within one of the size boxes.
bool keptWithinSizeBound(const Array<Point>& points, const Array<Triangle>& triangles,
  const Array<int>& regionId, const OverlayOptions& oo)
{
  const SizeBoxes boxes(oo.sizeInBoxesOnly ? oo.sizeBoxes : Array<SizeBox>{});
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    if (regionId[t] < 0)
      continue;
    Bounds b = emptyBounds();
    for (int v : triangles[t])
      extend(b, points[v]);
    if (oo.sizeInBoxesOnly ? !boxes.covers(b) : !within(b, oo.sizeWithin))
      return false;
  }
  return true;
}

/// Where each region whose edge bound is tighter than the overlay's own
/// overlayBound (0: none) lies, with that bound: the bounds of each of its triangles
/// in this round. Together they cover the region and little more (a
/// region's own bounds would take in every region nested within it), and an
/// overlay triangle that reaches into the region meets one of them.
Array<SizeBox> regionSizeBoxes(const Array<Point>& points, const Array<Triangle>& triangles,
  const Array<int>& regionId, const Array<double>& regionMaxEdge, double overlayBound)
{
  Array<char> tighter(regionMaxEdge.size(), 0);
  bool any = false;
  for (std::size_t r = 0; r < regionMaxEdge.size(); ++r)
  {
    tighter[r] = regionMaxEdge[r] > 0 && (overlayBound == 0 || regionMaxEdge[r] < overlayBound);
    any = any || tighter[r];
  }
  if (!any)
    return {};
  Array<SizeBox> boxes;
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    const int r = regionId[t];
    if (r >= 0 && tighter[r])
      boxes.push_back({ boundsOf(std::initializer_list<Point>{ points[triangles[t][0]],
                          points[triangles[t][1]], points[triangles[t][2]] }),
        regionMaxEdge[r] });
  }
  return boxes;
}

/// Whether a cycle of segments (a group of them joined by cycles) passes
/// through a point marked in isInput and is more than minSize across: a
/// region the segments enclose has an input point on its boundary and is
/// not a speck (the crossings of segments meant to meet at one point close
/// one, possibly through a road's own vertex there).
bool inputPointOnACycle(const Array<Point>& points, const Array<char>& isInput,
  const Array<Segment>& segments, double minSize)
{
  const CycleComponents cycles = cycleComponents(points.size(), segments);
  const Array<Bounds> boxes = cycleBounds(points, segments, cycles);
  for (std::size_t e = 0; e < segments.size(); ++e)
    if (const int c = cycles.component[e]; c >= 0 &&
        (isInput[segments[e][0]] || isInput[segments[e][1]]) &&
        std::max(boxes[c].width(), boxes[c].height()) > minSize)
      return true;
  return false;
}

/// Whether the walk's pieces of the first `inputs` segments (the rest are
/// the hull's) form a cycle among the overlay's `vertices`: split where they
/// pass input points, and once where they overlap (duplicates left out).
bool walkedPiecesEnclose(const Walk& walk, std::size_t inputs, std::size_t vertices)
{
  Array<Segment> pieces;
  for (const Piece& p : walk.pieces)
    if (!p.duplicate && static_cast<std::size_t>(p.segment) < inputs)
      pieces.push_back({ p.v0, p.v1 });
  return segmentsEncloseRegion(vertices, pieces);
}

/// Per vertex of a round's mesh (n of them): whether it is an input point,
/// not a crossing; vertexOf maps w's points to them.
Array<char> inputVertices(const Work& w, const Array<int>& vertexOf, std::size_t n)
{
  Array<char> isInput(n, 0);
  for (std::size_t i = 0; i < w.points.size(); ++i)
    if (!w.isCrossingPoint[i] && vertexOf[i] >= 0)
      isInput[vertexOf[i]] = 1;
  return isInput;
}

/// Below this size across, a group of cycles is taken for a speck of
/// crossings (inputPointOnACycle): a few merge tolerances, or 2^-26 (about
/// 1.5e-8) of the input's extent, half of double precision's digits.
double speckSize(const Work& w, double scaledTolerance)
{
  const Bounds b = boundsOf(w.points);
  return std::max(4 * scaledTolerance, std::ldexp(std::max(b.width(), b.height()), -26));
}

/// Auto means the enclosed regions if the segments enclose any (decided on
/// the segments as split at their crossings; once meshed, one with an input
/// point on its boundary), else the hull; a hull without area falls back to
/// the box. For the hull domain, hull receives its boundary.
Domain Mesher::chooseDomain(const Work& w, Array<int>& hull)
{
  hull.clear();
  Domain domain = options.domain;
  if (domain == Domain::Auto)
  {
    const bool encloses = !enclosesNothing && !enclosesOnlyCrossings &&
      (piecesEnclose || segmentsEncloseRegion(w.points.size(), w.segments));
    // After a crossing round whose walk found no input point on a segment
    // (which only the walk splits at), the segments here have the cycles of
    // the pieces: judge them now rather than mesh the regions first.
    if (encloses && crossingRounds > 0 && !inputPointsOnSegments)
    {
      Array<char> isInput(w.points.size());
      for (std::size_t i = 0; i < w.points.size(); ++i)
        isInput[i] = !w.isCrossingPoint[i];
      enclosesOnlyCrossings =
        !inputPointOnACycle(w.points, isInput, w.segments, speckSize(w, scaledTolerance()));
    }
    domain = encloses && !enclosesOnlyCrossings ? Domain::Enclosed : Domain::Hull;
  }
  if (domain == Domain::Hull)
  {
    hull = hullBoundary(w.points);
    if (hull.size() < 3)
    {
      hull.clear();
      domain = Domain::Box;
    }
  }
  return domain;
}

/// How much adding the origin back may lengthen an edge: half a unit in the
/// last place of each coordinate, at both ends.
double Mesher::originRounding() const
{
  const double far =
    std::max(std::fabs(frame.origin.x), std::fabs(frame.origin.y)) + std::ldexp(1.0, exponent);
  return 2 * std::numeric_limits<double>::epsilon() * far;
}

/// The size bound the mesh meets before the origin is added back: the
/// user's, or with shrinkBound, less originRounding(), so that the user's
/// coordinates meet it (a review: an edge of 7.0003e-5 against 7e-5 at 1e8).
double Mesher::boundBeforeTheOrigin() const
{
  const double bound = options.maxEdgeLength;
  if (!shrinkBound || !(bound > 0) || (frame.origin.x == 0 && frame.origin.y == 0))
    return bound;
  return originRounding() < bound / 2 ? bound - originRounding() : bound;
}

void Mesher::meshRounds(Work& w)
{
  Statistics& st = res.stats;
  const double sinTheta1 = series::sin(options.minAngleDeg * series::kPi / 180.0);
  // Crossing points are rounded, so splitting may expose new tiny crossings:
  // repeat a few times, then give up with a clear error. Other rounds (the
  // hull instead, the size bound elsewhere) do not count towards that.
  for (int round = 0;; ++round)
  {
    const std::size_t warningsBefore = res.warnings.size();
    if (round > 0)
      run.newRound();
    Array<Segment> segments = w.segments;
    Array<int> hull;
    const Domain domain = chooseDomain(w, hull);
    appendHullEdges(hull, segments);
    auto t = Clock::now();
    const OverlayOptions oo = overlayOptionsFor(w, domain, segments, hull);
    // Region areas, or the bound where triangles are kept, mesh again, mostly
    // finer: this round is the smaller part.
    if (!regionSizesKnown && (boundWhereKept || oo.sizeFromAreas))
      run.shareRound(0.2);
    run.phase("overlay", 0.02, 0.6);
    Overlay overlay = buildOverlay(w.points, oo, run);
    st.secondsOverlay += since(t);

    t = Clock::now();
    run.phase("stitch", 0.6, 0.62);
    // From here on the compact copy serves: the refinement's triangles are
    // freed, and their pages (kept by the Reuse scope) hold the later phases'
    // arrays.
    OverlayEdges ov = compactOverlay(overlay.mesh, run);
    for (Segment& s : segments)
      s = { overlay.inputVertex[s[0]], overlay.inputVertex[s[1]] };
    run.phase("stitch", 0.62, 0.7); // compaction done: the walks
    // Where segments overlap, the piece kept carries the data of the one
    // that comes first in the input; the hull's edges (past the working
    // segments) come last.
    Array<int> firstInInputOrder(segments.size(), std::numeric_limits<int>::max());
    for (std::size_t s = 0; s < w.segmentOrigin.size(); ++s)
      if (w.segmentOrigin[s] >= 0)
        firstInInputOrder[s] = w.segmentOrigin[s];
    Walk walk = walkSegments(
      ov, overlay, segments, sinTheta1, run, nullptr, &firstInInputOrder, nearMissSearch(w));
    st.secondsStitch += since(t);
    if (!walk.segmentCrossings.empty())
    {
      splitRoundCrossings(w, walk);
      continue;
    }
    // A segment ending on another (a T-junction) or overlapping it closes a
    // cycle that only the walk's pieces show (a review: a triangle with one
    // corner on its base was meshed as the hull): the enclosed domain then.
    if (options.domain == Domain::Auto && domain == Domain::Hull && !enclosesNothing &&
      !enclosesOnlyCrossings && !piecesEnclose &&
      (walk.splitsAtInputVertices > 0 || !walk.overlaps.empty()) &&
      walkedPiecesEnclose(walk, w.segments.size(), overlay.mesh.points.size()))
    {
      res.warnings.resize(warningsBefore);
      piecesEnclose = true;
      continue;
    }
    st.segmentsSplitAtVertices = walk.splitsAtInputVertices + walk.overlaps.size();
    warnAboutWalk(w, walk, segments, overlay, domain);
    NearMissSearch closePoints = nearMissSearch(w);
    closePoints.reach *= kClosePointsExtent / kNearMissExtent;
    closePairs = closePointPairs(w, overlay, ov, closePoints, input, clean.pointOf);
    st.overlayVertices = overlay.mesh.points.size();
    st.overlaySteinerPoints = overlay.steinerPoints + kBoxCorners;
    if (overlay.refinementsSkipped > 0)
      res.warnings.push_back(std::to_string(overlay.refinementsSkipped) +
        " overlay refinement step(s) were skipped because a Steiner point fell on an existing "
        "vertex; the overlay may fall short of the angle " +
        formatNumber(options.minAngleDeg) + " degrees there");
    st.overlayTriangles = ov.tris.size();

    t = Clock::now();
    // The overlay is only output from here on, and stitching builds the
    // graph in its arrays: copy what the output keeps.
    if (options.keepOverlay)
    {
      res.overlay.vertices = overlay.mesh.points;
      res.overlay.triangles = ov.tris;
    }
    Array<Edge> edges;
    run.phase("stitch", 0.7, 0.75); // the walks done: the planar graph
    PlanarGraph g = stitch(std::move(ov), std::move(overlay.mesh.points), overlay.isInput, walk,
      options.keepEdges ? &edges : nullptr, st, run);
    if (options.keepVertexSegments)
      findGraphSegments(walk, g, w);
    // Only a domain that removes triangles can leave a segment out.
    plainPieces.clear();
    if (domain != Domain::Box || !w.holes.empty())
      for (const Piece& p : walk.pieces)
        if (!p.duplicate && p.crossingCount == 0)
          plainPieces.push_back({ p.v0, p.v1, p.segment });
    st.secondsStitch += since(t);
    overlay.mesh = Triangulation();
    walk = Walk();

    t = Clock::now();
    run.phase("complete", 0.75, 0.9);
    Completion c = complete(g, st, run);
    st.secondsComplete = since(t);

    t = Clock::now();
    run.phase("domain", 0.9, 0.95);
    Carving carve = carveDomain(g.points, c.triangles, c.constrainedEdges, domain != Domain::Box,
      w.holes, std::move(g.intactAdjacency), w.regionSeeds, run);
    st.secondsDomain = since(t);
    if (meshAgainAfterCarving(w, g, c, carve, overlay, oo, domain))
    {
      res.warnings.resize(warningsBefore); // this round's warnings come again
      continue;
    }
    // A region's maximum area is a bound on its edges, which the overlay
    // applies over the region's triangles: found in this round, meshed again.
    const Array<double> regionMaxEdge = regionMaxEdges(carve, oo.maxEdgeLength);
    // Regions bounded more tightly than the overlay is everywhere get boxes.
    const double overlayBound = boundWhereKept ? 0.0 : oo.maxEdgeLength;
    if (!regionSizesKnown)
    {
      regionSizesKnown = true;
      regionBoxes =
        regionSizeBoxes(g.points, c.triangles, carve.regionId, regionMaxEdge, overlayBound);
      if (!regionBoxes.empty())
      {
        res.warnings.resize(warningsBefore);
        continue;
      }
      run.shareRound(1.0); // no finer round follows: this one ends the run
    }
    const std::size_t graphPoints = g.points.size(); // the edges' vertices
    if (std::any_of(regionMaxEdge.begin(), regionMaxEdge.end(), [](double h) { return h > 0; }))
    {
      run.phase("domain", 0.95, 0.96); // carved: long completed edges split
      const LongEdges split = splitLongEdges(g.points, g.origin, c.triangles, carve.regionId,
        c.constrainedEdges, regionMaxEdge, st.predictedMaxAngleDeg, run);
      st.longEdgesSplit = split.split;
      // A region seed on a segment goes to the same side in every round
      // (carveDomain's rule), but one within rounding of a segment may be
      // judged on it in one round and beside it in another, so that a region
      // not refined takes the area: refine where this round's limited
      // regions lie too, mesh again.
      if (split.remaining > 0 && !regionBoxes.empty() && regionRounds < 2)
      {
        ++regionRounds;
        const Array<SizeBox> more =
          regionSizeBoxes(g.points, c.triangles, carve.regionId, regionMaxEdge, overlayBound);
        regionBoxes.insert(regionBoxes.end(), more.begin(), more.end());
        res.warnings.resize(warningsBefore);
        continue;
      }
      if (split.remaining > 0)
        res.warnings.push_back(longEdgesWarning(split));
    }
    warnAboutRegionSeeds(carve);
    warnAboutHoles(w, carve, domain);
    run.phase("domain", 0.96, 1.0); // the output arrays
    res.domain = domain;
    buildOutput(w, g, c, carve, overlay, edges, domain);
    if (options.keepEdges) // points splitting long edges are on none of them
      res.edgeVertices.resize(graphPoints);
    return;
  }
}

/// Whether a carved round is to be meshed again another way: the auto
/// domain's cycles enclose nothing, or only crossings and specks (the hull
/// then), or a region reaches beyond the size bound (the bound everywhere).
bool Mesher::meshAgainAfterCarving(const Work& w, const PlanarGraph& g, const Completion& c,
  const Carving& carve, const Overlay& overlay, const OverlayOptions& oo, Domain domain)
{
  const Statistics& st = res.stats;
  // A cycle of segments need not enclose any area: mesh the hull instead
  // (once).
  if (options.domain == Domain::Auto && domain == Domain::Enclosed && carve.enclosedNothing)
  {
    enclosesNothing = true;
    return true;
  }
  // Nor need regions whose boundaries pass through no input point, or
  // specks, be what was meant: the crossings of segments meant to meet at
  // one point close one. Without crossings, as before: every boundary has
  // input points, and specks are the input's own.
  if (options.domain == Domain::Auto && domain == Domain::Enclosed && st.crossingsSplit > 0 &&
    !inputPointOnACycle(g.points, inputVertices(w, overlay.inputVertex, g.points.size()),
      c.constrainedEdges, speckSize(w, scaledTolerance())))
  {
    enclosesOnlyCrossings = true;
    return true;
  }
  // The size bound must cover every kept triangle: where a region closed
  // by a T-junction reaches beyond it, mesh again with the bound everywhere.
  if (oo.maxEdgeLength > 0 && domain == Domain::Enclosed && !sizeEverywhere && !boundWhereKept &&
    !keptWithinSizeBound(g.points, c.triangles, carve.regionId, oo))
  {
    sizeEverywhere = true;
    return true;
  }
  return false;
}

/// The overlay's options for a round: Γ, the size bound and where it
/// applies (the region boxes; only where a first round kept triangles).
OverlayOptions Mesher::overlayOptionsFor(
  const Work& w, Domain domain, const Array<Segment>& segments, const Array<int>& hull)
{
  const Statistics& st = res.stats;
  OverlayOptions oo;
  oo.gamma = st.gamma;
  oo.gapRatio = options.gapRatioOverlay;
  oo.maxEdgeLength = std::ldexp(boundBeforeTheOrigin(), -exponent);
  // A bound that scaling rounds to 0 would read as none: keep it tiny, and
  // the overlay refuses it as too small to mesh.
  if (options.maxEdgeLength > 0 && oo.maxEdgeLength == 0)
    oo.maxEdgeLength = std::numeric_limits<double>::denorm_min();
  oo.maxSteinerPoints = options.maxSteinerPoints;
  oo.sizeBoxes = regionBoxes;
  oo.sizeFromAreas = options.regionAreas &&
    std::any_of(input.regions.begin(), input.regions.end(),
      [](const RegionAttribute& r) { return r.maxArea > 0; });
  // Both the size boxes and the domain's estimate read the cycles.
  const CycleComponents cycles = domain == Domain::Enclosed && oo.maxEdgeLength > 0
    ? cycleComponents(w.points.size(), segments)
    : CycleComponents{};
  limitRefinement(oo, domain, w, segments, cycles, !sizeEverywhere);
  if (!regionSizesKnown)
    boundWhereKept = domain != Domain::Box && !sizeEverywhere && oo.maxEdgeLength > 0 &&
      worthFindingTheDomainFirst(
        oo, w.points.size(), domainAreaEstimate(w, segments, cycles, hull, domain));
  // The bound only where the first round kept triangles (none in it).
  if (boundWhereKept)
  {
    oo.sizeInBoxesOnly = true;
    oo.sizeBoxes = regionBoxes;
  }
  return oo;
}

/// Splits the crossings of segments a round's walk found, at their rounded
/// intersection points, for the next round; an error where crossings are not
/// to be resolved, or cross again after 5 rounds.
void Mesher::splitRoundCrossings(Work& w, const Walk& walk)
{
  Statistics& st = res.stats;
  if (!options.resolveCrossings)
    throw Stop{ crossingError(w, walk.segmentCrossings, frame, options.pointFormat) +
      "; enable resolving intersections to split them (the filter's ResolveIntersections; "
      "osm-mesh without --no-resolve)" };
  // Each round splits at rounded points, which may cross again.
  if (++crossingRounds >= 5)
    throw Stop{ "could not resolve all crossings after 5 rounds of splitting them at their "
                "rounded intersection points, which crossed again: " +
        crossingError(w, walk.segmentCrossings, frame, options.pointFormat) +
        "; the segments there come closer than double precision separates",
      false, {}, { -1, -1 }, Stop::Remedy::JoinSegments };
  if (st.crossingsSplit == 0)
    firstCrossing = describeCrossing(w, walk.segmentCrossings.front(), frame, options.pointFormat);
  // Splitting many crossings takes a while: abort is polled around it.
  run.report(1.0);
  splitCrossings(w, walk.segmentCrossings, st);
  run.report(1.0);
  inputPointsOnSegments = walk.splitsAtInputVertices > 0;
  SeedsAcross seeds;
  const std::size_t joined = mergeEqualPoints(w, scaledTolerance(), seeds);
  if (options.mergeTolerance > 0)
    crossingsJoined += joined;
  if (seeds.count > 0 && seedsAcrossJoins.count == 0)
    seedsAcrossJoins = seeds;
}

/// The round's warnings once its segments are walked: why the domain
/// changed, the crossings split, seeds a join moved across a segment,
/// overlapping segments, and ends that just miss a segment.
void Mesher::warnAboutWalk(const Work& w, const Walk& walk, const Array<Segment>& segments,
  const Overlay& overlay, Domain domain)
{
  const Statistics& st = res.stats;
  // Say why the domain changed, once.
  if (domain == Domain::Box && options.domain != Domain::Box)
    res.warnings.push_back(w.points.size() == 1
        ? "the input is one point" +
          std::string(st.duplicatePointsMerged > 0 ? " once merged" : "") +
          ", whose convex hull has no area: meshing the padded box around it instead"
        : "the input points are collinear or within rounding of it, or some lie within rounding "
          "of a corner of their convex hull or of a hull edge from both sides, so that hull has "
          "no area at double precision somewhere (its edges would pass within rounding of input "
          "points): meshing the padded bounding box instead");
  if (enclosesNothing)
    res.warnings.push_back("the segments form cycles, but they enclose no area (collinear "
                           "segments over each other): the auto domain meshes the convex hull");
  if (enclosesOnlyCrossings)
    res.warnings.push_back("the regions the segments enclose have no input point on their "
                           "boundaries, or are specks under " +
      roughNumber(std::ldexp(speckSize(w, scaledTolerance()), exponent)) +
      " across (as where segments meant to meet at one point cross apart, which a merge "
      "tolerance joins): the auto domain meshes the convex hull; the enclosed domain meshes "
      "those regions alone");
  if (st.crossingsSplit > 0)
    res.warnings.push_back("split " + std::to_string(st.crossingsSplit) +
      " crossing(s) of input segments at their intersection points, e.g. " + firstCrossing +
      (crossingsJoined > 0 ? "; " + std::to_string(crossingsJoined) +
            " of those points joined another within the merge tolerance"
                           : ""));
  if (seedsAcrossJoins.count > 0)
    res.warnings.push_back(std::to_string(seedsAcrossJoins.count) +
      " hole or region seed(s) now lie on the other side of a segment that bent where its "
      "crossing joined another point within the merge tolerance, e.g. " +
      seedsAcrossJoins.example);
  // Overlaps of input segments (a hull edge along a segment is no news).
  const auto inputs = static_cast<int>(w.segments.size());
  const auto overlap = std::find_if(walk.overlaps.begin(), walk.overlaps.end(),
    [&](const std::array<int, 4>& o) { return o[1] < inputs; });
  if (overlap != walk.overlaps.end())
  {
    const auto count = std::count_if(walk.overlaps.begin(), walk.overlaps.end(),
      [&](const std::array<int, 4>& o) { return o[1] < inputs; });
    const auto& [a, b, u, v] = *overlap;
    const auto at = [&](int vertex) {
      const Point& q = overlay.mesh.points[vertex];
      return formatPoint(frame.toUser(q), options.pointFormat);
    };
    res.warnings.push_back(std::to_string(count) +
      " piece(s) of input segments lie along another input segment and are meshed once, e.g. " +
      segmentName(w, a) + " and " + segmentName(w, b) + " overlap from " + at(u) + " to " + at(v));
  }
  if (std::string nearMiss =
        nearMissWarning(w, walk, segments, input, clean.pointOf, frame, options.pointFormat);
      !nearMiss.empty())
    res.warnings.push_back(std::move(nearMiss));
}

/// The warnings of a carved domain: hole seeds that removed nothing, or
/// everything, or lie on segments or the boundary; an empty enclosed domain;
/// an outline the auto domain found open.
void Mesher::warnAboutHoles(const Work& w, const Carving& carve, Domain domain)
{
  const Statistics& st = res.stats;
  if (!carve.unusedHoles.empty())
    res.warnings.push_back(std::to_string(carve.unusedHoles.size()) +
      " hole point(s) lie outside the meshed domain or in a region already removed, e.g. "
      "hole " +
      std::to_string(carve.unusedHoles.front()) + " at " +
      formatPoint(input.holes[carve.unusedHoles.front()], options.pointFormat));
  // Say why the mesh is empty when the holes took all of it (a seed in the
  // wrong region, or a merge tolerance that collapsed the input).
  if (carve.regions == 0 && w.holes.size() > carve.unusedHoles.size())
  {
    std::size_t used = 0;
    while (used < carve.unusedHoles.size() && carve.unusedHoles[used] == static_cast<int>(used))
      ++used;
    res.warnings.push_back("the hole point(s) removed every region, e.g. hole " +
      std::to_string(used) + " at " + formatPoint(input.holes[used], options.pointFormat) +
      ": the mesh is empty");
  }
  else if (carve.regions == 0 && domain == Domain::Enclosed)
    res.warnings.push_back(
      "the segments enclose no region (no closed loop of them around an area): the enclosed "
      "domain is empty; the hull or box domain meshes such input");
  if (!carve.seedsOnSegments.empty())
    res.warnings.push_back(std::to_string(carve.seedsOnSegments.size()) +
      " hole point(s) lie on a segment or at its end, e.g. hole " +
      std::to_string(carve.seedsOnSegments.front()) + " at " +
      formatPoint(input.holes[carve.seedsOnSegments.front()], options.pointFormat) +
      ": the region the direction +x from it enters (above, where a segment runs along +x) "
      "was removed; move the point into the hole to choose");
  // (A review: a seed on the outer boundary emptied the mesh, and only a
  // seed on a segment inside was said to be on one.)
  if (!carve.seedsOnBoundary.empty())
    res.warnings.push_back(std::to_string(carve.seedsOnBoundary.size()) +
      " hole point(s) lie on the domain's boundary, e.g. hole " +
      std::to_string(carve.seedsOnBoundary.front()) + " at " +
      formatPoint(input.holes[carve.seedsOnBoundary.front()], options.pointFormat) +
      ": the region inside it was removed; move the point out of the domain to keep it");
  if (options.domain == Domain::Auto && domain == Domain::Hull)
    if (std::string open = openOutlineWarning(w, input, clean.pointOf, options.pointFormat);
        !open.empty())
      res.warnings.push_back(std::move(open));
}

std::string Mesher::longEdgesWarning(const LongEdges& split) const
{
  const std::string ratio = generalText(split.worst, 3);
  return std::to_string(split.remaining) +
    " triangle(s) keep an edge longer than the maximum edge length (or their region's bound "
    "for its maximum area), up to " +
    ratio + " times it, e.g. near " + formatPoint(frame.toUser(split.at), options.pointFormat) +
    ": it lies on a segment, or splitting it would make an angle above the bound";
}

/// Per region of carve, the longest edge allowed there (in the core's
/// coordinates; 0: none): maxEdge, or the edge of the equilateral triangle
/// of the region's maximum area if shorter. As for attributes, the last seed
/// in a region gives its area (as Triangle does).
Array<double> Mesher::regionMaxEdges(const Carving& carve, double maxEdge) const
{
  Array<double> bound(carve.regions, maxEdge);
  if (!options.regionAreas)
    return bound;
  Array<double> area(carve.regions, -1.0);
  for (std::size_t k = 0; k < input.regions.size(); ++k)
    if (carve.seedRegion[k] >= 0)
      area[carve.seedRegion[k]] = input.regions[k].maxArea; // the last seed wins
  for (std::size_t r = 0; r < carve.regions; ++r)
  {
    if (!(area[r] > 0))
      continue;
    // sqrt(3)/4 h^2 = area; in the core's coordinates, scaled by 2^-exponent.
    double h = std::ldexp(std::sqrt(4 * area[r] / std::sqrt(3.0)), -exponent);
    // One that underflows stays tiny: the overlay refuses it as too small.
    h = h > 0 ? h : std::numeric_limits<double>::denorm_min();
    bound[r] = bound[r] > 0 ? std::min(bound[r], h) : h;
  }
  return bound;
}

/// Region seeds that give no triangle an attribute, and area limits not
/// applied, are said.
void Mesher::warnAboutRegionSeeds(const Carving& carve)
{
  const Array<RegionAttribute>& regions = input.regions;
  std::size_t outside = 0, overridden = 0, limits = 0;
  int firstOutside = -1, firstOverridden = -1;
  Array<char> claimed; // per region: a later seed gives its attribute
  claimed.assign(carve.regions, char{ 0 });
  // From the last seed back, so that the first seed of each kind is noted last.
  for (std::size_t k = regions.size(); k-- > 0;)
  {
    const int region = carve.seedRegion[k];
    limits += regions[k].maxArea > 0 ? 1 : 0;
    if (region < 0)
    {
      ++outside;
      firstOutside = static_cast<int>(k);
    }
    else if (claimed[region])
    {
      ++overridden;
      firstOverridden = static_cast<int>(k);
    }
    else
      claimed[region] = 1;
  }
  if (outside > 0)
    res.warnings.push_back(std::to_string(outside) +
      " region point(s) lie outside the meshed domain or in a hole, e.g. region " +
      std::to_string(firstOutside) + " at " +
      formatPoint(regions[firstOutside].seed, options.pointFormat) +
      ": their attributes are given to no triangle");
  if (overridden > 0)
    res.warnings.push_back(std::to_string(overridden) +
      " region point(s) share their region with a later one, whose attribute and maximum area "
      "the "
      "region takes "
      "(as Triangle does), e.g. region " +
      std::to_string(firstOverridden) + " at " +
      formatPoint(regions[firstOverridden].seed, options.pointFormat));
  if (!carve.regionSeedsOnSegments.empty())
  {
    const int k = carve.regionSeedsOnSegments.front();
    res.warnings.push_back(std::to_string(carve.regionSeedsOnSegments.size()) +
      " region point(s) lie on a segment or at its end, e.g. region " + std::to_string(k) + " at " +
      formatPoint(regions[k].seed, options.pointFormat) +
      ": the region the direction +x from it enters (above, where a segment runs along +x) "
      "takes its attribute" +
      (options.regionAreas ? " and area" : "") + "; move the point into its region to choose");
  }
  if (limits > 0 && !options.regionAreas)
    res.warnings.push_back(std::to_string(limits) +
      " region(s) set a maximum triangle area, which is not applied: turn on region areas "
      "(osm-mesh --region-areas, the filter's ApplyRegionAreas) to apply them, as Triangle's -a");
}

/// The attribute of each kept triangle from the region seeds (res.regionId
/// already compacted to the kept triangles).
void Mesher::assignRegionAttributes(const Carving& carve)
{
  if (input.regions.empty())
    return;
  Array<double> ofRegion;
  ofRegion.assign(carve.regions, 0.0);
  for (std::size_t r = 0; r < input.regions.size(); ++r)
    if (carve.seedRegion[r] >= 0)
      ofRegion[carve.seedRegion[r]] = input.regions[r].attribute; // the last seed wins
  res.regionAttribute.resize(res.regionId.size());
  for (std::size_t t = 0; t < res.regionId.size(); ++t)
    res.regionAttribute[t] = ofRegion[res.regionId[t]];
}

/// Whether an edge of the mesh is longer than maxEdge by no more than rounding:
/// a relative 2^-36 (the fuzzer: 2.9285714285714306 against 2.928571428571429
/// once an origin was added back), or slack (the rounding of adding it back).
/// Edges a warning says stay longer are far longer.
bool anyRoundedAbove(const TriMesh& mesh, double maxEdge, double slack)
{
  const double bound2 = maxEdge * maxEdge;
  const double rounded2 = std::max(bound2 * (1 + 0x1p-36), (maxEdge + slack) * (maxEdge + slack));
  if (!(maxEdge > 0))
    return false;
  for (const Triangle& t : mesh.triangles)
    for (int k = 0; k < 3; ++k)
      if (const double d2 = dist2(mesh.vertices[t[k]], mesh.vertices[t[(k + 1) % 3]]);
          d2 > bound2 && d2 <= rounded2)
        return true;
  return false;
}

/// Whether a triangle of the mesh is not counter-clockwise (exactly).
bool anyTurnedOver(const TriMesh& mesh)
{
  for (const Triangle& t : mesh.triangles)
    if (!(orient2d(mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]]) > 0))
      return true;
  return false;
}

/// Smallest and largest angle of the mesh in degrees, exactly as angleAt gives
/// them. An atan2 per angle was a tenth of a run: a cosine filter skips the
/// angles that cannot reach either extreme, and only the others get atan2.
/// The filter compares cos|cos| (monotone in the cosine) multiplied out,
/// dot|dot| against bound * |u|^2 |v|^2: no square root or division per angle.
/// Polls run (in the phase's [0.6, 0.85]) for an abort as it goes.
void angleExtremes(const TriMesh& mesh, double& minDeg, double& maxDeg, RunContext& run)
{
  const double deg = 180.0 / series::kPi;
  // Far above the rounding of the filter's products and of the conversions.
  const double slack = 1e-9;
  auto signedSquare = [](double x) { return x * std::fabs(x); };
  minDeg = mesh.triangles.empty() ? 0.0 : 180.0;
  maxDeg = 0.0;
  // Skip an angle whose cos|cos| is strictly between these (none at first).
  double below = -4, above = 4;
  const double n = static_cast<double>(mesh.triangles.size());
  for (const Triangle& t : mesh.triangles)
  {
    run.tickWith([&] { return 0.6 + 0.25 * double(&t - mesh.triangles.data()) / n; }, 1u << 16);
    const Point& p0 = mesh.vertices[t[0]];
    const Point& p1 = mesh.vertices[t[1]];
    const Point& p2 = mesh.vertices[t[2]];
    // Edge i is opposite corner i; the angle at corner i lies between edges
    // i + 1 and i + 2, and their dot product, negated exactly, is the one of
    // the vectors from that corner that angleAt(p[i+1], p[i], p[i+2]) takes.
    const double ex[3] = { p2.x - p1.x, p0.x - p2.x, p1.x - p0.x };
    const double ey[3] = { p2.y - p1.y, p0.y - p2.y, p1.y - p0.y };
    double len2[3];
    bool normal = true;
    for (int i = 0; i < 3; ++i)
    {
      len2[i] = ex[i] * ex[i] + ey[i] * ey[i];
      // Within these norms nothing over- or underflows (NaN fails the tests too).
      normal = normal && len2[i] > 1e-150 && len2[i] < 1e150;
    }
    // Corner i between edges j and k, written out three times (a loop's
    // index arithmetic cost as much as the filter).
    auto corner = [&](int i, int j, int k) {
      const double key = signedSquare(-(ex[j] * ex[k] + ey[j] * ey[k]));
      const double norms = len2[j] * len2[k];
      if (normal && key < below * norms && key > above * norms)
        return;
      const double angle =
        deg * angleAt(mesh.vertices[t[j]], mesh.vertices[t[i]], mesh.vertices[t[k]]);
      minDeg = std::min(minDeg, angle);
      maxDeg = std::max(maxDeg, angle);
      below = signedSquare(series::cos(minDeg / deg) - slack);
      above = signedSquare(series::cos(maxDeg / deg) + slack);
    };
    corner(0, 1, 2);
    corner(1, 2, 0);
    corner(2, 0, 1);
  }
}

/// Says where the output exceeds the largest-angle bound, which holds for
/// points placed exactly: at coordinates far larger than a feature (1e-10
/// apart at 1e3, about a thousand units in the last place), rounding the
/// stitched points moves a sliver's angles by tenths of a degree (a review
/// found 170.12 degrees against 169.95 on a pencil of lines shifted there;
/// 159.19 unshifted). A triangle too large for that is a defect of ours.
std::string angleBoundWarning(const TriMesh& mesh, double boundDeg, const PointFormat& format)
{
  const double deg = 180.0 / series::kPi;
  std::size_t count = 0;
  double worst = 0, shortest = 0, magnitude = 0;
  Point at{};
  for (const Triangle& t : mesh.triangles)
  {
    const Point p[3] = { mesh.vertices[t[0]], mesh.vertices[t[1]], mesh.vertices[t[2]] };
    double largest = 0;
    int corner = 0;
    for (int i = 0; i < 3; ++i)
      if (const double a = deg * angleAt(p[(i + 1) % 3], p[i], p[(i + 2) % 3]); a > largest)
      {
        largest = a;
        corner = i;
      }
    if (!(largest > boundDeg))
      continue;
    ++count;
    if (largest <= worst)
      continue;
    worst = largest;
    at = p[corner];
    shortest = std::numeric_limits<double>::infinity();
    magnitude = 0;
    for (int i = 0; i < 3; ++i)
    {
      const Point &a = p[i], &b = p[(i + 1) % 3];
      shortest = std::min(shortest, std::hypot(b.x - a.x, b.y - a.y));
      magnitude = std::max({ magnitude, std::fabs(a.x), std::fabs(a.y) });
    }
  }
  const double ulps = shortest / (std::numeric_limits<double>::epsilon() * magnitude);
  // Rounding by a few units moves an angle by about units / ulps radians.
  const bool rounding = (worst - boundDeg) / deg * ulps <= 64;
  const std::string degrees = fixedText(boundDeg, 2) + " degrees, up to " + fixedText(worst, 2);
  return std::to_string(count) + " triangle(s) exceed the largest-angle bound of " + degrees +
    " at " + formatPoint(at, format) + ", in a triangle whose shortest side, " +
    roughNumber(shortest) + ", spans " + roughNumber(ulps) +
    " units in the last place of its coordinates" +
    (rounding ? ": there rounding the points placed on segments moves the angles by that much; "
                "translating the input nearer the origin (subtracting an offset from its "
                "coordinates) leaves more of double precision to features this small"
              : ": this is not rounding but a defect of the mesher; please report it with the "
                "input");
}

Array<int> Mesher::keepDomainTriangles(
  const PlanarGraph& g, Completion& c, Carving& carve, const Unscaler& unscale)
{
  Array<int> newIndex;
  newIndex.assign(g.points.size(), -1);
  // Upper bounds: room never touched costs nothing, growing copies.
  res.mesh.vertices.reserve(g.points.size());
  res.vertexOrigin.reserve(g.points.size());
  // The kept triangles and their region ids move down in place.
  res.mesh.triangles = std::move(c.triangles);
  res.regionId = std::move(carve.regionId);
  Array<Triangle>& tris = res.mesh.triangles;
  Array<int>& region = res.regionId;
  std::size_t kept = 0;
  for (std::size_t t = 0; t < tris.size(); ++t)
  {
    run.tickWith([&] { return 0.5 * double(t) / double(tris.size()); }, 1u << 16);
    if (region[t] < 0)
      continue;
    Triangle tri = tris[t];
    for (int& v : tri)
    {
      if (newIndex[v] < 0)
      {
        newIndex[v] = static_cast<int>(res.mesh.vertices.size());
        res.mesh.vertices.push_back(unscale(g.points[v]));
        res.vertexOrigin.push_back(g.origin[v]);
        if (options.keepVertexSegments) // points splitting long edges are on none
          res.vertexSegment.push_back(
            static_cast<std::size_t>(v) < graphSegment.size() ? graphSegment[v] : -1);
      }
      v = newIndex[v];
    }
    tris[kept] = tri;
    region[kept++] = region[t];
  }
  // Where the domain dropped much (a large exterior), give the memory back.
  const bool shrink = kept < tris.size() / 4 * 3;
  tris.resize(kept);
  region.resize(kept);
  if (shrink)
  {
    tris.shrink_to_fit();
    region.shrink_to_fit();
  }
  return newIndex;
}

void Mesher::mapInputVertices(
  const Work& w, const Overlay& overlay, const Array<int>& newIndex, Domain domain)
{
  // Points created by splitting crossing segments are neither input nor Steiner.
  for (std::size_t i = 0; i < w.points.size(); ++i)
  {
    const int v = newIndex[overlay.inputVertex[i]];
    if (w.isCrossingPoint[i] && v >= 0)
      res.vertexOrigin[v] = VertexOrigin::Other;
  }
  res.inputVertex.assign(input.points.size(), -1);
  std::size_t outside = 0;
  int example = -1;
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    res.inputVertex[i] = newIndex[overlay.inputVertex[clean.pointOf[i]]];
    if (res.inputVertex[i] < 0 && ++outside == 1)
      example = static_cast<int>(i);
  }
  // Say so when the domain leaves input out: nothing disappears silently.
  // (Only the enclosed domain leaves out points outside every hole.)
  if (outside > 0)
    res.warnings.push_back(std::to_string(outside) +
      " input point(s) lie outside the meshed domain (outside every enclosed region or in a "
      "hole) and are not in the mesh, e.g. " +
      namePoint(input, example, options.pointFormat) +
      (domain == Domain::Enclosed ? "; the hull or box domain keeps those outside every region"
                                  : "") +
      (domain == Domain::Enclosed && res.stats.crossingsSplit > 0
          ? "; if segments meant to meet at one point cross apart and enclose a tiny region "
            "there, a merge tolerance joins their crossings"
          : ""));
}

void Mesher::checkOriginRounding()
{
  if (frame.origin.x == 0 && frame.origin.y == 0)
    return;
  const bool stretched = anyRoundedAbove(res.mesh, options.maxEdgeLength, originRounding());
  if (stretched && !shrinkBound)
  {
    boundStretched = true;
    throw Stop{ "adding the origin back stretched an edge past the size bound" };
  }
  if (stretched || res.stats.maxAngleDeg > res.stats.predictedMaxAngleDeg ||
    anyTurnedOver(res.mesh))
  {
    roundedBadly = true;
    throw Stop{ "adding the origin back rounded the mesh badly" };
  }
}

void Mesher::keepEdgesForInspection(const Work& w, const PlanarGraph& g, Array<Edge>& edges,
  const Array<int>& newIndex, const Unscaler& unscale)
{
  res.edgeVertices.reserve(g.points.size());
  for (const Point& p : g.points)
    res.edgeVertices.push_back(unscale(p));
  res.edges = std::move(edges);
  res.edgeVertexInMesh = newIndex;
  for (Edge& e : res.edges) // walked segments to input segments
    e.segment = e.segment >= 0 && e.segment < static_cast<int>(w.segmentOrigin.size())
      ? w.segmentOrigin[e.segment]
      : -1;
}

void Mesher::buildOutput(const Work& w, const PlanarGraph& g, Completion& c, Carving& carve,
  const Overlay& overlay, Array<Edge>& edges, Domain domain)
{
  Statistics& st = res.stats;
  const Unscaler unscale(frame);
  const Array<int> newIndex = keepDomainTriangles(g, c, carve, unscale);
  assignRegionAttributes(carve);
  mapInputVertices(w, overlay, newIndex, domain);
  if (std::string close =
        closePointsWarning(closePairs, res.inputVertex, input, options.pointFormat);
      !close.empty())
    res.warnings.push_back(std::move(close));
  warnAboutDroppedSegments(w, g, carve.droppedConstrained, domain, unscale);
  st.regions = carve.regions;
  st.outputVertices = res.mesh.vertices.size();
  st.outputTriangles = res.mesh.triangles.size();
  run.report(0.6);
  angleExtremes(res.mesh, st.minAngleDeg, st.maxAngleDeg, run);
  checkOriginRounding();
  if (st.maxAngleDeg > st.predictedMaxAngleDeg)
    res.warnings.push_back(
      angleBoundWarning(res.mesh, st.predictedMaxAngleDeg, options.pointFormat));
  run.report(0.85);
  if (options.keepEdges)
    keepEdgesForInspection(w, g, edges, newIndex, unscale);
  for (Point& p : res.overlay.vertices)
    p = unscale(p);
}

} // namespace

namespace
{

Result meshIn(const Pslg& input, const Options& options, Progress* progress, bool translate,
  bool& roundedBadly, bool shrinkBound = false, bool* stretched = nullptr)
{
  const pages::Reuse reuse; // declared first: the mesher's arrays are freed into it
  Mesher mesher(input, options, progress, translate, shrinkBound);
  try
  {
    return mesher.execute();
  }
  catch (const Stop& stop)
  {
    roundedBadly = mesher.translationRoundedBadly();
    if (stretched)
      *stretched = mesher.boundStretchedByTheOrigin();
    Result r;
    r.error = stop.reason + (stop.outgrown ? mesher.grownByCrossings() : "");
    r.warnings = mesher.takeWarnings();
    return r;
  }
  catch (const std::bad_alloc&)
  {
    // Above 30 degrees a runaway refinement is the likelier cause, which no
    // machine or cap cures.
    Result r;
    r.error = options.minAngleDeg > 30.0
      ? "out of memory: with a minimum angle above 30 degrees the overlay refinement need not "
        "end; use 30 degrees or less"
      : "out of memory: the input needs a larger machine, or a Steiner point cap" +
        mesher.grownByCrossings();
    r.warnings = mesher.takeWarnings();
    return r;
  }
}

/// Meshes about an origin near the points (exactOrigin); where those points
/// do not survive rounding to the user's coordinates, meshes in these
/// instead, as near to the offset as they are: the robust predicates then
/// see the points as they are written.
Result meshOnce(const Pslg& input, const Options& options, Progress* progress)
{
  bool roundedBadly = false, stretched = false;
  Result r = meshIn(input, options, progress, true, roundedBadly, false, &stretched);
  // Edges the origin's rounding stretched past the size bound: that mesh
  // again, meeting the bound less the rounding.
  if (stretched)
    r = meshIn(input, options, progress, true, roundedBadly, true);
  if (!roundedBadly)
    return r;
  r = meshIn(input, options, progress, false, roundedBadly);
  // Such an input has features below what its coordinates resolve, which
  // the mesh at them may fail on in a step that does not say so (the
  // fuzzer: points 1e-21 apart at y = 1, "input point 1 was not inserted").
  const std::string internal = "internal error: ";
  if (const std::size_t at = r.error.find(internal); !r.ok && at != std::string::npos)
    r.error = "the input has features below what double precision resolves at its coordinates "
              "(below about 1e-14 of the coordinate magnitude): its mesh, made about an origin "
              "near it, did not survive rounding to them, and made at them it stopped where " +
      r.error.substr(at + internal.size());
  if (r.ok)
    r.warnings.push_back("the input lies so far from the origin for its features that its mesh, "
                         "made about an origin near it, did not survive rounding to its "
                         "coordinates: it was made at those coordinates, where a segment may "
                         "pass through mesh points off it by about 3.8e-15 of its coordinates "
                         "(17 times their epsilon, a few dozen units in the last place); "
                         "subtracting an offset from the input keeps the segments straight");
  return r;
}

} // namespace

Result mesh(const Pslg& input, const Options& options, Progress* progress)
{
  const RoundToNearest rounding; // the host's rounding mode is restored on return
  Result r = meshOnce(input, options, progress);
  const double above =
    options.remeshAboveDeg > 0 ? options.remeshAboveDeg : r.stats.predictedMaxAngleDeg;
  // Above 30 degrees (Γ below 1) nothing is proven, and the refinement may
  // not end: no second mesh there.
  if (!r.ok || options.gapRatioOverlay || !(r.stats.maxAngleDeg > above) ||
    options.minAngleDeg > 30)
    return r;
  // The paper proves the bound for an overlay of gap-ratio quality; the
  // radius-edge overlay is much smaller and has always met it, but nothing
  // proves it does: where it does not, the proof's premise is met instead.
  const std::string why = "the mesh from the radius-edge overlay has an angle of " +
    formatNumber(r.stats.maxAngleDeg) + " degrees, above " + formatNumber(above);
  // The gap-ratio mesh took up to 12.5 times the triangles on the real
  // inputs: one this machine could not hold is not tried.
  if (const double need = 13.0 * double(r.stats.outputTriangles) * kBytesPerTriangle,
      memory = memoryToCheck(need);
      memory > 0 && need > memory)
  {
    r.warnings.push_back(why +
      "; it was not made again from a gap-ratio overlay, which could "
      "take 13 times the triangles, " +
      roughNumber(need / 1e9) + " GB, more than this machine's " + roughNumber(memory / 1e9) +
      " GB");
    return r;
  }
  Options strict = options;
  strict.gapRatioOverlay = true;
  Result again = meshOnce(input, strict, progress);
  if (!again.ok && again.error == kAbortedByTheUser)
    return again;
  if (!again.ok)
  {
    r.warnings.push_back(
      why + ", and making it again from a gap-ratio overlay failed: " + again.error);
    r.stats.secondsTotal += again.stats.secondsTotal;
    return r;
  }
  again.stats.secondsTotal += r.stats.secondsTotal; // the first mesh's time counts too
  again.warnings.insert(again.warnings.begin(),
    why +
      ": it was made again from an overlay of gap-ratio quality (the paper's Definition 2), "
      "for which the paper proves the bound (its largest angle is now " +
      formatNumber(again.stats.maxAngleDeg) + " degrees)");
  return again;
}

} // namespace osm
