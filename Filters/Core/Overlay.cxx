// Sparse Voronoi Refinement of a point set (Hudson, Miller, Phillips 2006),
// as phase 1 of Overlay Stitch Meshing.
//
// Uninserted input points wait in buckets attached to the triangle that
// contains them. A triangle is refined when it is of poor quality (radius /
// shortest edge > Γ; with gapRatio, radius / a corner's nearest-neighbour
// distance > Γ, the paper's Definition 2; or an edge longer than the size
// bound) or crowded (its bucket is not empty). Refining inserts a Steiner
// point, unless an uninserted input point lies within kYield·r of it (r: the
// Steiner point's distance to the triangle's nearest corner): then that point
// is inserted instead. Larger triangles are refined first (by size class,
// within a factor of 8 in circumradius: SizeQueue.h), so the mesh stays a
// well-graded quality Delaunay mesh throughout, which bounds the work.
//
// SVR keeps a waiting point in the bucket of every triangle whose circumdisk
// holds it; here it waits in one, which moves less, and the yield test sees
// the points of the Steiner point's cavity only. SVR's proof of O(n log(L/s)
// + m) work does not carry over as it stands: the benchmark suite measures
// the time per triangle instead (BENCHMARKS.md).
//
// The Steiner point is the circumcenter or, for a skinny triangle, its
// off-center (Üngör, "Off-centers", LATIN 2004): the point on the bisector of
// the shortest edge that makes with that edge a triangle just inside the
// quality bound. It lands nearer the short edge that made the triangle poor,
// so the overlay needs about 10% fewer points; the paper allows any point-set
// mesher with SVR's guarantees, and these keep them (offCenterHeight below).

#include "Overlay.h"

#include "Clean.h"
#include "HugePages.h"
#include "NumberText.h"
#include "Predicates.h"
#include "Series.h"
#include "SizeQueue.h"
#include "SpatialSort.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <new>
#include <string>
#include <utility>

#if defined(__unix__) || defined(__APPLE__)
#include <unistd.h>
#endif

namespace osm
{

double gammaForMinAngle(double minAngleDeg)
{
  return 1.0 / (2.0 * series::sin(minAngleDeg * series::kPi / 180.0));
}

double minAngleForGamma(double gamma)
{
  // libm's: called once per run, outside the meshing call, on the whole range
  // (sin 35° lies beyond series::asin's).
  return std::asin(1.0 / (2.0 * gamma)) * 180.0 / series::kPi;
}

namespace
{

/// A cap on the mesh's size was hit (the mesher then says what grew it).
[[noreturn]] void outgrew(std::string reason)
{
  Stop stop{ std::move(reason) };
  stop.outgrown = true;
  throw stop;
}

/// Fraction of the circumradius within which an input point is preferred.
/// SVR allows any constant below 1; inserting input points earlier means fewer
/// Steiner points. Measured on the real inputs and 3 generated ones: 0.5 -> 0.6
/// gives 3.5% fewer output triangles (random segments 6.4%), largest angle
/// 149.87 degrees; beyond 0.6 the count hardly falls.
constexpr double kYield = 0.6;

/// The off-center's distance from the midpoint of the shortest edge, per unit
/// of that edge's length L, for the quality bound Γ (sin θ1 = 1 / 2Γ). The
/// apex of the isosceles triangle on the edge with apex angle θ1 lies at
/// 1 / (2 tan(θ1 / 2)) = Γ (1 + cos θ1); 5% nearer, the triangle that the edge
/// and the off-center make is strictly good (its apex angle is above θ1)
/// whatever the rounding, so it is not refined again. The off-center lies in
/// the triangle's empty circumdisk, farther than this distance from its
/// boundary and from the edge's ends, and the distance is at least Γ L for
/// θ1 up to 35 degrees: like a circumcenter, a new point lies at least Γ times
/// the shortest edge of the triangle it refines from every vertex, which is
/// what bounds the refinement and its size. Measured (output triangles,
/// against circumcenters, on the 17 real inputs and 3 generated ones): 8%
/// fewer in the geometric mean, from 19% fewer (A.poly) to 8% more
/// (double_hex.poly), and 11% fewer over all; from 0.85 to 1 times the apex
/// distance the counts show no trend; at 0.7 of it, 3% fewer (the off-centers
/// tried in BENCHMARKS.md item 32).
double offCenterHeight(double gamma)
{
  const double sinTheta = 1.0 / (2.0 * gamma);
  return 0.95 * gamma * (1.0 + std::sqrt(1.0 - sinTheta * sinTheta));
}

} // namespace

namespace
{

/// A control group's memory limit from one of its files (cgroup v2's
/// memory.max, v1's memory.limit_in_bytes), or 0: none, or no such file.
double cgroupLimit(const std::string& path)
{
  std::ifstream in(path);
  double limit = 0;
  return in >> limit && limit > 0 ? limit : 0.0; // "max" reads as no number
}

} // namespace

double cgroupMemoryLimit(const std::string& root)
{
  // Named in /proc/self/cgroup: "0::path" for cgroup v2, whose files are
  // memory.max; "N:...memory...:path" for v1's memory controller.
  std::ifstream self(root + "/proc/self/cgroup");
  double tightest = 0;
  std::string line;
  while (std::getline(self, line))
  {
    const std::size_t a = line.find(':'), b = line.find(':', a + 1);
    if (a == std::string::npos || b == std::string::npos)
      continue;
    const std::string controllers = "," + line.substr(a + 1, b - a - 1) + ",";
    const bool v2 = controllers == ",,", v1 = controllers.find(",memory,") != std::string::npos;
    if (!v2 && !v1)
      continue;
    const std::string base = root + (v2 ? "/sys/fs/cgroup" : "/sys/fs/cgroup/memory");
    const std::string file = v2 ? "/memory.max" : "/memory.limit_in_bytes";
    // The group, then each ancestor up to the root of the hierarchy.
    for (std::string path = line.substr(b + 1);;)
    {
      while (!path.empty() && path.back() == '/')
        path.pop_back();
      if (const double limit = cgroupLimit(base + path + file);
          limit > 0 && (tightest == 0 || limit < tightest))
        tightest = limit;
      if (path.empty())
        break;
      path.erase(path.rfind('/') == std::string::npos ? 0 : path.rfind('/'));
    }
  }
  return tightest;
}

double physicalMemoryBytes()
{
  // Read once per process: the files cost more than meshing a small input
  // (every call read /proc/self/cgroup and the limits along its path).
  static const double once = [] {
    double memory = 0;
#if defined(__unix__) || defined(__APPLE__)
    const long pages = sysconf(_SC_PHYS_PAGES), size = sysconf(_SC_PAGE_SIZE);
    if (pages > 0 && size > 0)
      memory = double(pages) * double(size);
#endif
    // v1's "no limit" is a huge number, above the physical memory: ignored.
    if (const double limit = cgroupMemoryLimit(""); limit > 0 && (memory == 0 || limit < memory))
      memory = limit;
    return memory;
  }();
  return once;
}

namespace
{

Array<Point> permuted(const Array<Point>& points, const Array<int>& order)
{
  Array<Point> out;
  out.reserve(order.size());
  for (int i : order)
    out.push_back(points[i]);
  return out;
}

/// Renumber the vertices after the box corners along a Hilbert curve, so that
/// the later phases, which visit vertices and triangles by index, touch memory
/// in spatial order (refinement creates them in a scattered order).
/// fraction: the overlay's progress, reported between the steps (each
/// linear in the vertices or triangles) to poll for an abort.
void renumberAlongHilbertCurve(Overlay& overlay, RunContext& run, double fraction)
{
  Triangulation& mesh = overlay.mesh;
  const int n = static_cast<int>(mesh.points.size());
  if (n <= 4)
    return;
  // The box corners stay 0..3; the others follow the curve.
  const Array<int> order = hilbertOrder(mesh.points.data() + 4, n - 4);
  run.report(fraction);
  Array<int> newIndex;
  newIndex.assign(n, 0);
  for (int v = 0; v < 4; ++v)
    newIndex[v] = v;
  for (int k = 0; k < n - 4; ++k)
    newIndex[order[k] + 4] = k + 4;
  Array<Point> points;
  Array<char> isInput;
  points.assign(n, Point{});
  isInput.assign(n, char{ 0 });
  for (int v = 0; v < n; ++v)
  {
    points[newIndex[v]] = mesh.points[v];
    isInput[newIndex[v]] = overlay.isInput[v];
  }
  mesh.points.swap(points);
  overlay.isInput.swap(isInput);
  run.report(fraction);
  for (Triangulation::Slot& t : mesh.tri)
    if (t.v[0] >= 0)
      for (int& v : t.v)
        v = newIndex[v];
  for (int& v : overlay.inputVertex)
    v = newIndex[v];
}

class Refiner
{
public:
  Refiner(const Array<Point>& points, const OverlayOptions& options, RunContext& run)
    : original(hilbertOrder(points))
    , input(permuted(points, original))
    , run(run)
    , gamma2(options.gamma * options.gamma * (1.0 + 1e-12))
    , offCenter2(options.offCenters ? std::pow(offCenterHeight(options.gamma), 2) : 0.0)
    , gapRatio(options.gapRatio)
    , maxEdge(options.sizeInBoxesOnly ? 0.0 : options.maxEdgeLength)
    , maxEdge2(maxEdge * maxEdge)
    , steinerCap(options.maxSteinerPoints)
    , limited(options.limitRefinement)
    , beyondGuarantee(options.gamma < 1.0)
    , within(options.refineWithin)
    , sizeWithin(options.sizeWithin)
    , sizeBoxes(options.sizeBoxes)
    , sizeFromAreas(options.sizeFromAreas)
  {}

  Overlay refine();

private:
  /// A triangle made by an insertion has the new vertex at index 2, so a
  /// slot and that vertex name one triangle over the whole run (a failed
  /// insertion makes none, so its vertex index may come again): an item whose
  /// slot holds another apex is stale (its triangle was destroyed).
  struct Item
  {
    int tri;
    int apex;
  };

  bool standing(const Item& item) const
  {
    return mesh.alive(item.tri) && mesh.tri[item.tri].v[2] == item.apex;
  }
  void makeBox();
  void enqueueIfNeeded(int t);
  /// Queues the triangles around vertex a not incident to v (start: one that is).
  void enqueueAround(int a, int start, int v);
  /// With gapRatio: the nearest-neighbour distances after inserting v.
  void updateNearest(int v);
  /// Whether the size bound asks to refine triangle abc (longest: its longest
  /// edge, squared).
  bool sizeBoundRefines(const Point& a, const Point& b, const Point& c, double longest) const;
  void refineTriangle(int t);
  Point steinerPoint(int t, const Point& circumcenter) const;
  void splitHullEdge(int edge);
  /// cavityKnown: cavity and waiting already hold p's cavity and its points.
  bool insertVertex(const Point& p, int start, int inputIndex, bool cavityKnown = false);
  void distribute(int v, const Array<int>& fan);
  int findInFan(const Point& q, int v, const Array<int>& fan, std::size_t& hint) const;
  void countSteiner();
  void checkHardCap();
  double pointsForMaxEdge() const;
  /// The refinement's progress in [0, 1], never decreasing between calls.
  double progressOf(double forMaxEdge);

  // The input points in Hilbert order: the buckets of a triangle then hold
  // points that are near in memory too. original[i] is input point i's index
  // in the caller's order, which every choice and message uses.
  const Array<int> original;
  const Array<Point> input;
  RunContext& run;
  const double gamma2;
  const double offCenter2; ///< (off-center height / shortest edge)^2; 0: circumcenters only
  const bool gapRatio;     ///< Γ bounds radius / nearest-neighbour distance at each corner
  const double maxEdge;    ///< 0: none over sizeWithin (the size boxes may have theirs)
  const double maxEdge2;
  const std::size_t steinerCap;
  const bool limited;
  const bool beyondGuarantee; ///< Γ below 1 (θ1 above 30 degrees): refinement need not end
  const Bounds within;
  const Bounds sizeWithin;
  const SizeBoxes sizeBoxes;
  const bool sizeFromAreas;
  /// What sets the size bound, for messages.
  std::string sizeBoundName() const
  {
    return sizeFromAreas ? "the maximum edge length or a region's maximum triangle area"
                         : "the maximum edge length";
  }

  Overlay out;
  Triangulation& mesh = out.mesh;
  // A triangle's bucket (its first waiting input point, -1 if none) is its
  // slot's info.
  Array<int> bucketNext; ///< per input point: next in its bucket
  /// Per input point (in Hilbert order, near in memory as insertion proceeds):
  /// its mesh vertex; out.inputVertex gets it in the caller's order at the end.
  Array<int> vertexOf;
  SizeQueue<Item> queue;
  std::size_t inserted = 0;
  std::size_t hardCap = 0;
  double capFromMemory = 0;   ///< the memory that set hardCap, if it did
  bool memoryAsked = false;   ///< hardCap takes the memory into account
  std::size_t checkCapAt = 0; ///< more Steiner points than this: checkHardCap
  double lastProgress = 0;
  /// With gapRatio, per mesh vertex: the squared distance to its nearest
  /// neighbour among the inserted vertices (Definition 2's r).
  Array<double> nearest2;
  /// Scratch: vertices whose nearest neighbour came nearer in an insertion.
  Array<int> nearer;
  // Scratch.
  Triangulation::Cavity cavity;
  Array<int> created;
  Array<int> waiting;
};

void Refiner::makeBox()
{
  const Bounds b = boundsOf(input);
  double size = std::max(b.width(), b.height());
  if (size == 0)
    size = std::max({ std::fabs(b.lo.x), std::fabs(b.lo.y), 1.0 });
  // A box several times the input keeps the hull's influence away from it.
  const double cx = 0.5 * (b.lo.x + b.hi.x), cy = 0.5 * (b.lo.y + b.hi.y), h = 2.0 * size;
  const int c0 = mesh.addPoint({ cx - h, cy - h });
  const int c1 = mesh.addPoint({ cx + h, cy - h });
  const int c2 = mesh.addPoint({ cx + h, cy + h });
  const int c3 = mesh.addPoint({ cx - h, cy + h });
  out.isInput.assign(4, 0);
  if (gapRatio)
    nearest2.assign(4, 4 * h * h); // the box side, squared
  const int t0 = mesh.newTriangle(c0, c1, c2);
  const int t1 = mesh.newTriangle(c0, c2, c3);
  mesh.link(t0, t1);
  bucketNext.assign(input.size(), -1);
  // Walk in reverse so buckets list points in (Hilbert) index order.
  for (int i = static_cast<int>(input.size()) - 1; i >= 0; --i)
  {
    const int t = orient2d(mesh.points[c0], mesh.points[c2], input[i]) <= 0 ? t0 : t1;
    bucketNext[i] = mesh.tri[t].info;
    mesh.tri[t].info = i;
  }
}

void Refiner::enqueueIfNeeded(int t)
{
  const Point& a = mesh.vertex(t, 0);
  const Point& b = mesh.vertex(t, 1);
  const Point& c = mesh.vertex(t, 2);
  // One circumcenter serves the quality test, r / shortest edge > Γ, and the
  // queue key. A degenerate triangle has an infinite or NaN radius: it counts
  // as poor, and refineTriangle skips it.
  const Point o = circumcenterOffset(a, b, c);
  if (mesh.tri[t].info < 0)
  {
    const double la = dist2(b, c), lb = dist2(a, c), lc = dist2(a, b);
    const bool tooLong = sizeBoundRefines(a, b, c, std::max({ la, lb, lc }));
    // A corner's nearest neighbour is at most its edges away: the gap ratio
    // asks more than the radius / shortest edge ratio.
    const Triangulation::Slot& slot = mesh.tri[t];
    const double near2 = gapRatio
      ? std::min({ nearest2[slot.v[0]], nearest2[slot.v[1]], nearest2[slot.v[2]] })
      : std::min({ la, lb, lc });
    if (!tooLong && o.x * o.x + o.y * o.y <= gamma2 * near2)
      return;
    // Poor, but beyond the bounds where output can be: leave it (tested only
    // here, after the quality test that most new triangles pass).
    if (limited && outsideBounds(a, b, c, within))
      return;
  }
  // The key as refineTriangle computes the radius (only its size class counts).
  queue.push(dist2(a, Point{ a.x + o.x, a.y + o.y }), { t, mesh.tri[t].v[2] });
}

bool Refiner::sizeBoundRefines(const Point& a, const Point& b, const Point& c, double longest) const
{
  return (maxEdge > 0 && longest > maxEdge2 && !(limited && outsideBounds(a, b, c, sizeWithin))) ||
    (!sizeBoxes.empty() && sizeBoxes.tooLong(a, b, c, longest));
}

Overlay Refiner::refine()
{
  // Most inputs need 2 to 17 overlay vertices per input point (random ones
  // about 5): reserve for 6, so typical runs never copy the growing arrays.
  // Where address space is short (strict overcommit), just grow as needed.
  const std::size_t expected = 6 * input.size() + 64;
  try
  {
    mesh.reserve(expected, 2 * expected);
    out.isInput.reserve(expected);
  }
  catch (const std::bad_alloc&)
  {}
  makeBox();
  vertexOf.assign(input.size(), -1);
  // Overlay size is O(n log(L/s)), plus what a size bound asks for; doubles
  // bound log(L/s), so this cap only catches a numerical runaway, turning a
  // hang into a clear error. A cap of the caller's replaces it.
  const double forMaxEdge = pointsForMaxEdge();
  // Triangle slots are ints, and a mesh has about twice as many triangles as vertices.
  const double indexable = std::numeric_limits<int>::max() / 2;
  if (!(forMaxEdge <= indexable))
  {
    const std::string need =
      std::isfinite(forMaxEdge) ? "at least " + generalText(forMaxEdge, 3) : "more";
    throw Stop{ sizeBoundName() + " is too small for this input: the overlay would need " + need +
      " points, and a mesh can index " + std::to_string(static_cast<long long>(indexable)) };
  }
  // A mesh this machine cannot hold would end in the system killing the
  // process (the host application with it): refuse it at once. About 2.2
  // points per forMaxEdge (below), 2 triangles per point, and
  // kBytesPerTriangle (a review's la.poly at 0.003, 2.7e8 triangles, was
  // killed at 23 GB; another's at 0.0032 was let through at 150 bytes).
  if (const double need = 2.2 * forMaxEdge * 2 * kBytesPerTriangle, memory = memoryToCheck(need);
      memory > 0 && need > memory)
  {
    const std::string sizes = "about " + generalText(2.2 * forMaxEdge, 3) + " points, at least " +
      generalText(need / 1e9, 3) + " GB, and this machine has " + generalText(memory / 1e9, 3) +
      " GB";
    throw Stop{ sizeBoundName() +
      " is too small for this machine's memory: the overlay would need " + sizes };
  }
  // A size bound may ask for many more points than the input has: about 2.2
  // times forMaxEdge (measured on squares), so room for 2.5 times spares
  // copying the growing arrays (0.25 s at 5e6 triangles, unpolled).
  if (const double bounded = 2.5 * forMaxEdge; bounded > double(expected))
  {
    try
    {
      mesh.reserve(static_cast<std::size_t>(bounded), 2 * static_cast<std::size_t>(bounded));
      out.isInput.reserve(static_cast<std::size_t>(bounded));
    }
    catch (const std::bad_alloc&)
    {}
  }
  if (steinerCap > 0 && steinerCap < kBoxCorners)
    throw Stop{ "the overlay needs more than the allowed " + std::to_string(steinerCap) +
      " Steiner points: the " + std::to_string(kBoxCorners) +
      " corners of its padding box count among them" };
  // The gap-ratio overlay grades far more slowly around close points (a
  // review: about 4,000 Steiner points per decade of spread around each
  // close pair, against 200), so its cap per point is 100 times larger.
  hardCap = steinerCap > 0 ? steinerCap
                           : (gapRatio ? 100000 : 1000) * input.size() + 1000000 +
      static_cast<std::size_t>(8 * forMaxEdge);
  // Nor more than this machine's memory holds, asked when the overlay gets
  // beyond the points any holds (checkHardCap).
  checkCapAt = std::min<std::size_t>(hardCap, std::size_t(kPointsUncheckedAgainstMemory));
  enqueueIfNeeded(0);
  enqueueIfNeeded(1);
  while (!queue.empty())
  {
    const Item item = queue.pop();
    // A triangle still standing is unchanged since it was queued (refining
    // empties a bucket only by destroying its triangle), so it is still poor
    // or crowded: no need to test it again.
    if (!standing(item))
      continue;
    const std::size_t before = mesh.points.size();
    refineTriangle(item.tri);
    // Yielding or splitting the box may leave this triangle standing: retry it.
    if (mesh.points.size() > before && standing(item))
      enqueueIfNeeded(item.tri);
    run.tickWith([&] { return progressOf(forMaxEdge); });
  }
  out.inputVertex.assign(input.size(), -1);
  for (std::size_t i = 0; i < input.size(); ++i)
  {
    if (vertexOf[i] < 0)
      throw Stop{ "internal error: input point " + std::to_string(original[i]) +
        " was not inserted" };
    out.inputVertex[original[i]] = vertexOf[i];
  }
  mesh.releaseInsertionScratch();
  run.report(lastProgress);
  renumberAlongHilbertCurve(out, run, lastProgress);
  return std::move(out);
}

double Refiner::progressOf(double forMaxEdge)
{
  const double n = static_cast<double>(input.size());
  double fraction = n == 0 ? 1.0 : double(inserted) / n;
  // With a size bound that asks for more points than the input has, the
  // Steiner points are most of the work: count all points against the
  // expected total (about 2.2 times the bound's lower bound, as measured on
  // squares refined to 10^6 points), not only the input points.
  if (forMaxEdge > n)
  {
    const double steiner = static_cast<double>(out.steinerPoints);
    fraction = std::min(
      fraction, (double(inserted) + steiner) / (n + std::max(1.05 * steiner, 2.2 * forMaxEdge)));
  }
  lastProgress = std::max(lastProgress, fraction); // never backwards
  return lastProgress;
}

double Refiner::pointsForMaxEdge() const
{
  // A triangle with no edge longer than h has at most the area of the
  // equilateral one (sqrt(3)/4 h^2), and a triangulation at most about twice
  // as many triangles as vertices: a region of area A needs at least
  // A / (sqrt(3)/2 h^2) vertices. The region is the box, or with limited
  // refinement the bounds, padded by an edge each way (triangles across them
  // are refined too); the size boxes add theirs. h^2 may underflow: the
  // count is then infinite.
  const Bounds box{ mesh.points[0], mesh.points[2] };
  double count = sizeBoxes.pointsNeeded(box);
  if (maxEdge > 0)
  {
    double w = box.width(), h = box.height();
    if (limited)
    {
      w = std::min(w, sizeWithin.width() + 2 * maxEdge);
      h = std::min(h, sizeWithin.height() + 2 * maxEdge);
    }
    count += w * h / (0.8660254037844386 * maxEdge * maxEdge);
  }
  return count;
}

void Refiner::countSteiner()
{
  ++out.steinerPoints;
  if (steinerCap > 0 && out.steinerPoints + kBoxCorners > steinerCap)
    outgrew("the overlay needs more than the allowed " + std::to_string(steinerCap) +
      (beyondGuarantee ? " Steiner points: with a minimum angle above 30 degrees it need not "
                         "end, whatever the cap; use 30 degrees or less"
                       : " Steiner points; raise the cap or coarsen the input"));
  if (out.steinerPoints > checkCapAt)
    checkHardCap();
}

void Refiner::checkHardCap()
{
  // Nor more than this machine's memory holds (2 triangles per point), so
  // that a runaway ends in this error rather than the system killing the
  // process: a review's Constrained_Sweden.poly at 34 degrees with the
  // gap-ratio overlay had a cap of 2.6e8 points, about 50 GB.
  // A caller's cap too: no cap makes a run fit.
  if (!memoryAsked)
  {
    memoryAsked = true;
    if (const double memory = physicalMemoryBytes(); memory > 0)
    {
      const double holds = meshPointsMemoryHolds(memory);
      if (holds < double(hardCap))
      {
        hardCap = static_cast<std::size_t>(holds);
        capFromMemory = memory;
      }
    }
    checkCapAt = hardCap;
  }
  if (out.steinerPoints > hardCap)
    outgrew("the overlay refinement exceeded " + std::to_string(hardCap) +
      (capFromMemory > 0 ? " Steiner points, as many as this machine's memory (" +
            roughNumber(capFromMemory / 1e9) + " GB) holds" +
            (beyondGuarantee ? ": with a minimum angle above 30 degrees it need not end"
                             : ": the input needs a larger machine")
          : beyondGuarantee
          ? " Steiner points without ending: with a minimum angle above 30 degrees "
            "it need not end; use 30 degrees or less"
          : gapRatio ? " Steiner points: the gap-ratio overlay grades slowly around input points "
                       "much closer together than the rest, and these are too many; without it "
                       "(the default overlay) such input needs far fewer"
                     : " Steiner points, which suggests a numerical problem with this input"));
}

Point Refiner::steinerPoint(int t, const Point& circumcenter) const
{
  if (offCenter2 == 0 || !std::isfinite(circumcenter.x) || !std::isfinite(circumcenter.y))
    return circumcenter;
  int s = 0; // the shortest edge is opposite corner s
  double shortest2 = std::numeric_limits<double>::infinity();
  for (int i = 0; i < 3; ++i)
  {
    const double l2 = dist2(mesh.vertex(t, (i + 1) % 3), mesh.vertex(t, (i + 2) % 3));
    if (l2 < shortest2)
    {
      shortest2 = l2;
      s = i;
    }
  }
  const Point& p = mesh.vertex(t, (s + 1) % 3);
  const Point& q = mesh.vertex(t, (s + 2) % 3);
  const Point m{ 0.5 * (p.x + q.x), 0.5 * (p.y + q.y) };
  // The circumcenter lies on the same bisector, on the side of corner s (its
  // angle is the smallest, below 60 degrees): take the nearer of the two.
  const double h2 = offCenter2 * shortest2;
  const double c2 = dist2(m, circumcenter);
  if (!(h2 < c2))
    return circumcenter;
  const double f = std::sqrt(h2 / c2);
  return { m.x + f * (circumcenter.x - m.x), m.y + f * (circumcenter.y - m.y) };
}

void Refiner::refineTriangle(int t)
{
  const Point& a = mesh.vertex(t, 0);
  const Point& b = mesh.vertex(t, 1);
  const Point& d = mesh.vertex(t, 2);
  const Point c = steinerPoint(t, circumcenter(a, b, d));
  const double r2 = std::min({ dist2(a, c), dist2(b, c), dist2(d, c) });
  int exitEdge = -1;
  const int start = std::isfinite(c.x) && std::isfinite(c.y) ? mesh.locate(c, t, &exitEdge) : -2;
  if (start == -2)
  {
    ++out.refinementsSkipped;
    return;
  }
  if (start < 0)
  {
    splitHullEdge(exitEdge);
    return;
  }
  // Refining below the resolution of doubles at this position cannot succeed:
  // the input has features smaller than its coordinates can express.
  const double resolution =
    64 * std::numeric_limits<double>::epsilon() * std::max(std::fabs(c.x), std::fabs(c.y));
  if (r2 < resolution * resolution)
  {
    // So small a triangle is too long only for a size bound that small.
    if (sizeBoundRefines(a, b, d, std::max({ dist2(a, b), dist2(b, d), dist2(d, a) })))
      throw Stop{ sizeBoundName() +
          " is too small for double precision at these coordinates (edges below about 1e-14 of "
          "the coordinate magnitude): use a larger one, or move the input nearer the origin",
        true, c };
    throw Stop{ std::string(kPointsTooCloseSubject) +
        " together than double precision resolves at their coordinates (features below "
        "about 1e-14 of the coordinate magnitude)",
      true, c, { -1, -1 }, Stop::Remedy::MergePoints };
  }
  if (!mesh.cavityOf(c, start, cavity))
  {
    ++out.refinementsSkipped;
    return;
  }
  // A Steiner point that encroaches the box boundary splits the boundary instead.
  for (int e : cavity.boundary)
  {
    if (mesh.across(e) >= 0)
      continue;
    const int u = e / 3, i = e % 3;
    const Point& p = mesh.vertex(u, (i + 1) % 3);
    const Point& q = mesh.vertex(u, (i + 2) % 3);
    if ((c.x - p.x) * (c.x - q.x) + (c.y - p.y) * (c.y - q.y) <= 0)
    {
      splitHullEdge(e);
      return;
    }
  }
  // Yield to the nearest waiting input point close to the Steiner point. The
  // scan also collects the waiting points, for insertVertex if c is inserted.
  int best = -1, bestTri = -1;
  double bestD2 = kYield * kYield * r2;
  waiting.clear();
  for (int u : cavity.triangles)
  {
    for (int i = mesh.tri[u].info; i >= 0; i = bucketNext[i])
    {
      waiting.push_back(i);
      const double d2 = dist2(input[i], c);
      if (d2 < bestD2 || (d2 == bestD2 && (best < 0 || original[i] < original[best])))
      {
        best = i;
        bestTri = u;
        bestD2 = d2;
      }
    }
  }
  if (best >= 0)
  {
    if (!insertVertex(input[best], bestTri, best))
      ++out.refinementsSkipped;
    return;
  }
  countSteiner();
  // The cavity of c and its waiting points are known: reuse them.
  if (!insertVertex(c, start, -1, true))
    ++out.refinementsSkipped;
}

void Refiner::splitHullEdge(int edge)
{
  const int t = edge / 3, i = edge % 3;
  const Point& p = mesh.vertex(t, (i + 1) % 3);
  const Point& q = mesh.vertex(t, (i + 2) % 3);
  // Box edges are axis-parallel, so the midpoint stays exactly on them.
  const Point m{ p.x == q.x ? p.x : 0.5 * (p.x + q.x), p.y == q.y ? p.y : 0.5 * (p.y + q.y) };
  countSteiner();
  if (!insertVertex(m, t, -1))
    ++out.refinementsSkipped;
}

bool Refiner::insertVertex(const Point& p, int start, int inputIndex, bool cavityKnown)
{
  if (!cavityKnown)
  {
    if (!mesh.cavityOf(p, start, cavity))
      return false;
    // Collect the waiting points of the cavity; they move to the new triangles.
    waiting.clear();
    for (int u : cavity.triangles)
    {
      for (int i = mesh.tri[u].info; i >= 0; i = bucketNext[i])
        if (i != inputIndex)
          waiting.push_back(i);
    }
  }
  const int v = mesh.addPoint(p);
  if (!mesh.insertIntoCavity(v, cavity, created))
  {
    mesh.points.pop_back();
    return false;
  }
  out.isInput.push_back(inputIndex >= 0 ? 1 : 0);
  if (inputIndex >= 0)
  {
    vertexOf[inputIndex] = v;
    ++inserted;
  }
  // The new triangles' buckets start empty (newTriangle resets info).
  distribute(v, created);
  if (gapRatio)
    updateNearest(v);
  for (int u : created)
    enqueueIfNeeded(u);
  for (std::size_t k = 0; k < nearer.size(); k += 2)
    enqueueAround(nearer[k], nearer[k + 1], v);
  return true;
}

void Refiner::updateNearest(int v)
{
  // A nearest neighbour is a Delaunay neighbour: v's are the fan's outer
  // vertices, and only they can have come nearer to a vertex. Those that did
  // may leave their older triangles above the gap ratio (listed in nearer,
  // each with a fan triangle it is a corner of).
  const Point& p = mesh.points[v];
  nearest2.push_back(std::numeric_limits<double>::infinity());
  nearer.clear();
  for (int u : created)
    for (int k = 0; k < 2; ++k) // v[1] too: on the box boundary the fan is open
    {
      const int a = mesh.tri[u].v[k];
      const double d = dist2(p, mesh.points[a]);
      nearest2[v] = std::min(nearest2[v], d);
      if (d < nearest2[a])
      {
        nearest2[a] = d;
        nearer.push_back(a);
        nearer.push_back(u);
      }
    }
}

void Refiner::enqueueAround(int a, int start, int v)
{
  // Both ways around a from a triangle of the fan, up to the hull or back.
  for (const int step : { 1, 2 })
  {
    int t = start;
    for (;;)
    {
      const int i = mesh.localIndex(t, a);
      t = mesh.tri[t].n[(i + step) % 3];
      if (t < 0 || t == start)
        break;
      if (mesh.localIndex(t, v) < 0)
        enqueueIfNeeded(t);
    }
    if (t == start)
      break;
  }
}

int Refiner::findInFan(const Point& q, int v, const Array<int>& fan, std::size_t& hint) const
{
  // q lies in the cavity, which the fan covers, star-shaped around v: q is in
  // the closed fan triangle (a, b, v) iff it lies in the closed wedge from the
  // ray v->a to the ray v->b. (q lies strictly left of v->a iff
  // orient(v, q, a) < 0.)
  const Point& c = mesh.points[v];
  // Waiting points come in Hilbert order, so most lie in the wedge of the
  // one before: try it first. Strictly inside it, q is in no other closed
  // wedge (a star's open wedges are disjoint, each under 180 degrees), so
  // the scan below would find this one too.
  if (hint < fan.size())
  {
    const Triangulation::Slot& s = mesh.tri[fan[hint]];
    if (orient2d(c, q, mesh.points[s.v[0]]) < 0 && orient2d(c, q, mesh.points[s.v[1]]) > 0)
      return fan[hint];
  }
  // Consecutive fan triangles share a ray, so each ray is tested once: about
  // one orientation per triangle instead of three.
  int previousB = -1;
  double previousSide = 0;
  for (std::size_t k = 0; k < fan.size(); ++k)
  {
    const int u = fan[k];
    const int a = mesh.tri[u].v[0], b = mesh.tri[u].v[1];
    const double sideA = a == previousB ? previousSide : orient2d(c, q, mesh.points[a]);
    previousB = -1;
    if (sideA > 0) // q is strictly right of v->a: not in this wedge
      continue;
    const double sideB = orient2d(c, q, mesh.points[b]);
    if (sideB >= 0)
    {
      hint = k;
      return u;
    }
    previousB = b;
    previousSide = sideB;
  }
  return mesh.locate(q, fan.front());
}

void Refiner::distribute(int v, const Array<int>& fan)
{
  // Reverse order keeps each bucket in increasing point order: deterministic.
  std::size_t hint = 0;
  for (auto it = waiting.rbegin(); it != waiting.rend(); ++it)
  {
    const int i = *it;
    int u = findInFan(input[i], v, fan, hint);
    if (u < 0)
      throw Stop{ "internal error: lost input point " + std::to_string(original[i]) +
        " during refinement" };
    bucketNext[i] = mesh.tri[u].info;
    mesh.tri[u].info = i;
  }
}

} // namespace

Overlay buildOverlay(const Array<Point>& points, const OverlayOptions& options, RunContext& run)
{
  if (points.empty())
    return {};
  Refiner refiner(points, options, run);
  return refiner.refine();
}

} // namespace osm
