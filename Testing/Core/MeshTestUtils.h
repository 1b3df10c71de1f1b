// Helpers shared by the core tests: run the mesher and check its result with
// the independent validator.
#ifndef osm_MeshTestUtils_h
#define osm_MeshTestUtils_h

#include "Mesher.h"
#include "Validate.h"

#include <gtest/gtest.h>

#include <string>

namespace osm
{

/// Mesh and validate; every failure names the case. Returns the result.
inline Result meshAndValidate(const Pslg& input, const std::string& name, Options options = {},
  ValidationOptions vo = {})
{
  Result r = mesh(input, options);
  EXPECT_TRUE(r.ok) << name << ": " << r.error;
  if (!r.ok)
    return r;
  if (!input.holes.empty())
    vo.requireAllInputVertices = false;
  const ValidationReport report = validate(input, r.mesh.vertices, r.mesh.triangles, vo);
  EXPECT_TRUE(report.ok) << name << ": " << (report.errors.empty() ? "" : report.errors.front());
  EXPECT_LE(r.stats.maxAngleDeg, r.stats.predictedMaxAngleDeg + 1e-9) << name;
  EXPECT_EQ(r.regionId.size(), r.mesh.triangles.size()) << name;
  EXPECT_EQ(r.vertexOrigin.size(), r.mesh.vertices.size()) << name;
  return r;
}

} // namespace osm

#endif
