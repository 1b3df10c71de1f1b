// Writing a meshing result for people and tools outside VTK: Triangle's
// .node/.ele/.edge files, an SVG drawing, and the statistics as JSON.
#ifndef osm_MeshWriter_h
#define osm_MeshWriter_h

#include "Mesher.h"

#include <ostream>
#include <string>

namespace osm
{

/// Write base.node, base.ele and base.edge (1-based, as Triangle writes them).
/// The .edge file lists the input subsegments with boundary marker 1 and the
/// other mesh edges with 0. Returns an empty string or the reason it failed.
std::string writeTriangleFiles(const std::string& base, const Result& result);

/// Draw the mesh: triangles thin, input segments bold, discarded overlay edges dashed.
void writeSvg(std::ostream& out, const Result& result);

/// Every statistic and the warnings as one JSON object.
void writeStatisticsJson(std::ostream& out, const Result& result);

} // namespace osm

#endif
