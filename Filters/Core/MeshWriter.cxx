#include "MeshWriter.h"

#include "NumberText.h"
#include "OutputFile.h"
#include "TriangleMarkers.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <locale>
#include <string>
#include <system_error>
#include <vector>

namespace osm
{

namespace
{

/// %.17g: every double read back exactly, in any locale.
std::string exact(double x)
{
  return generalText(x, 17);
}

/// Per mesh edge (of edges), the entry of Result::edges that is the input
/// subsegment on it, -1 for none.
std::vector<int> inputSubsegments(const Result& r, const MeshEdges& edges)
{
  // Input subsegments are recorded against the edge vertices: map by
  // coordinates, to vertices of triangles (an unused one may share them).
  std::vector<char> used(r.mesh.vertices.size(), 0);
  for (const Triangle& t : r.mesh.triangles)
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  std::vector<std::pair<Point, int>> byPoint;
  for (std::size_t v = 0; v < r.mesh.vertices.size(); ++v)
    if (used[v])
      byPoint.push_back({ r.mesh.vertices[v], static_cast<int>(v) });
  std::sort(
    byPoint.begin(), byPoint.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  auto find = [&](const Point& p) {
    auto it = std::lower_bound(
      byPoint.begin(), byPoint.end(), p, [](const auto& a, const Point& q) { return a.first < q; });
    return it != byPoint.end() && it->first == p ? it->second : -1;
  };
  std::vector<int> subsegment(edges.size(), -1);
  for (std::size_t i = 0; i < r.edges.size(); ++i)
  {
    const Edge& e = r.edges[i];
    if (!(e.flags & EdgeInput))
      continue;
    const std::size_t k = edges.find(find(r.edgeVertices[e.a]), find(r.edgeVertices[e.b]));
    if (k < edges.size())
      subsegment[k] = static_cast<int>(i);
  }
  return subsegment;
}

/// Base.poly's text: no vertices (base.node's), the segments (with their
/// markers), holes and regions.
void writePolyFile(std::ostream& poly, const MeshEdges& edges, const std::vector<int>& subsegment,
  const std::vector<int>& marker, const NodeData& data)
{
  const std::size_t first = data.firstIndex == 0 ? 0 : 1;
  std::vector<std::size_t> segments;
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (subsegment[e] >= 0 || edges.onBoundary(e))
      segments.push_back(e);
  poly << "# the mesh's input subsegments and boundary edges; its vertices are in the .node\n"
       << "0 2 0 1\n"
       << segments.size() << " 1\n";
  for (std::size_t k = 0; k < segments.size(); ++k)
  {
    const std::size_t e = segments[k];
    poly << k + first << ' ' << edges.lower(e) + first << ' ' << edges.higher(e) + first << ' '
         << marker[e] << '\n';
  }
  poly << data.holes.size() << '\n';
  for (std::size_t h = 0; h < data.holes.size(); ++h)
  {
    poly << h + first << ' ' << exact(data.holes[h].x) << ' ' << exact(data.holes[h].y) << '\n';
  }
  if (data.regions.empty())
    return;
  poly << data.regions.size() << '\n';
  for (std::size_t i = 0; i < data.regions.size(); ++i)
  {
    const RegionAttribute& region = data.regions[i];
    poly << i + first << ' ' << exact(region.seed.x) << ' ' << exact(region.seed.y) << ' '
         << exact(region.attribute) << ' ' << exact(region.maxArea) << '\n';
  }
}

} // namespace

std::string writeTriangleFiles(const std::string& base, const Result& r, const NodeData& data)
{
  const std::size_t n = r.mesh.vertices.size();
  if (data.attributes.size() != n * data.attributeCount ||
    (!data.markers.empty() && data.markers.size() != n) ||
    (!data.edgeMarkers.empty() && data.edgeMarkers.size() != r.edges.size()))
    return "internal error: vertex attributes or markers for " + base +
      ".node do not match its vertices";
  // Opened one by one, so that a failure names its file and reason; what
  // the write made or changed is then removed (a user review: empty files
  // were left), through a symbolic link the file it names, not the link (a
  // second review: links were removed, their files left rewritten).
  const int count = data.writePoly ? 4 : 3;
  const std::string names[4] = { base + ".node", base + ".ele", base + ".edge", base + ".poly" };
  const OutputFile before[4] = { OutputFile(names[0]), OutputFile(names[1]), OutputFile(names[2]),
    OutputFile(names[3]) };
  std::ofstream files[4];
  const auto failed = [&](int k, int error) {
    for (std::ofstream& file : files)
      file.close();
    bool removed = false;
    for (int j = 0; j < count; ++j) // base.poly only when written (it may be the input)
      removed = before[j].removeIfWritten() || removed;
    return "cannot write " + names[k] + ": " +
      (error != 0 ? std::generic_category().message(error) : std::string("failed")) +
      (removed ? " (the partial files are removed)" : "");
  };
  for (int k = 0; k < count; ++k)
  {
    errno = 0;
    files[k].open(names[k]);
    if (!files[k])
      return failed(k, errno);
    files[k].imbue(std::locale::classic()); // no digit grouping from a host's global locale
  }
  std::ofstream &node = files[0], &ele = files[1], &edge = files[2];
  const MeshEdges edges(r.mesh);
  const std::vector<int> subsegment = inputSubsegments(r, edges);
  std::vector<int> marker(edges.size(), 0); // .edge's, Triangle's boundary markers
  for (std::size_t e = 0; e < edges.size(); ++e)
    marker[e] = boundaryMarker(subsegment[e] >= 0 && !data.edgeMarkers.empty()
        ? data.edgeMarkers[static_cast<std::size_t>(subsegment[e])]
        : 0,
      edges.onBoundary(e));
  const std::size_t first = data.firstIndex == 0 ? 0 : 1;
  node << n << " 2 " << data.attributeCount << " 1\n";
  for (std::size_t v = 0; v < n; ++v)
  {
    node << v + first << ' ' << exact(r.mesh.vertices[v].x) << ' ' << exact(r.mesh.vertices[v].y);
    for (std::size_t k = 0; k < data.attributeCount; ++k)
      node << ' ' << exact(data.attributes[v * data.attributeCount + k]);
    node << ' '
         << (data.markers.empty() ? boundaryMarker(0, edges.vertexOnBoundary(int(v)))
                                  : data.markers[v])
         << '\n';
  }
  // Attributes: the regional attribute first when there is one (as Triangle's
  // -A writes it), then the region id.
  const bool attributes =
    r.regionAttribute.size() == r.mesh.triangles.size() && !r.regionAttribute.empty();
  ele << r.mesh.triangles.size() << (attributes ? " 3 2\n" : " 3 1\n");
  for (std::size_t t = 0; t < r.mesh.triangles.size(); ++t)
  {
    ele << t + first << ' ' << r.mesh.triangles[t][0] + first << ' '
        << r.mesh.triangles[t][1] + first << ' ' << r.mesh.triangles[t][2] + first << ' ';
    if (attributes)
    {
      ele << exact(r.regionAttribute[t]) << ' ';
    }
    ele << r.regionId[t] << '\n';
  }
  edge << edges.size() << " 1\n";
  for (std::size_t e = 0; e < edges.size(); ++e)
    edge << e + first << ' ' << edges.lower(e) + first << ' ' << edges.higher(e) + first << ' '
         << marker[e] << '\n';
  if (data.writePoly)
    writePolyFile(files[3], edges, subsegment, marker, data);
  for (int k = 0; k < count; ++k)
  {
    // A full disk shows when a buffer is flushed, at the latest on closing.
    errno = 0;
    files[k].close();
    if (!files[k])
      return failed(k, errno);
  }
  return std::string();
}

void writeSvg(std::ostream& out, const Result& r)
{
  double x0 = 0, y0 = 0, x1 = 1, y1 = 1;
  if (!r.mesh.vertices.empty())
  {
    x0 = x1 = r.mesh.vertices[0].x;
    y0 = y1 = r.mesh.vertices[0].y;
  }
  for (const Point& p : r.mesh.vertices)
  {
    x0 = std::min(x0, p.x);
    x1 = std::max(x1, p.x);
    y0 = std::min(y0, p.y);
    y1 = std::max(y1, p.y);
  }
  // Map to an 1000-unit-wide picture, y up.
  const double size = std::max({ x1 - x0, y1 - y0, 1e-300 }), scale = 1000.0 / size;
  const double w = (x1 - x0) * scale + 20, h = (y1 - y0) * scale + 20;
  auto X = [&](const Point& p) { return 10 + (p.x - x0) * scale; };
  auto Y = [&](const Point& p) { return 10 + (y1 - p.y) * scale; };
  out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << fixedText(w, 0) << "\" height=\""
      << fixedText(h, 0) << "\" viewBox=\"0 0 " << fixedText(w, 3) << ' ' << fixedText(h, 3)
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  auto line = [&](const Point& a, const Point& b, const char* style) {
    out << "<line x1=\"" << fixedText(X(a), 3) << "\" y1=\"" << fixedText(Y(a), 3) << "\" x2=\""
        << fixedText(X(b), 3) << "\" y2=\"" << fixedText(Y(b), 3) << "\" " << style << "/>\n";
  };
  out << "<g id=\"mesh\">\n";
  const MeshEdges edges(r.mesh);
  const std::vector<int> input = inputSubsegments(r, edges);
  for (std::size_t e = 0; e < edges.size(); ++e)
    if (input[e] < 0) // drawn bold below
      line(r.mesh.vertices[edges.lower(e)], r.mesh.vertices[edges.higher(e)],
        "stroke=\"#4a6fa5\" stroke-width=\"0.4\"");
  out << "</g>\n<g id=\"discarded\">\n";
  for (const Edge& e : r.edges)
    if (e.flags & EdgeDiscarded)
      line(r.edgeVertices[e.a], r.edgeVertices[e.b],
        "stroke=\"#d62728\" stroke-width=\"0.6\" stroke-dasharray=\"3,2\"");
  out << "</g>\n<g id=\"input\">\n";
  for (const Edge& e : r.edges)
    if (e.flags & EdgeInput)
      line(r.edgeVertices[e.a], r.edgeVertices[e.b], "stroke=\"black\" stroke-width=\"2\"");
  out << "</g>\n</svg>\n";
}

namespace
{

std::string jsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
      out += '\\';
    if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", c);
      out += buf;
      continue;
    }
    out += c;
  }
  return out + "\"";
}

} // namespace

void writeStatisticsJson(std::ostream& out, const Result& r)
{
  out << "{\n  \"ok\": " << (r.ok ? "true" : "false") << ",\n";
  if (!r.ok)
    out << "  \"error\": " << jsonString(r.error) << ",\n";
  for (const auto& [name, value] : r.stats.items())
    out << "  " << jsonString(name) << ": " << exact(std::isfinite(value) ? value : 0.0) << ",\n";
  out << "  \"Warnings\": [";
  for (std::size_t i = 0; i < r.warnings.size(); ++i)
    out << (i ? ", " : "") << jsonString(r.warnings[i]);
  out << "]\n}\n";
}

} // namespace osm
