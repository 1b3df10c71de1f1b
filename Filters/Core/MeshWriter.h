// Writing a meshing result for people and tools outside VTK: Triangle's
// .node/.ele/.edge files, an SVG drawing, and the statistics as JSON.
#ifndef osm_MeshWriter_h
#define osm_MeshWriter_h

#include "Mesher.h"

#include <ostream>
#include <string>
#include <vector>

namespace osm
{

/// What the .node file gives each vertex besides its coordinates, as
/// Triangle writes its vertex attributes and boundary markers, and the
/// .edge file's markers of the input subsegments.
struct NodeData
{
  std::size_t attributeCount = 0; ///< per vertex
  std::vector<double> attributes; ///< vertex-major: attributeCount per vertex
  /// Per vertex; empty: 1 on the mesh's boundary, 0 elsewhere (Triangle's
  /// markers for input without any).
  std::vector<int> markers;
  /// Per entry of Result::edges: the .edge marker of the mesh edge it is
  /// when an input subsegment; empty: 0 (then boundary edges 1).
  std::vector<int> edgeMarkers;
  /// The number of the first node, element and edge: 1, or 0 as in an input
  /// file that counts from 0 (Triangle numbers its output as its input).
  int firstIndex = 1;
  /// Whether to write base.poly too, and the holes and regions it lists (the
  /// input's, in the mesh's coordinates).
  bool writePoly = true;
  std::vector<Point> holes;
  std::vector<RegionAttribute> regions;
};

/// Write base.node, base.ele and base.edge (numbered from data.firstIndex),
/// and with data.writePoly base.poly, as Triangle's -p does.
/// Vertices no triangle uses are written too (Triangle writes duplicate input
/// vertices and those in holes unless -j).
/// The .edge file lists every mesh edge with Triangle's boundary marker: an
/// input subsegment's nonzero marker (from edgeMarkers; without them, input
/// without markers to Triangle), else 1 on the mesh's boundary (the holes'
/// included), else 0. The .poly file lists no vertices (they are base.node's)
/// and as segments the mesh edges that are input subsegments or on its
/// boundary, with the same markers, then data's holes and regions: the
/// constraints to mesh or refine again (Triangle's -r reads them). Returns an
/// empty string or the reason it failed (node data of the wrong size among
/// them).
std::string writeTriangleFiles(
  const std::string& base, const Result& result, const NodeData& data = {});

/// Draw the mesh: triangles thin, input segments bold, discarded overlay edges dashed.
void writeSvg(std::ostream& out, const Result& result);

/// Every statistic and the warnings as one JSON object.
void writeStatisticsJson(std::ostream& out, const Result& result);

} // namespace osm

#endif
