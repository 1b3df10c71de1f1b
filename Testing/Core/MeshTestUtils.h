// Helpers shared by the core tests: run the mesher and check its result with
// the independent validator.
#ifndef osm_MeshTestUtils_h
#define osm_MeshTestUtils_h

#include "Clean.h"
#include "Mesher.h"
#include "Validate.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace osm
{

/// The area a mesh covers (its triangles' signed areas summed).
inline double area(const TriMesh& m)
{
  double a = 0;
  for (const Triangle& t : m.triangles)
  {
    const Point &p = m.vertices[t[0]], &q = m.vertices[t[1]], &r = m.vertices[t[2]];
    a += 0.5 * ((q.x - p.x) * (r.y - p.y) - (q.y - p.y) * (r.x - p.x));
  }
  return a;
}

/// Mesh and validate; every failure names the case. Returns the result.
inline Result meshAndValidate(
  const Pslg& input, const std::string& name, Options options = {}, ValidationOptions vo = {})
{
  // A size bound asked of the mesher is checked on every edge.
  if (vo.maxEdgeLength == 0)
    vo.maxEdgeLength = options.maxEdgeLength;
  // Segments bend onto points within the merge tolerance of them.
  if (vo.snapTolerance == 0)
    vo.snapTolerance = options.mergeTolerance;
  Result r = mesh(input, options);
  EXPECT_TRUE(r.ok) << name << ": " << r.error;
  if (!r.ok)
    return r;
  // Crossings within the merge tolerance of a point or of each other join
  // it: a segment's chain then passes that close to its line (Options).
  if (vo.chainOffset == 0 && r.stats.crossingsSplit > 0)
    vo.chainOffset = options.mergeTolerance;
  // Points the domain leaves out (outside every region, in holes) must be
  // reported by a warning; the rest of the input must be in the mesh, each
  // where it was merged to: within the merge tolerance. Their segments stay
  // in the validator's input, which skips them, so that it sees where they
  // crossed the segments it checks (a chain bends there). A left-out point
  // within the merge tolerance of a segment still splits it for the
  // validator, which then skips the pieces it ends: weaker there. A left-out
  // point stands where cleaning merged it: a segment whose end joined a point
  // outside the domain runs from there (as the fuzzer found).
  Pslg present = input;
  present.segments.clear();
  CleanPslg merged;
  Statistics ignored;
  std::vector<std::string> ignoredWarnings;
  EXPECT_EQ(cleanPslg(input, merged, ignored, ignoredWarnings, options.mergeTolerance), "");
  if (merged.pointOf.size() == input.points.size())
    for (std::size_t i = 0; i < input.points.size(); ++i)
      present.points[i] = merged.points[merged.pointOf[i]];
  std::size_t leftOut = 0;
  std::vector<char> used(r.mesh.vertices.size(), 0);
  for (const Triangle& t : r.mesh.triangles)
    for (int v : t)
      used.at(v) = 1;
  for (std::size_t i = 0; i < input.points.size(); ++i)
    if (r.inputVertex.at(i) < 0)
      ++leftOut;
    else
    {
      const Point& at = r.mesh.vertices.at(r.inputVertex[i]);
      const Point& p = input.points[i];
      EXPECT_TRUE(at == p || std::hypot(at.x - p.x, at.y - p.y) <= options.mergeTolerance)
        << name << ": input point " << i << " moved further than the merge tolerance";
      EXPECT_TRUE(used.at(r.inputVertex[i])) << name << ": input point " << i << " in no triangle";
      present.points[i] = at;
    }
  for (const Segment& s : input.segments)
    if (!(present.points[s[0]] == present.points[s[1]]))
      present.segments.push_back(s);
  if (leftOut > 0)
  {
    vo.requireAllInputVertices = false; // checked above for the points in the mesh
    bool warned = false;
    for (const std::string& w : r.warnings)
      warned = warned || w.find("outside the meshed domain") != std::string::npos;
    EXPECT_TRUE(warned) << name << ": input points left out without a warning";
  }
  // The domain: its boundary along the segments (and the hull's or the box's
  // edges), and no hole seed covered unless a merge moved one across a
  // segment (warned about).
  vo.boundary = r.domain == Domain::Enclosed ? DomainBoundary::Segments
    : r.domain == Domain::Hull               ? DomainBoundary::SegmentsOrHull
                                             : DomainBoundary::SegmentsOrBox;
  EXPECT_TRUE(r.domain != Domain::Auto || input.points.empty()) << name;
  bool seedsMoved = false;
  for (const std::string& w : r.warnings)
    seedsMoved = seedsMoved || w.find("seed(s) now lie on the other side") != std::string::npos;
  vo.checkHoles = !seedsMoved;
  const ValidationReport report = validate(present, r.mesh.vertices, r.mesh.triangles, vo);
  EXPECT_TRUE(report.ok) << name << ": " << (report.errors.empty() ? "" : report.errors.front());
  EXPECT_LE(r.stats.maxAngleDeg, r.stats.predictedMaxAngleDeg + 1e-9) << name;
  // The bound, 169.95 degrees at 30, by the validator's own measure too.
  EXPECT_LE(report.maxAngleDeg, r.stats.predictedMaxAngleDeg + 1e-9) << name;
  EXPECT_EQ(r.regionId.size(), r.mesh.triangles.size()) << name;
  EXPECT_EQ(r.vertexOrigin.size(), r.mesh.vertices.size()) << name;
  return r;
}

} // namespace osm

#endif
