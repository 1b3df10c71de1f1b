// Reading Triangle's .poly and .node files into a Pslg.
#ifndef osm_PolyReader_h
#define osm_PolyReader_h

#include "Pslg.h"

#include <istream>
#include <string>
#include <vector>

namespace osm
{

struct PolyFile
{
  bool ok = false;
  /// On failure: "<file>:<line>: <reason>", e.g. "a.poly:12: segment 4 refers to vertex 40, which
  /// does not exist (vertices are numbered 1 to 9)".
  std::string error;
  Pslg pslg;          ///< points renumbered from 0 in file order; holes and regions from the file
  int firstIndex = 0; ///< 0 or 1: the numbering the file used
  std::vector<std::vector<double>> pointAttributes; ///< per point (may be empty)
  std::vector<int> pointMarkers;                    ///< per point, empty if the file has none
  std::vector<int> segmentMarkers;                  ///< per segment, empty if the file has none
};

/// Read a .poly file (with a .node beside it when the .poly lists zero vertices)
/// or a .node file (points only). Never throws. The extension (.poly or .node, any case)
/// selects the format; other extensions and unreadable files give an error naming the path.
PolyFile readPolyFile(const std::string& path);

/// Parse .poly text from a stream; name is used in error messages. If the text lists
/// zero vertices, nodeText (the .node content) supplies them; without it that is an error.
/// Errors in nodeText are reported under name with its extension replaced by ".node".
PolyFile parsePoly(std::istream& in, const std::string& name, std::istream* nodeText = nullptr);

/// Parse .node text (points, attributes, markers).
PolyFile parseNode(std::istream& in, const std::string& name);

/// Whether .poly text lists zero vertices (and so reads them from the .node
/// beside it), its first data line read as parsePoly reads it: comments, a
/// byte order mark, any line ends, a count written "0", "0.0" or ".0".
bool polyListsNoVertices(std::istream& in);

} // namespace osm

#endif
