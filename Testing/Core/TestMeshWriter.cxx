// Writing results: Triangle files read back exactly, SVG and JSON content.
#include "MeshWriter.h"
#include "PolyReader.h"
#include "Predicates.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

using namespace osm;
namespace fs = std::filesystem;

namespace
{
Result squareWithSlit()
{
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.2, 0.3 }, { 0.7, 0.35 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 } };
  return mesh(p);
}

/// The same in the box domain, with its edges: the mesh's boundary is the
/// padded box, and the square's sides and the slit lie inside.
Result squareWithSlitInABox()
{
  Pslg p;
  p.points = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 0.2, 0.3 }, { 0.7, 0.35 } };
  p.segments = { { 0, 1 }, { 1, 2 }, { 2, 3 }, { 3, 0 }, { 4, 5 } };
  Options o;
  o.domain = Domain::Box;
  o.keepEdges = true;
  return mesh(p, o);
}

/// Per edge of the mesh (lower vertex, higher), how many triangles have it.
std::map<std::pair<int, int>, int> trianglesPerEdge(const Result& r)
{
  std::map<std::pair<int, int>, int> triangles;
  for (const Triangle& t : r.mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++triangles[{ std::min(t[i], t[(i + 1) % 3]), std::max(t[i], t[(i + 1) % 3]) }];
  return triangles;
}
} // namespace

TEST(MeshWriter, TriangleFilesReadBackExactly)
{
  const Result r = squareWithSlit();
  ASSERT_TRUE(r.ok) << r.error;
  const fs::path dir = fs::temp_directory_path() / "osm-writer-test";
  fs::create_directories(dir);
  const std::string base = (dir / "out").string();
  ASSERT_EQ(writeTriangleFiles(base, r), "");
  const PolyFile node = readPolyFile(base + ".node");
  ASSERT_TRUE(node.ok) << node.error;
  EXPECT_EQ(node.firstIndex, 1);
  ASSERT_EQ(node.pslg.points.size(), r.mesh.vertices.size());
  for (std::size_t i = 0; i < r.mesh.vertices.size(); ++i)
    EXPECT_EQ(node.pslg.points[i], r.mesh.vertices[i]);
  std::ifstream ele(base + ".ele");
  std::size_t count = 0, corners = 0;
  ele >> count >> corners;
  EXPECT_EQ(count, r.mesh.triangles.size());
  EXPECT_EQ(corners, 3u);
  std::size_t id, a, b, c;
  int region;
  ASSERT_TRUE(ele >> id >> a >> b >> c >> region);
  EXPECT_EQ(id, 1u);
  EXPECT_EQ(a, static_cast<std::size_t>(r.mesh.triangles[0][0] + 1));
  std::ifstream edge(base + ".edge");
  std::size_t edges = 0, markers = 0, inputEdges = 0;
  edge >> edges >> markers;
  for (std::size_t e = 0; e < edges; ++e)
  {
    int m;
    ASSERT_TRUE(edge >> id >> a >> b >> m);
    inputEdges += m;
  }
  // Euler: E = V + F - 1 for a disc; the sides, its boundary, are marked.
  EXPECT_EQ(edges, r.mesh.vertices.size() + r.mesh.triangles.size() - 1);
  EXPECT_GE(inputEdges, 4u);
  fs::remove_all(dir);
}

TEST(MeshWriter, VertexAttributesAndMarkersReadBackExactly)
{
  const Result r = squareWithSlit();
  ASSERT_TRUE(r.ok) << r.error;
  NodeData data;
  data.attributeCount = 2;
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
  {
    data.attributes.push_back(r.mesh.vertices[v].x / 3); // not short in decimal
    data.attributes.push_back(-1e-300 * static_cast<double>(v));
    data.markers.push_back(static_cast<int>(v % 5));
  }
  const fs::path dir = fs::temp_directory_path() / "osm-writer-data-test";
  fs::create_directories(dir);
  const std::string base = (dir / "out").string();
  ASSERT_EQ(writeTriangleFiles(base, r, data), "");
  const PolyFile node = readPolyFile(base + ".node");
  ASSERT_TRUE(node.ok) << node.error;
  ASSERT_EQ(node.pointAttributes.size(), r.mesh.vertices.size());
  ASSERT_EQ(node.pointMarkers.size(), r.mesh.vertices.size());
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
  {
    ASSERT_EQ(node.pointAttributes[v].size(), 2u);
    EXPECT_EQ(node.pointAttributes[v][0], data.attributes[2 * v]);
    EXPECT_EQ(node.pointAttributes[v][1], data.attributes[2 * v + 1]);
    EXPECT_EQ(node.pointMarkers[v], data.markers[v]);
  }
  // Data of the wrong size is refused, naming the file.
  data.markers.pop_back();
  EXPECT_NE(writeTriangleFiles(base, r, data).find("out.node"), std::string::npos);
  fs::remove_all(dir);
}

TEST(MeshWriter, TriangleBoundaryMarkersWithoutData)
{
  // The box domain: the mesh's boundary is the padded box, not a segment.
  const Result r = squareWithSlitInABox();
  ASSERT_TRUE(r.ok) << r.error;
  const fs::path dir = fs::temp_directory_path() / "osm-writer-markers-test";
  fs::create_directories(dir);
  const std::string base = (dir / "out").string();
  ASSERT_EQ(writeTriangleFiles(base, r), "");
  // The boundary, independently: edges of one triangle.
  std::map<std::pair<int, int>, int> triangles = trianglesPerEdge(r);
  std::vector<int> boundaryVertex(r.mesh.vertices.size(), 0);
  for (const auto& [edge, count] : triangles)
    if (count == 1)
      boundaryVertex[edge.first] = boundaryVertex[edge.second] = 1;
  // Triangle's rules for input without markers: 1 on the boundary, else 0,
  // input vertices and subsegments inside included.
  const PolyFile node = readPolyFile(base + ".node");
  ASSERT_TRUE(node.ok) << node.error;
  ASSERT_EQ(node.pointMarkers.size(), r.mesh.vertices.size());
  int onBoundary = 0;
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
  {
    EXPECT_EQ(node.pointMarkers[v], boundaryVertex[v]) << "vertex " << v;
    onBoundary += boundaryVertex[v];
  }
  EXPECT_GE(onBoundary, 4);
  auto onInput = [](const Point& a, const Point& b) {
    auto side = [](double u, double v) { return u == v && (u == 0 || u == 1); };
    const bool square = (side(a.x, b.x) && a.y >= 0 && a.y <= 1 && b.y >= 0 && b.y <= 1) ||
      (side(a.y, b.y) && a.x >= 0 && a.x <= 1 && b.x >= 0 && b.x <= 1);
    const Point s0{ 0.2, 0.3 }, s1{ 0.7, 0.35 };
    const bool slit = orient2d(s0, s1, a) == 0 && orient2d(s0, s1, b) == 0 &&
      std::min(a.x, b.x) >= 0.2 && std::max(a.x, b.x) <= 0.7;
    return square || slit;
  };
  std::ifstream edge(base + ".edge");
  std::size_t edges = 0, markers = 0, id, a, b;
  edge >> edges >> markers;
  int wrong = 0, boundaryEdges = 0, inside = 0;
  for (std::size_t e = 0; e < edges; ++e)
  {
    int m;
    ASSERT_TRUE(edge >> id >> a >> b >> m);
    const int lo = static_cast<int>(std::min(a, b)) - 1, hi = static_cast<int>(std::max(a, b)) - 1;
    const bool boundary = triangles[{ lo, hi }] == 1;
    boundaryEdges += boundary;
    inside += onInput(r.mesh.vertices[lo], r.mesh.vertices[hi]) && !boundary;
    wrong += m != (boundary ? 1 : 0);
  }
  EXPECT_GE(boundaryEdges, 4);
  EXPECT_GE(inside, 5); // input subsegments inside the box: marked 0
  EXPECT_EQ(wrong, 0);
  fs::remove_all(dir);
}

TEST(MeshWriter, PolyFileListsTheSegmentsToMeshAgain)
{
  // Found by a Triangle user's review: without a .poly (Triangle's -p writes
  // one) an interior segment's edges were marked 0 in .edge like any other,
  // and could not be told apart or refined again. The box domain: the slit
  // is inside, the boundary is the box.
  const Result r = squareWithSlitInABox();
  ASSERT_TRUE(r.ok) << r.error;
  const fs::path dir = fs::temp_directory_path() / "osm-writer-poly-test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string base = (dir / "out").string();
  NodeData data;
  data.firstIndex = 0;
  data.holes = { { 0.1 / 3, -5 } };
  data.regions = { { { 0.5, 0.5 }, 7.25, 1e-3 }, { { 2, 2 }, -1, -1 } };
  ASSERT_EQ(writeTriangleFiles(base, r, data), "");
  const PolyFile poly = readPolyFile(base + ".poly"); // its vertices from out.node
  ASSERT_TRUE(poly.ok) << poly.error;
  EXPECT_EQ(poly.firstIndex, 0);
  ASSERT_EQ(poly.pslg.points.size(), r.mesh.vertices.size());
  // Its segments: exactly the mesh edges on the input or the boundary.
  std::map<std::pair<int, int>, int> triangles = trianglesPerEdge(r);
  const Point s0{ 0.2, 0.3 }, s1{ 0.7, 0.35 };
  auto onInput = [&](const Point& a, const Point& b) {
    auto side = [](double u, double v) { return u == v && (u == 0 || u == 1); };
    auto in = [](double u) { return u >= 0 && u <= 1; };
    return (side(a.x, b.x) && in(a.y) && in(b.y)) || (side(a.y, b.y) && in(a.x) && in(b.x)) ||
      (orient2d(s0, s1, a) == 0 && orient2d(s0, s1, b) == 0 && std::min(a.x, b.x) >= 0.2 &&
        std::max(a.x, b.x) <= 0.7);
  };
  std::size_t expected = 0;
  for (const auto& [edge, count] : triangles)
    expected += count == 1 || onInput(r.mesh.vertices[edge.first], r.mesh.vertices[edge.second]);
  ASSERT_EQ(poly.pslg.segments.size(), expected);
  ASSERT_EQ(poly.segmentMarkers.size(), expected);
  double slit = 0;
  for (std::size_t k = 0; k < expected; ++k)
  {
    const Segment& sg = poly.pslg.segments[k];
    const auto key = std::make_pair(std::min(sg[0], sg[1]), std::max(sg[0], sg[1]));
    ASSERT_EQ(triangles.count(key), 1u) << "segment " << k << " is no mesh edge";
    const bool boundary = triangles[key] == 1;
    EXPECT_EQ(poly.segmentMarkers[k], boundary ? 1 : 0) << "segment " << k;
    const Point &a = r.mesh.vertices[key.first], &b = r.mesh.vertices[key.second];
    if (!boundary && orient2d(s0, s1, a) == 0 && orient2d(s0, s1, b) == 0)
      slit += std::hypot(b.x - a.x, b.y - a.y);
  }
  EXPECT_NEAR(slit, std::hypot(0.5, 0.05), 1e-12); // the slit, whole
  ASSERT_EQ(poly.pslg.holes.size(), 1u);
  EXPECT_EQ(poly.pslg.holes[0], data.holes[0]);
  ASSERT_EQ(poly.pslg.regions.size(), 2u);
  EXPECT_EQ(poly.pslg.regions[0].seed, data.regions[0].seed);
  EXPECT_EQ(poly.pslg.regions[0].attribute, 7.25);
  EXPECT_EQ(poly.pslg.regions[0].maxArea, 1e-3);
  EXPECT_EQ(poly.pslg.regions[1].maxArea, -1);
  // Without regions the section is left out, as Triangle does; without
  // writePoly an old .poly stays as it was.
  data.regions.clear();
  ASSERT_EQ(writeTriangleFiles(base, r, data), "");
  EXPECT_TRUE(readPolyFile(base + ".poly").pslg.regions.empty());
  {
    std::ofstream(base + ".poly") << "the input\n";
  }
  data.writePoly = false;
  ASSERT_EQ(writeTriangleFiles(base, r, data), "");
  std::ifstream kept(base + ".poly");
  std::string line;
  std::getline(kept, line);
  EXPECT_EQ(line, "the input");
  fs::remove_all(dir);
}

TEST(MeshWriter, UnwritablePathGivesAReason)
{
  EXPECT_EQ(writeTriangleFiles("/nonexistent-dir/x", squareWithSlit()),
    "cannot write /nonexistent-dir/x.node: No such file or directory");
  // Found by a user review: with a directory named x.edge the message gave
  // no reason, and empty x.node and x.ele were left behind.
  const fs::path dir = fs::temp_directory_path() / "osm-writer-unwritable";
  fs::remove_all(dir);
  fs::create_directories(dir / "x.edge");
  const std::string base = (dir / "x").string();
  EXPECT_EQ(writeTriangleFiles(base, squareWithSlit()),
    "cannot write " + base + ".edge: Is a directory (the partial files are removed)");
  EXPECT_FALSE(fs::exists(base + ".node"));
  EXPECT_FALSE(fs::exists(base + ".ele"));
  fs::remove_all(dir);
}

TEST(MeshWriter, AFailedWriteRemovesWhatItWroteThroughLinksNotTheLinks)
{
  // Found by a review: the links were removed, the file one named was left
  // rewritten, and the message named no file.
  if (!fs::exists("/dev/full"))
    GTEST_SKIP() << "no /dev/full";
  const fs::path dir = fs::temp_directory_path() / "osm-writer-links";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string base = (dir / "x").string();
  fs::create_symlink("target.node", base + ".node");
  fs::create_symlink("/dev/full", base + ".ele");
  EXPECT_EQ(writeTriangleFiles(base, squareWithSlit()),
    "cannot write " + base + ".ele: No space left on device (the partial files are removed)");
  EXPECT_TRUE(fs::is_symlink(base + ".node"));
  EXPECT_TRUE(fs::is_symlink(base + ".ele"));
  EXPECT_FALSE(fs::exists(dir / "target.node"));
  EXPECT_FALSE(fs::exists(base + ".edge"));
  fs::remove_all(dir);
}

TEST(MeshWriter, SvgAndJson)
{
  const Result r = squareWithSlit();
  std::ostringstream svg, json;
  writeSvg(svg, r);
  EXPECT_EQ(svg.str().rfind("<svg", 0), 0u);
  EXPECT_NE(svg.str().find("<g id=\"input\">"), std::string::npos);
  EXPECT_NE(svg.str().find("</svg>"), std::string::npos);
  writeStatisticsJson(json, r);
  EXPECT_NE(json.str().find("\"ok\": true"), std::string::npos);
  EXPECT_NE(json.str().find("\"OutputTriangles\": " + std::to_string(r.mesh.triangles.size())),
    std::string::npos);
  // Messages quote file names and tokens: quotes, backslashes and control
  // bytes are escaped, so the JSON stays valid (a mutation test: none of them
  // was written in a test).
  Result failed;
  failed.ok = false;
  failed.error = "C:\\data\\t.poly:3: found '\"x\"'\tand \x01";
  failed.warnings = { "a\\b", "line\nbreak" };
  failed.stats.maxAngleDeg = std::numeric_limits<double>::quiet_NaN();
  std::ostringstream bad;
  writeStatisticsJson(bad, failed);
  EXPECT_NE(bad.str().find("\"ok\": false"), std::string::npos) << bad.str();
  EXPECT_NE(
    bad.str().find(R"json("error": "C:\\data\\t.poly:3: found '\"x\"'\u0009and \u0001",)json"),
    std::string::npos)
    << bad.str();
  EXPECT_NE(bad.str().find(R"json("Warnings": ["a\\b", "line\u000abreak"])json"), std::string::npos)
    << bad.str();
  EXPECT_NE(bad.str().find("\"MaxAngleDeg\": 0,"), std::string::npos) << bad.str();
}
