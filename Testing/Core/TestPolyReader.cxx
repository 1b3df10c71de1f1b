// Tests of the Triangle .poly/.node reader: inline texts for every feature and every
// error path (with the exact line reported), then the real files in ../shared/data/pslg.
#include "PolyReader.h"
#include "SharedData.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

using namespace osm;
namespace fs = std::filesystem;

namespace
{

PolyFile poly(const std::string& text, std::istream* nodeText = nullptr)
{
  std::istringstream in(text);
  return parsePoly(in, "t.poly", nodeText);
}

PolyFile node(const std::string& text)
{
  std::istringstream in(text);
  return parseNode(in, "t.node");
}

/// The parse failed with exactly "<where>: ..." and the message contains fragment.
::testing::AssertionResult failsAt(
  const PolyFile& f, const std::string& where, const std::string& fragment)
{
  if (f.ok)
    return ::testing::AssertionFailure() << "parsed, expected an error at " << where;
  if (f.error.rfind(where + ": ", 0) != 0)
    return ::testing::AssertionFailure() << "error '" << f.error << "' is not at " << where;
  if (f.error.find(fragment) == std::string::npos)
    return ::testing::AssertionFailure() << "error '" << f.error << "' lacks '" << fragment << "'";
  return ::testing::AssertionSuccess();
}

// A unit square with a hole, 1-based, reused by several tests.
const char* const squareWithHole = "4 2 0 0\n"
                                   "1 0 0\n"
                                   "2 1 0\n"
                                   "3 1 1\n"
                                   "4 0 1\n"
                                   "4 0\n"
                                   "1 1 2\n"
                                   "2 2 3\n"
                                   "3 3 4\n"
                                   "4 4 1\n"
                                   "1\n"
                                   "1 0.5 0.5\n";

} // namespace

// --- Valid input -------------------------------------------------------------------

TEST(PolyReader, MinimalFile)
{
  const PolyFile f = poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n3 0\n0 0 1\n1 1 2\n2 2 0\n0\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_TRUE(f.error.empty());
  EXPECT_EQ(f.firstIndex, 0);
  ASSERT_EQ(f.pslg.points.size(), 3u);
  EXPECT_EQ(f.pslg.points[1], (Point{ 1, 0 }));
  EXPECT_EQ(f.pslg.points[2], (Point{ 0, 1 }));
  ASSERT_EQ(f.pslg.segments.size(), 3u);
  EXPECT_EQ(f.pslg.segments[2], (Segment{ 2, 0 }));
  EXPECT_TRUE(f.pslg.holes.empty());
  EXPECT_TRUE(f.pointAttributes.empty());
  EXPECT_TRUE(f.pointMarkers.empty());
  EXPECT_TRUE(f.segmentMarkers.empty());
  EXPECT_TRUE(f.pslg.regions.empty());
}

TEST(PolyReader, CommentsBlankLinesAndWhitespace)
{
  // Comments before, between and after data, tabs, CRLF, a byte order mark,
  // a comment glued to a number, and no final newline.
  const std::string text = "\xEF\xBB\xBF# header comment\r\n"
                           "\r\n"
                           "   # indented comment\n"
                           "\t3\t2 0 0   # vertices\n"
                           "\n"
                           "1 0 0\r\n"
                           "  2   4.5   0  \n"
                           "# between vertices\n"
                           "3 0 2#glued comment\n"
                           "3 0\n"
                           "1 1 2\n"
                           "\n\n"
                           "2 2 3\n"
                           "3 3 1 # last segment\n"
                           "# no holes\n"
                           "0";
  const PolyFile f = poly(text);
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pslg.points.size(), 3u);
  EXPECT_EQ(f.pslg.points[0], (Point{ 0, 0 }));
  EXPECT_EQ(f.pslg.points[1], (Point{ 4.5, 0 }));
  EXPECT_EQ(f.pslg.points[2], (Point{ 0, 2 }));
  EXPECT_EQ(f.pslg.segments.size(), 3u);
}

TEST(PolyReader, ClassicMacLineEndsAreLineEnds)
{
  // Found by a review: a file whose lines end with CR alone (classic Mac OS)
  // read as one line, "4 vertices announced, but only 0 lines follow".
  const PolyFile f = poly("# square\r4 2 0 0\r1 0 0\r2 1 0\r3 1 1\r4 0 1\r\r4 0\r1 1 2\r2 2 3\r"
                          "3 3 4\r4 4 1\r0\r");
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pslg.points.size(), 4u);
  EXPECT_EQ(f.pslg.points[2], (Point{ 1, 1 }));
  ASSERT_EQ(f.pslg.segments.size(), 4u);
  EXPECT_EQ(f.pslg.segments[3], (Segment{ 3, 0 }));
  // Errors count those lines.
  const PolyFile bad = poly("4 2 0 0\r1 0 0\r2 1 x\r3 1 1\r4 0 1\r0 0\r");
  ASSERT_FALSE(bad.ok);
  EXPECT_EQ(bad.error.rfind("t.poly:3: ", 0), 0u) << bad.error;
  // CR alone with a final LF, and CR mixed with CRLF and LF (a review: both
  // refused, the second as "vertex index 4 is out of sequence").
  for (const char* text :
    { "4 2 0 0\r1 0 0\r2 1 0\r3 1 1\r4 0 1\r4 0\r1 1 2\r2 2 3\r3 3 4\r4 4 1\r0\n",
      "4 2 0 0\r\n1 0 0\r2 1 0\n3 1 1\r\r\n4 0 1\r4 0\n1 1 2\r2 2 3\r\n3 3 4\r4 4 1\r\n0" })
  {
    const PolyFile mixed = poly(text);
    ASSERT_TRUE(mixed.ok) << mixed.error;
    EXPECT_EQ(mixed.pslg.points.size(), 4u);
    EXPECT_EQ(mixed.pslg.segments.size(), 4u);
  }
  const PolyFile late = poly("4 2 0 0\r\n1 0 0\r2 1 0\n3 1 q\r\n4 0 1\n");
  EXPECT_EQ(late.error.rfind("t.poly:4: ", 0), 0u) << late.error;
}

TEST(PolyReader, WholeNumbersWrittenAsRealsAreIntegers)
{
  // Found by a Triangle user's review: numpy's savetxt writes every column
  // as a real ("1.000000000000000000e+00"); Triangle reads such indices and
  // counts, and they were refused here. (Triangle's strtol reads the digits
  // before the point: 1.0e+01 as 1; here its value, 10, as such files mean.)
  const PolyFile f = poly("3.0 2 0 0\n1.0 0 0\n2.000000000000000000e+00 1 0\n3 0 1\n"
                          "1 0.0\n1.000000000000000000e+00 1.0 3e0\n0.0\n");
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pslg.points.size(), 3u);
  ASSERT_EQ(f.pslg.segments.size(), 1u);
  EXPECT_EQ(f.pslg.segments[0], (Segment{ 0, 2 }));
}

TEST(PolyReader, ListsNoVerticesAsTheReaderReadsIt)
{
  // The check osm-mesh makes before choosing its outputs, so that it never
  // writes over the .node a .poly reads its vertices from (a review: its
  // own check missed ".0" and CR-only files).
  for (const char* text : { "0 2 0 0\n", ".0 2 0 0\n", "# a\r0.0 2 0 0\r3 0\r",
         "\xEF\xBB\xBF# a\r\n\r\n  0e0 2 0 0", "+0\t2 0 0" })
  {
    std::istringstream in(text);
    EXPECT_TRUE(polyListsNoVertices(in)) << text;
  }
  for (const char* text :
    { "4 2 0 0\n", "", "# only a comment\n", "0x0 2 0 0\n", "0.5 2\n", "zero 2 0 0\n" })
  {
    std::istringstream in(text);
    EXPECT_FALSE(polyListsNoVertices(in)) << text;
  }
}

TEST(PolyReader, ZeroBasedNumbering)
{
  const PolyFile f = poly("3 2 0 0\n0 5 6\n1 7 8\n2 9 10\n2 0\n0 0 2\n1 2 1\n0\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.firstIndex, 0);
  EXPECT_EQ(f.pslg.points[0], (Point{ 5, 6 }));
  EXPECT_EQ(f.pslg.segments[0], (Segment{ 0, 2 }));
  EXPECT_EQ(f.pslg.segments[1], (Segment{ 2, 1 }));
}

TEST(PolyReader, OneBasedNumberingIsRenumberedFromZero)
{
  const PolyFile f = poly(squareWithHole);
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.firstIndex, 1);
  ASSERT_EQ(f.pslg.points.size(), 4u);
  EXPECT_EQ(f.pslg.points[3], (Point{ 0, 1 }));
  ASSERT_EQ(f.pslg.segments.size(), 4u);
  EXPECT_EQ(f.pslg.segments[0], (Segment{ 0, 1 }));
  EXPECT_EQ(f.pslg.segments[3], (Segment{ 3, 0 }));
}

TEST(PolyReader, NumberFormats)
{
  const PolyFile f = poly("5 2 0 0\n"
                          "1 1.5E+02 1.5e2\n"
                          "2 -.5 +3\n"
                          "3 0.418893E+02 -.000000E+00\n"
                          "4 2. 1e-400\n" // underflow reads as zero, like strtod
                          "5 -1.25E-1 7\n"
                          "+1 0\n"
                          "1 1 +2\n"
                          "0\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pslg.points[0], (Point{ 150, 150 }));
  EXPECT_EQ(f.pslg.points[1], (Point{ -0.5, 3 }));
  EXPECT_EQ(f.pslg.points[2].x, 41.8893);
  EXPECT_EQ(f.pslg.points[2].y, 0.0);
  EXPECT_EQ(f.pslg.points[3], (Point{ 2, 0 }));
  EXPECT_EQ(f.pslg.points[4], (Point{ -0.125, 7 }));
  EXPECT_EQ(f.pslg.segments[0], (Segment{ 0, 1 }));
}

TEST(PolyReader, AttributesAndMarkers)
{
  // Any nonzero marker flag means markers; absent attributes and markers read as 0
  // (as in triangle.c); tokens beyond what a line needs are ignored.
  const PolyFile f = poly("4 2 2 7\n"
                          "1 0 0 0.5 -2 11\n"
                          "2 1 0 1.5 3 12 99 extra\n"
                          "3 1 1 2.5\n"
                          "4 0 1\n"
                          "3 1\n"
                          "1 1 2 5\n"
                          "2 2 3 -6 extra tokens\n"
                          "3 3 4\n"
                          "0\n");
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pointAttributes.size(), 4u);
  EXPECT_EQ(f.pointAttributes[0], (std::vector<double>{ 0.5, -2 }));
  EXPECT_EQ(f.pointAttributes[1], (std::vector<double>{ 1.5, 3 }));
  EXPECT_EQ(f.pointAttributes[2], (std::vector<double>{ 2.5, 0 }));
  EXPECT_EQ(f.pointAttributes[3], (std::vector<double>{ 0, 0 }));
  EXPECT_EQ(f.pointMarkers, (std::vector<int>{ 11, 12, 0, 0 }));
  EXPECT_EQ(f.segmentMarkers, (std::vector<int>{ 5, -6, 0 }));
}

TEST(PolyReader, DeclaredAttributesLeftOutReadAsZeroWhateverTheFileLength)
{
  // A review: 3 vertices declaring 5 attributes and writing none were refused
  // as "cannot fit in the rest of the file", and read once a long comment
  // followed. Triangle reads them as 0; so does the reader, up to 2^20 values.
  const std::string text = "3 2 5 0\n1 0 0\n2 1 0\n3 0 1\n0 0\n0\n";
  for (const std::string& tail : { std::string(), "#" + std::string(100, 'x') + "\n" })
  {
    const PolyFile f = poly(text + tail);
    ASSERT_TRUE(f.ok) << f.error;
    ASSERT_EQ(f.pointAttributes.size(), 3u);
    EXPECT_EQ(f.pointAttributes[2], (std::vector<double>(5, 0.0)));
  }
  // Beyond 2^20 values the file must hold them.
  EXPECT_TRUE(failsAt(poly("3 2 400000 0\n1 0 0\n2 1 0\n3 0 1\n"), "t.poly:1",
    "3 vertices with 400000 attributes each cannot fit in the rest of the file"));
}

TEST(PolyReader, ZeroMarkerFlagsIgnoreExtraColumns)
{
  const PolyFile f = poly("3 2 0 0\n1 0 0 8\n2 1 0 8\n3 0 1 8\n1 0\n1 1 2 9\n0\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_TRUE(f.pointAttributes.empty());
  EXPECT_TRUE(f.pointMarkers.empty());
  EXPECT_TRUE(f.segmentMarkers.empty());
}

TEST(PolyReader, NegativeMarkerFlagsMeanMarkers)
{
  // Any nonzero flag, as in triangle.c (a mutation test: only positive ones
  // were tried).
  const PolyFile f = poly("3 2 0 -1\n1 0 0 8\n2 1 0 7\n3 0 1\n1 -2\n1 1 2 9\n0\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pointMarkers, (std::vector<int>{ 8, 7, 0 }));
  EXPECT_EQ(f.segmentMarkers, (std::vector<int>{ 9 }));
}

TEST(PolyReader, HeaderFieldsAfterTheCountAreOptional)
{
  // triangle.c defaults a missing dimension to 2 and missing counts of
  // attributes and markers to 0.
  const PolyFile f = poly("3\n1 0 0\n2 1 0\n3 0 1\n1\n1 1 2\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pslg.points.size(), 3u);
  EXPECT_EQ(f.pslg.segments.size(), 1u);
}

TEST(PolyReader, Holes)
{
  const PolyFile f = poly("3 2 0 0\n1 0 0\n2 9 0\n3 0 9\n0\n2\n1 1 1 ignored\n2 2.5 -1e1\n");
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pslg.holes.size(), 2u);
  EXPECT_EQ(f.pslg.holes[0], (Point{ 1, 1 }));
  EXPECT_EQ(f.pslg.holes[1], (Point{ 2.5, -10 }));
}

TEST(PolyReader, MissingHolesSectionMeansNoHoles)
{
  const PolyFile f = poly("3 2 0 0\n1 0 0\n2 9 0\n3 0 9\n1 0\n1 1 2\n# the end\n\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_TRUE(f.pslg.holes.empty());
  EXPECT_TRUE(f.pslg.regions.empty());
}

TEST(PolyReader, RegionalAttributesWithFourAndFiveTokens)
{
  const PolyFile f = poly(std::string(squareWithHole) +
    "3\n"
    "1 0.1 0.1 7 0.25\n"
    "2 0.9 0.1 0.05\n"
    "3 0.9 0.9 -1 -1 extra\n");
  ASSERT_TRUE(f.ok) << f.error;
  ASSERT_EQ(f.pslg.regions.size(), 3u);
  EXPECT_EQ(f.pslg.regions[0].seed, (Point{ 0.1, 0.1 }));
  EXPECT_EQ(f.pslg.regions[0].attribute, 7);
  EXPECT_EQ(f.pslg.regions[0].maxArea, 0.25);
  // One value: Triangle uses it as both the attribute and the area limit.
  EXPECT_EQ(f.pslg.regions[1].attribute, 0.05);
  EXPECT_EQ(f.pslg.regions[1].maxArea, 0.05);
  EXPECT_EQ(f.pslg.regions[2].attribute, -1);
  EXPECT_EQ(f.pslg.regions[2].maxArea, -1);
  ASSERT_EQ(f.pslg.holes.size(), 1u);
}

TEST(PolyReader, NodeText)
{
  const PolyFile f = node("# a node file\n3 2 1 1\n0 0 0 4 1\n1 2 0 5 0\n2 0 2 6 2\n");
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.firstIndex, 0);
  ASSERT_EQ(f.pslg.points.size(), 3u);
  EXPECT_EQ(f.pslg.points[2], (Point{ 0, 2 }));
  EXPECT_TRUE(f.pslg.segments.empty());
  EXPECT_EQ(f.pointAttributes[1], (std::vector<double>{ 5 }));
  EXPECT_EQ(f.pointMarkers, (std::vector<int>{ 1, 0, 2 }));
}

TEST(PolyReader, EmptyNodeTextAndTrailingLinesAreAccepted)
{
  const PolyFile empty = node("0 2 0 0\n");
  ASSERT_TRUE(empty.ok) << empty.error;
  EXPECT_TRUE(empty.pslg.points.empty());
  const PolyFile trailing = node("1 2 0 0\n1 3 4\nanything after the vertices\n");
  ASSERT_TRUE(trailing.ok) << trailing.error;
  EXPECT_EQ(trailing.pslg.points.size(), 1u);
}

TEST(PolyReader, ZeroVerticesTakesThemFromNodeStream)
{
  std::istringstream nodeText("# beside\n3 2 1 1\n1 0 0 0.5 7\n2 4 0 1.5 8\n3 0 4 2.5 9\n");
  const PolyFile f = poly("0 2 0 0\n3 0\n1 1 2\n2 2 3\n3 3 1\n1\n1 1 1\n", &nodeText);
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.firstIndex, 1);
  ASSERT_EQ(f.pslg.points.size(), 3u);
  EXPECT_EQ(f.pslg.points[1], (Point{ 4, 0 }));
  EXPECT_EQ(f.pslg.segments[2], (Segment{ 2, 0 }));
  EXPECT_EQ(f.pointAttributes[2], (std::vector<double>{ 2.5 }));
  EXPECT_EQ(f.pointMarkers, (std::vector<int>{ 7, 8, 9 }));
  EXPECT_EQ(f.pslg.holes.size(), 1u);
}

TEST(PolyReader, ZeroVerticesWithoutNodeTextIsAnError)
{
  EXPECT_TRUE(failsAt(poly("# c\n0 2 0 0\n1 0\n1 1 2\n0\n"), "t.poly:2",
    "the file lists 0 vertices, so they must come from a .node text, but none was given"));
}

TEST(PolyReader, ZeroVerticesReportsNodeTextErrorsAgainstTheNodeName)
{
  std::istringstream bad("3 2 0 0\n1 0 0\n2 0 zero\n3 1 1\n");
  EXPECT_TRUE(failsAt(poly("0 2 0 0\n0 0\n0\n", &bad), "t.node:3", "'zero'"));
  // Segments are checked against the vertices of the .node text.
  std::istringstream two("2 2 0 0\n0 0 0\n1 1 0\n");
  EXPECT_TRUE(failsAt(poly("0 2 0 0\n1 0\n5 0 2\n0\n", &two), "t.poly:3",
    "segment 5 refers to vertex 2, which does not exist"));
}

// --- Files -------------------------------------------------------------------------

class PolyReaderFiles : public ::testing::Test
{
protected:
  void SetUp() override
  {
    std::random_device random;
    dir_ = fs::temp_directory_path() / ("osm_polyreader_" + std::to_string(random()));
    fs::create_directories(dir_);
  }
  void TearDown() override
  {
    std::error_code ec;
    fs::remove_all(dir_, ec);
  }
  std::string write(const std::string& name, const std::string& text) const
  {
    const fs::path p = dir_ / name;
    std::ofstream(p, std::ios::binary) << text;
    return p.string();
  }
  fs::path dir_;
};

TEST_F(PolyReaderFiles, PolyWithZeroVerticesReadsTheNodeFileBesideIt)
{
  write("sq.node", "4 2 0 1\n0 0 0 1\n1 1 0 1\n2 1 1 1\n3 0 1 1\n");
  const std::string path = write("sq.poly", "0 2 0 0\n4 0\n0 0 1\n1 1 2\n2 2 3\n3 3 0\n0\n");
  const PolyFile f = readPolyFile(path);
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.firstIndex, 0);
  EXPECT_EQ(f.pslg.points.size(), 4u);
  EXPECT_EQ(f.pslg.segments.size(), 4u);
  EXPECT_EQ(f.pointMarkers.size(), 4u);
}

TEST_F(PolyReaderFiles, NodeFileAlone)
{
  const std::string path = write("pts.node", "2 2 0 0\n1 3 4\n2 5 6\n");
  const PolyFile f = readPolyFile(path);
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pslg.points.size(), 2u);
  EXPECT_TRUE(f.pslg.segments.empty());
}

TEST_F(PolyReaderFiles, ExtensionIsCaseInsensitive)
{
  const PolyFile f = readPolyFile(write("SQ.POLY", squareWithHole));
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pslg.holes.size(), 1u);
}

TEST_F(PolyReaderFiles, ErrorsNameTheFile)
{
  const std::string path = write("bad.poly", "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 4\n");
  EXPECT_TRUE(failsAt(readPolyFile(path), path + ":6", "refers to vertex 4"));
  const std::string nodePath = write("badnode.node", "2 2 0 0\n1 3 4\n2 5 inf\n");
  EXPECT_TRUE(failsAt(readPolyFile(nodePath), nodePath + ":3", "'inf'"));
}

TEST_F(PolyReaderFiles, MissingNodeFileIsReportedWithItsPath)
{
  const std::string path = write("lonely.poly", "# no vertices here\n0 2 0 0\n0 0\n0\n");
  const PolyFile f = readPolyFile(path);
  EXPECT_TRUE(failsAt(f, path + ":2", (dir_ / "lonely.node").string()));
}

TEST_F(PolyReaderFiles, NodeFileErrorsAreReportedAgainstTheNodeFile)
{
  const std::string nodePath = write("n.node", "2 3 0 0\n1 0 0\n2 1 1\n");
  const std::string path = write("n.poly", "0 2 0 0\n0 0\n");
  EXPECT_TRUE(failsAt(readPolyFile(path), nodePath + ":1", "dimension must be 2, not 3"));
}

TEST_F(PolyReaderFiles, UnreadableOrUnknownFiles)
{
  const std::string missing = (dir_ / "missing.poly").string();
  PolyFile f = readPolyFile(missing);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.error.rfind(missing + ": ", 0), 0u) << f.error;

  fs::create_directories(dir_ / "folder.poly");
  f = readPolyFile((dir_ / "folder.poly").string());
  EXPECT_FALSE(f.ok);
  EXPECT_NE(f.error.find("directory"), std::string::npos) << f.error;

  const std::string other = write("data.txt", squareWithHole);
  f = readPolyFile(other);
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.error.rfind(other + ": ", 0), 0u) << f.error;
  EXPECT_NE(f.error.find(".poly or .node"), std::string::npos) << f.error;

  EXPECT_FALSE(readPolyFile("").ok);
}

TEST(PolyReader, UnusableStreamIsAnError)
{
  std::ifstream closed("/nonexistent-osm-dir/closed.poly"); // failed to open: failbit set
  const PolyFile f = parsePoly(closed, "closed.poly");
  EXPECT_FALSE(f.ok);
  EXPECT_EQ(f.error.rfind("closed.poly: ", 0), 0u) << f.error;
}

// --- Errors, each with the exact line ------------------------------------------------

TEST(PolyReaderErrors, EmptyOrCommentOnly)
{
  EXPECT_TRUE(failsAt(poly(""), "t.poly:1", "empty"));
  EXPECT_TRUE(failsAt(poly("# a\n\n# b\n"), "t.poly:3", "empty"));
  EXPECT_TRUE(failsAt(node("   \n"), "t.node:1", "empty"));
}

TEST(PolyReaderErrors, TruncatedSectionsSayWhatWasExpectedAndFound)
{
  // Comments after the last item keep the cheap line bound from firing first.
  EXPECT_TRUE(failsAt(poly("# c\n4 2 0 0\n1 0 0\n2 1 0\n3 0 1\n#\n#\n#\n"), "t.poly:2",
    "vertex section truncated: 4 vertices announced, 3 found"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n#\n#\n"), "t.poly:5",
    "segment section truncated: 3 segments announced, 1 found"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n2\n1 0.1 0.1\n#\n"), "t.poly:6",
    "hole section truncated: 2 holes announced, 1 found"));
  EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "2\n1 0.5 0.5 1\n\n\n"), "t.poly:13",
    "region section truncated: 2 regions announced, 1 found"));
  EXPECT_TRUE(failsAt(node("3 2 0 0\n0 0 0\n# gone\n#\n"), "t.node:1",
    "vertex section truncated: 3 vertices announced, 1 found"));
}

TEST(PolyReaderErrors, ACountAboveTheItemsListedSaysSo)
{
  // Found by a Triangle user's review: 5 segments announced and 4 listed
  // read the holes' count line as a segment, and the error named a segment
  // 0 that the file does not have, with no word of the count.
  EXPECT_TRUE(failsAt(
    poly("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n5 0\n1 1 2\n2 2 3\n3 3 4\n4 4 1\n0\n"), "t.poly:11",
    "missing first endpoint of segment 0 (line 11 is read as segment 5 of the 5 segments line 6 "
    "announces: does the file list fewer than it announces?)"));
  EXPECT_TRUE(failsAt(poly("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 0\n1 1 2\n2 2 3\n3 3 "
                           "4\n4 4 1\n2\n1 0.5 0.5\n0\n"),
    "t.poly:13", "(line 13 is read as hole 2 of the 2 holes line 11 announces"));
  // After the vertices the next header is "<#segments> [<markers>]".
  EXPECT_TRUE(failsAt(poly("5 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n4 1\n1 1 2 0\n"), "t.poly:6",
    "(line 6 is read as vertex 5 of the 5 vertices line 1 announces"));
  // A malformed segment in a section of the right length gets no such hint.
  const PolyFile bad = poly("4 2 0 0\n1 0 0\n2 1 0\n3 1 1\n4 0 1\n2 0\n1 1 2\n2 2\n0\n");
  EXPECT_TRUE(failsAt(bad, "t.poly:8", "missing second endpoint of segment 2"));
  EXPECT_EQ(bad.error.find("announces"), std::string::npos) << bad.error;
}

TEST(PolyReaderErrors, MissingSegmentSection)
{
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n# end\n"), "t.poly:5",
    "the file ends where the number of segments was expected"));
}

TEST(PolyReaderErrors, NegativeCounts)
{
  EXPECT_TRUE(failsAt(poly("-3 2 0 0\n"), "t.poly:1", "negative number of vertices: -3"));
  EXPECT_TRUE(failsAt(poly("3 2 -1 0\n1 0 0\n2 1 0\n3 0 1\n"), "t.poly:1",
    "negative number of vertex attributes: -1"));
  EXPECT_TRUE(failsAt(
    poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n\n-1 0\n"), "t.poly:6", "negative number of segments: -1"));
  EXPECT_TRUE(failsAt(
    poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n-2\n"), "t.poly:6", "negative number of holes: -2"));
  EXPECT_TRUE(failsAt(
    poly(std::string(squareWithHole) + "-1\n"), "t.poly:13", "negative number of regions: -1"));
}

TEST(PolyReaderErrors, HugeCountsAreRefusedBeforeAllocating)
{
  EXPECT_TRUE(failsAt(poly("1000000 2 0 0\n1 0 0\n2 1 0\n"), "t.poly:1",
    "1000000 vertices announced, but only 2 lines follow"));
  EXPECT_TRUE(failsAt(poly("3000000000 2 0 0\n"), "t.poly:1", "too many vertices: 3000000000"));
  EXPECT_TRUE(failsAt(poly("99999999999999999999999 2 0 0\n"), "t.poly:1",
    "number of vertices is out of range: '99999999999999999999999'"));
  EXPECT_TRUE(failsAt(poly("3 2 1000000000 0\n1 0 0\n2 1 0\n3 0 1\n"), "t.poly:1",
    "3 vertices with 1000000000 attributes each cannot fit in the rest of the file"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n2000000000 0\n1 1 2\n"), "t.poly:5",
    "2000000000 segments announced, but only 1 line follows"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n123456789\n"), "t.poly:6",
    "123456789 holes announced, but only 0 lines follow"));
  EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "99999\n1 0 0 1\n"), "t.poly:13",
    "99999 regions announced"));
}

TEST(PolyReaderErrors, DimensionOtherThanTwo)
{
  EXPECT_TRUE(failsAt(
    poly("# 3-d\n3 3 0 0\n1 0 0 0\n2 1 0 0\n3 0 1 0\n"), "t.poly:2", "dimension must be 2, not 3"));
  EXPECT_TRUE(failsAt(node("1 1\n1 0\n"), "t.node:1", "dimension must be 2, not 1"));
}

TEST(PolyReaderErrors, TextWhereANumberBelongsIsQuoted)
{
  EXPECT_TRUE(failsAt(poly("three 2 0 0\n"), "t.poly:1",
    "expected an integer for the number of vertices, found 'three'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 abc 0\n3 0 1\n"), "t.poly:3",
    "expected a number for the x coordinate of vertex 2, found 'abc'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1.5D+02\n"), "t.poly:4",
    "y coordinate of vertex 3, found '1.5D+02'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1,5 0\n3 0 1\n"), "t.poly:3", "'1,5'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\nx2 1 0\n3 0 1\n"), "t.poly:3",
    "expected an integer for the vertex index, found 'x2'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 2.5 3\n"), "t.poly:6",
    "expected an integer for the first endpoint of segment 1, found '2.5'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 nan 3\n"), "t.poly:6",
    "expected an integer for the first endpoint of segment 1, found 'nan'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1e300 3\n"), "t.poly:6",
    "first endpoint of segment 1 is out of range: '1e300'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 0x1 3\n"), "t.poly:6", "'0x1'"));
  // One leading '+' is dropped as strtod drops it, not a second sign (a
  // mutation test: '+-1' read as -1).
  EXPECT_TRUE(failsAt(
    poly("3 2 0 0\n1 0 0\n2 +-1 0\n3 0 1\n"), "t.poly:3", "x coordinate of vertex 2, found '+-1'"));
  EXPECT_TRUE(failsAt(
    poly("3 2 0 0\n1 0 0\n2 1 ++1\n3 0 1\n"), "t.poly:3", "y coordinate of vertex 2, found '++1'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 +-1 3\n"), "t.poly:6",
    "first endpoint of segment 1, found '+-1'"));
  EXPECT_TRUE(failsAt(poly("2 2 0 1\n1 0 0 a\n2 1 0\n"), "t.poly:2",
    "expected an integer for the boundary marker of vertex 1, found 'a'"));
  EXPECT_TRUE(
    failsAt(poly("2 2 1 0\n1 0 0 1\n2 1 0 q\n"), "t.poly:3", "attribute of vertex 2, found 'q'"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 0.5 half\n"), "t.poly:7",
    "y coordinate of hole 1, found 'half'"));
  EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "1\n1 0.5 0.5 big\n"), "t.poly:14",
    "attribute of region 1, found 'big'"));
  EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "1\n1 0.5 0.5 1 max\n"), "t.poly:14",
    "maximum area of region 1, found 'max'"));
  // Control bytes are escaped and long tokens cut short, so messages stay readable.
  EXPECT_TRUE(failsAt(poly(std::string("1 2 0 0\n1 \x01\x7f 0\n")), "t.poly:2", "'\\x01\\x7F'"));
  EXPECT_TRUE(failsAt(poly("1 2 0 0\n1 " + std::string(100, 'z') + " 0\n"), "t.poly:2",
    "'" + std::string(40, 'z') + "...'"));
}

TEST(PolyReaderErrors, NonFiniteNumbersAreRefused)
{
  for (const char* bad : { "nan", "NaN", "inf", "-inf", "infinity", "-INF", "1e999" })
  {
    const std::string quoted = std::string("'") + bad + "'";
    EXPECT_TRUE(failsAt(poly(std::string("3 2 0 0\n1 0 0\n2 ") + bad + " 0\n3 0 1\n"), "t.poly:3",
      "x coordinate of vertex 2 is not a finite number: " + quoted));
    EXPECT_TRUE(failsAt(poly(std::string("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n0\n1\n1 0 ") + bad + "\n"),
      "t.poly:7", "y coordinate of hole 1 is not a finite number: " + quoted));
    EXPECT_TRUE(failsAt(poly(std::string("1 2 1 0\n1 0 0 ") + bad + "\n"), "t.poly:2",
      "attribute of vertex 1 is not a finite number"));
    EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "1\n1 0.5 0.5 " + bad + "\n"),
      "t.poly:14", "attribute of region 1 is not a finite number"));
  }
}

TEST(PolyReaderErrors, SegmentEndpointOutOfRange)
{
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n3 0\n1 1 2\n2 2 40\n3 3 1\n0\n"),
    "t.poly:7", "segment 2 refers to vertex 40, which does not exist"));
  // 1-based files have no vertex 0; 0-based files have no vertex n.
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n7 0 1\n0\n"), "t.poly:6",
    "segment 7 refers to vertex 0, which does not exist"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 1 3\n0\n"), "t.poly:6",
    "segment 0 refers to vertex 3, which does not exist (vertices are numbered 0 to 2)"));
  EXPECT_TRUE(failsAt(
    poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 -1 2\n0\n"), "t.poly:6", "refers to vertex -1"));
  // No vertices at all (a .node listing none): not "numbered 0 to -1" (a review).
  std::istringstream noVertices("0 2 0 0\n");
  EXPECT_TRUE(failsAt(poly("0 2 0 0\n1 0\n1 1 2\n0\n", &noVertices), "t.poly:3",
    "segment 1 refers to vertex 1, which does not exist (there are no vertices)"));
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n0 0 0\n1 1 0\n2 0 1\n1 0\n0 99999999999 2\n0\n"), "t.poly:6",
    "refers to vertex 99999999999"));
}

TEST(PolyReaderErrors, VertexIndicesMustBeConsecutive)
{
  EXPECT_TRUE(failsAt(poly("3 2 0 0\n1 0 0\n\n# gap\n3 1 0\n2 0 1\n"), "t.poly:5",
    "vertex index 3 is out of sequence, expected 2"));
  EXPECT_TRUE(failsAt(node("3 2 0 0\n0 0 0\n1 1 0\n1 0 1\n"), "t.node:4",
    "vertex index 1 is out of sequence, expected 2"));
  EXPECT_TRUE(failsAt(poly("# c\n2 2 0 0\n2 0 0\n3 1 0\n"), "t.poly:3",
    "the first vertex must be numbered 0 or 1, not 2"));
}

TEST(PolyReaderErrors, MissingFields)
{
  EXPECT_TRUE(
    failsAt(poly("2 2 0 0\n1 0 0\n2 1\n"), "t.poly:3", "missing y coordinate of vertex 2"));
  EXPECT_TRUE(failsAt(
    poly("2 2 0 0\n1 0 0\n2 1 0\n1 0\n1 1\n"), "t.poly:5", "missing second endpoint of segment 1"));
  EXPECT_TRUE(failsAt(
    poly("2 2 0 0\n1 0 0\n2 1 0\n0\n1\n1 0.5\n"), "t.poly:6", "missing y coordinate of hole 1"));
  EXPECT_TRUE(failsAt(poly(std::string(squareWithHole) + "1\n1 0.5 0.5\n"), "t.poly:14",
    "missing attribute of region 1"));
}

TEST(PolyReaderErrors, MarkerOutOfIntRange)
{
  EXPECT_TRUE(failsAt(poly("2 2 0 1\n1 0 0 1\n2 1 0 4294967296\n"), "t.poly:3",
    "boundary marker of vertex 2 is out of range: '4294967296'"));
}

TEST(PolyReaderErrors, FailureLeavesNoPartialData)
{
  const PolyFile f = poly("3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n");
  EXPECT_FALSE(f.ok);
  EXPECT_TRUE(f.pslg.points.empty());
  EXPECT_TRUE(f.pslg.segments.empty());
}

// Every prefix and many one-byte corruptions of a rich file: no crash, no throw, and
// either a result or a located error (run under the sanitizers to make this bite).
TEST(PolyReaderErrors, CorruptedInputNeverCrashes)
{
  const std::string good = "# rich\n4 2 2 1\n1 0 0 0.5 1 3\n2 1 0 1.5 2 3\n3 1 1 2 3 3\n"
                           "4 0 1 4 5 3\n4 1\n1 1 2 7\n2 2 3 7\n3 3 4 7\n4 4 1 7\n1\n"
                           "1 0.5 0.5\n2\n1 0.1 0.1 3 0.2\n2 0.9 0.9 4\n";
  ASSERT_TRUE(poly(good).ok) << poly(good).error;
  auto check = [](const std::string& text) {
    const PolyFile f = poly(text);
    if (!f.ok)
    {
      EXPECT_EQ(f.error.rfind("t.poly:", 0), 0u) << f.error;
    }
  };
  for (std::size_t n = 0; n <= good.size(); ++n)
    check(good.substr(0, n));
  for (std::size_t i = 0; i < good.size(); ++i)
    for (const char c : { 'x', '#', '\n', '-', '9', '\0', ' ', '.', 'e' })
    {
      std::string text = good;
      text[i] = c;
      check(text);
    }
}

// --- Real data -----------------------------------------------------------------------

class PolyReaderData : public ::testing::Test
{
protected:
  void SetUp() override
  {
    // The tests below read these by name.
    for (const char* name : { "la.poly", "A.poly", "face.poly", "aust.poly" })
      if (!fs::is_regular_file(dir() / name))
        GTEST_SKIP() << "no " << name << " in " << dir() << "; real-data reader tests skipped";
  }
  static fs::path dir() { return shared_data::folder(); }
  static PolyFile read(const std::string& name) { return readPolyFile((dir() / name).string()); }
};

TEST_F(PolyReaderData, EveryPolyFileParses)
{
  std::size_t count = 0;
  for (const fs::path& file : shared_data::polyFiles())
  {
    ++count;
    const PolyFile f = readPolyFile(file.string());
    EXPECT_TRUE(f.ok) << f.error;
    EXPECT_GT(f.pslg.points.size(), 0u) << file;
  }
  EXPECT_GT(count, 0u) << "no .poly files in " << dir();
}

TEST_F(PolyReaderData, ExactCounts)
{
  struct Expected
  {
    const char* name;
    std::size_t vertices, segments, holes, regions;
  };
  const Expected table[] = {
    { "clusters.poly", 13, 12, 0, 0 },
    { "face.poly", 26, 22, 3, 0 },
    { "A.poly", 29, 29, 1, 0 },
    { "fish-and-rectangle.poly", 31, 44, 3, 0 },
    { "double_hex.poly", 96, 96, 2, 0 },
    { "airfoil_exterior.poly", 105, 105, 1, 0 },
    { "la.poly", 141, 148, 0, 6 },
    { "guitar.poly", 144, 144, 3, 0 },
    { "lake_superior.poly", 518, 518, 6, 0 },
    { "square_circle_hole.poly", 826, 135, 1, 0 },
  };
  for (const Expected& e : table)
  {
    SCOPED_TRACE(e.name);
    const PolyFile f = read(e.name);
    ASSERT_TRUE(f.ok) << f.error;
    EXPECT_EQ(f.pslg.points.size(), e.vertices);
    EXPECT_EQ(f.pslg.segments.size(), e.segments);
    EXPECT_EQ(f.pslg.holes.size(), e.holes);
    EXPECT_EQ(f.pslg.regions.size(), e.regions);
  }
}

TEST_F(PolyReaderData, DetailsOfSelectedFiles)
{
  // la.poly: exponent notation, markers, and 4-token region lines "1 6 -0.2 0.05".
  const PolyFile la = read("la.poly");
  ASSERT_TRUE(la.ok) << la.error;
  EXPECT_EQ(la.firstIndex, 1);
  EXPECT_EQ(la.pslg.points[1], (Point{ 41.8893, 0 }));
  EXPECT_EQ(la.pointMarkers[0], 101);
  EXPECT_EQ(la.pslg.regions[0].seed, (Point{ 6, -0.2 }));
  EXPECT_EQ(la.pslg.regions[0].attribute, 0.05);
  EXPECT_EQ(la.pslg.regions[0].maxArea, 0.05);
  // A.poly has one attribute per vertex; face.poly has markers and trailing comments.
  const PolyFile a = read("A.poly");
  ASSERT_TRUE(a.ok) << a.error;
  EXPECT_EQ(a.pointAttributes[0], (std::vector<double>{ -0.57 }));
  const PolyFile face = read("face.poly");
  ASSERT_TRUE(face.ok) << face.error;
  EXPECT_EQ(face.pslg.holes[2], (Point{ 50, 50 }));
  EXPECT_EQ(face.segmentMarkers.size(), 22u);
}

TEST_F(PolyReaderData, DerivedFilesParse)
{
  for (const char* name : { "img5.poly", "airfoil.poly", "Constrained_Sweden.poly",
         "nazca_monkey.poly", "water-huge3.poly", "us48.poly", "aust.poly" })
  {
    SCOPED_TRACE(name);
    const PolyFile f = read(name);
    ASSERT_TRUE(f.ok) << f.error;
    EXPECT_GT(f.pslg.points.size(), 0u);
    EXPECT_GT(f.pslg.segments.size(), 0u);
  }
}

// Reports the read time; speed is measured by the benchmarks, never asserted here.
TEST_F(PolyReaderData, ReadsTheLargestFile)
{
  const auto start = std::chrono::steady_clock::now();
  const PolyFile f = read("aust.poly");
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  ASSERT_TRUE(f.ok) << f.error;
  EXPECT_EQ(f.pslg.points.size(), 85853u);
  std::printf("reading aust.poly (3.5 MB) took %.1f ms\n", seconds * 1000.0);
  RecordProperty("aust_read_ms", std::to_string(seconds * 1000.0));
  EXPECT_EQ(f.pslg.segments.size(), 81396u);
}
