// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Test helper for the osm-mesh tests and the consumer test.
//
//   osm_cli_helper validate INPUT MESH [--allow-missing] [--max-angle A] [--max-edge H]
//                   [--area A] [--domain D]
//     Reads the input PSLG (.poly/.node with the core's reader, .vtp/.vtk
//     with VTK's readers: lines, polylines and polygon edges are segments)
//     and a mesh (.vtp, .vtu, .vtk with VTK's readers, or Triangle's
//     .node + .ele, 1-based), and checks the mesh with the core's independent
//     validator osm::validate. Input points are matched to mesh vertices by
//     their coordinates; every input point must be present unless
//     --allow-missing (holes and the enclosed domain leave points out).
//     With --max-edge, no edge may be longer than H; with --area, the
//     triangles' total area must also be A (holes honoured); with --domain
//     (enclosed, hull or box), the mesh's boundary must run along the input
//     segments (or the hull's or the mesh's bounding rectangle's edges) and
//     no hole seed may lie inside a triangle (the validator's check 9).
//     Prints one summary line; exit 0 iff the mesh is valid.
//
//   osm_cli_helper reader DATA_DIR OUT_DIR
//     The output contract of vtkTrianglePolyReader (arrays, cells, pieces,
//     errors) on Testing/Data files.
//
//   osm_cli_helper reference INPUT OUTPUT.vtp [--domain N] [--min-angle A]
//     The C++ pipeline osm-mesh is meant to be: vtkTrianglePolyReader (or
//     VTK's readers) -> vtkOverlayStitchMesher (Edges on, Overlay off) ->
//     vtkXMLPolyDataWriter (zlib level 1), timings left out of the field data.
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkOverlayStitchMesher.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkSmartPointer.h"
#include "vtkTrianglePolyReader.h"
#include "vtkUnstructuredGrid.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridReader.h"

#include "PolyReader.h"
#include "Validate.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace
{

std::string Extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  std::string ext = dot == std::string::npos ? std::string() : path.substr(dot);
  for (char& c : ext)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return ext;
}

[[noreturn]] void Die(const std::string& message)
{
  std::cerr << "osm_cli_helper: " << message << "\n";
  std::exit(2);
}

vtkSmartPointer<vtkPolyData> ReadVtkPolyData(const std::string& path)
{
  if (Extension(path) == ".vtp")
  {
    vtkNew<vtkXMLPolyDataReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    return reader->GetOutput();
  }
  vtkNew<vtkPolyDataReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  return reader->GetOutput();
}

osm::Pslg ReadInput(const std::string& path)
{
  const std::string ext = Extension(path);
  if (ext == ".poly" || ext == ".node")
  {
    osm::PolyFile file = osm::readPolyFile(path);
    if (!file.ok)
    {
      Die(file.error);
    }
    return file.pslg;
  }
  vtkSmartPointer<vtkPolyData> data = ReadVtkPolyData(path);
  osm::Pslg pslg;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    pslg.points.push_back({ p[0], p[1] });
  }
  auto add = [&pslg](vtkCellArray* cells, bool closed) {
    auto it = vtk::TakeSmartPointer(cells->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        if (ids[k] != ids[k + 1])
        {
          pslg.segments.push_back({ static_cast<int>(ids[k]), static_cast<int>(ids[k + 1]) });
        }
      }
      if (closed && n > 2 && ids[n - 1] != ids[0])
      {
        pslg.segments.push_back({ static_cast<int>(ids[n - 1]), static_cast<int>(ids[0]) });
      }
    }
  };
  add(data->GetLines(), false);
  add(data->GetPolys(), true);
  return pslg;
}

struct Mesh
{
  osm::Array<osm::Point> vertices;
  osm::Array<osm::Triangle> triangles;
};

/// The mesh without the vertices no triangle uses: a .node file lists the
/// input's duplicate points and those in holes too, as Triangle's does.
Mesh WithoutUnusedVertices(const Mesh& mesh)
{
  std::vector<int> index(mesh.vertices.size(), -1);
  Mesh used;
  for (const osm::Triangle& t : mesh.triangles)
  {
    osm::Triangle renumbered;
    for (int k = 0; k < 3; ++k)
    {
      int& i = index[static_cast<std::size_t>(t[k])];
      if (i < 0)
      {
        i = static_cast<int>(used.vertices.size());
        used.vertices.push_back(mesh.vertices[static_cast<std::size_t>(t[k])]);
      }
      renumbered[k] = i;
    }
    used.triangles.push_back(renumbered);
  }
  return used;
}

/// Triangle's .node + .ele, numbered from 0 or 1 (as the input), as
/// osm-mesh writes them.
Mesh ReadTriangleFiles(const std::string& nodePath)
{
  Mesh mesh;
  osm::PolyFile nodes = osm::readPolyFile(nodePath);
  if (!nodes.ok)
  {
    Die(nodes.error);
  }
  const long long first = nodes.firstIndex;
  if (first != 0 && first != 1)
  {
    Die(nodePath + ": numbered from " + std::to_string(first) + ", not 0 or 1");
  }
  mesh.vertices = nodes.pslg.points;
  const std::string elePath = nodePath.substr(0, nodePath.size() - 5) + ".ele";
  std::ifstream ele(elePath);
  if (!ele)
  {
    Die("cannot open " + elePath);
  }
  long long count = 0, corners = 0, attributes = 0;
  if (!(ele >> count >> corners >> attributes) || corners != 3 || count < 0)
  {
    Die(elePath + ": bad header");
  }
  for (long long t = 0; t < count; ++t)
  {
    long long index = 0, a = 0, b = 0, c = 0;
    if (!(ele >> index >> a >> b >> c) || index != t + first)
    {
      Die(elePath + ": bad triangle line " + std::to_string(t + 1));
    }
    const long long n = static_cast<long long>(mesh.vertices.size());
    for (long long v : { a, b, c })
    {
      if (v < first || v >= n + first)
      {
        Die(elePath + ": triangle " + std::to_string(index) + " refers to vertex " +
          std::to_string(v) + " of " + std::to_string(first) + ".." +
          std::to_string(n + first - 1));
      }
    }
    for (long long k = 0; k < attributes; ++k)
    {
      double value = 0;
      if (!(ele >> value))
      {
        Die(elePath + ": missing attribute on triangle " + std::to_string(index));
      }
    }
    mesh.triangles.push_back(
      { static_cast<int>(a - first), static_cast<int>(b - first), static_cast<int>(c - first) });
  }
  return WithoutUnusedVertices(mesh);
}

Mesh ReadMesh(const std::string& path)
{
  const std::string ext = Extension(path);
  if (ext == ".node")
  {
    return ReadTriangleFiles(path);
  }
  vtkSmartPointer<vtkDataSet> data;
  if (ext == ".vtu")
  {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(path.c_str());
    reader->Update();
    data = reader->GetOutput();
  }
  else
  {
    data = ReadVtkPolyData(path);
  }
  Mesh mesh;
  for (vtkIdType i = 0; i < data->GetNumberOfPoints(); ++i)
  {
    double p[3];
    data->GetPoint(i, p);
    mesh.vertices.push_back({ p[0], p[1] });
  }
  vtkNew<vtkGenericCell> cell;
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    data->GetCell(c, cell);
    if (cell->GetCellType() != VTK_TRIANGLE)
    {
      Die(path + ": cell " + std::to_string(c) + " is not a triangle");
    }
    mesh.triangles.push_back({ static_cast<int>(cell->GetPointId(0)),
      static_cast<int>(cell->GetPointId(1)), static_cast<int>(cell->GetPointId(2)) });
  }
  return mesh;
}

/// Per input point: the mesh vertex at its exact coordinates, or with a
/// merge tolerance the nearest within it (a merge moves a point by up to
/// that); -1 if none.
std::vector<int> MatchInputPoints(const osm::Pslg& input, const Mesh& mesh, double tolerance)
{
  std::vector<std::pair<osm::Point, int>> byPoint;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
  {
    byPoint.push_back({ mesh.vertices[v], static_cast<int>(v) });
  }
  std::sort(
    byPoint.begin(), byPoint.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<int> vertexOf(input.points.size(), -1);
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    const osm::Point& p = input.points[i];
    // By x, then y: the candidates within the tolerance lie from p.x - t on.
    auto it = std::lower_bound(byPoint.begin(), byPoint.end(),
      osm::Point{ p.x - tolerance, -std::numeric_limits<double>::infinity() },
      [](const auto& a, const osm::Point& q) { return a.first < q; });
    double best = tolerance * tolerance;
    for (; it != byPoint.end() && it->first.x <= p.x + tolerance; ++it)
    {
      const double dx = it->first.x - p.x, dy = it->first.y - p.y;
      if (dx * dx + dy * dy <= best && (vertexOf[i] < 0 || dx * dx + dy * dy < best))
      {
        best = dx * dx + dy * dy;
        vertexOf[i] = it->second;
      }
    }
  }
  return vertexOf;
}

int Validate(int argc, char* argv[])
{
  if (argc < 4)
  {
    Die("usage: validate INPUT MESH [--allow-missing] [--max-angle A] [--max-edge H] [--area A] "
        "[--domain D] [--merge-tolerance T]");
  }
  bool allowMissing = false;
  double expectedArea = -1.0;
  osm::ValidationOptions options;
  osm::ValidationOptions domain; // check 9 alone, on the whole input
  domain.maxAngleDeg = 180.0;
  domain.checkConformity = false;
  domain.requireAllInputVertices = false;
  domain.bruteForceOverlapLimit = 0;
  for (int i = 4; i < argc; ++i)
  {
    const std::string arg = argv[i];
    if (arg == "--allow-missing")
    {
      allowMissing = true;
    }
    else if (arg == "--max-angle" && i + 1 < argc)
    {
      options.maxAngleDeg = std::atof(argv[++i]);
    }
    else if (arg == "--max-edge" && i + 1 < argc)
    {
      options.maxEdgeLength = std::atof(argv[++i]);
    }
    else if (arg == "--merge-tolerance" && i + 1 < argc)
    {
      // What the mesh was made with: points move and segments bend by up to it.
      options.snapTolerance = options.chainOffset = std::atof(argv[++i]);
      domain.snapTolerance = domain.chainOffset = options.snapTolerance;
    }
    else if (arg == "--area" && i + 1 < argc)
    {
      expectedArea = std::atof(argv[++i]);
    }
    else if (arg == "--domain" && i + 1 < argc)
    {
      const std::string d = argv[++i];
      domain.checkHoles = true;
      if (d == "enclosed")
      {
        domain.boundary = osm::DomainBoundary::Segments;
      }
      else if (d == "hull")
      {
        domain.boundary = osm::DomainBoundary::SegmentsOrHull;
      }
      else if (d == "box")
      {
        domain.boundary = osm::DomainBoundary::SegmentsOrBox;
      }
      else
      {
        Die("unknown domain " + d);
      }
    }
    else
    {
      Die("unknown argument " + arg);
    }
  }
  osm::Pslg input = ReadInput(argv[2]);
  const Mesh mesh = ReadMesh(argv[3]);
  if (mesh.triangles.empty())
  {
    std::cout << "FAIL: " << argv[3] << " has no triangles\n";
    return 1;
  }

  // Input points present in the mesh, at the vertex found for each; moved
  // there (a merge moves them), and each vertex listed once.
  const std::vector<int> vertexOf = MatchInputPoints(input, mesh, options.snapTolerance);
  osm::Pslg present;
  std::vector<int> index(input.points.size(), -1);
  std::vector<int> presentOf(mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    const int v = vertexOf[i];
    if (v < 0)
    {
      continue;
    }
    input.points[i] = mesh.vertices[v];
    if (presentOf[v] < 0)
    {
      presentOf[v] = static_cast<int>(present.points.size());
      present.points.push_back(mesh.vertices[v]);
    }
    index[i] = presentOf[v];
  }
  const auto missing = static_cast<std::size_t>(std::count(vertexOf.begin(), vertexOf.end(), -1));
  if (missing > 0 && !allowMissing)
  {
    std::cout << "FAIL: " << missing << " input point(s) are not mesh vertices\n";
    return 1;
  }
  for (const osm::Segment& s : input.segments)
  {
    if (index[s[0]] >= 0 && index[s[1]] >= 0 && index[s[0]] != index[s[1]])
    {
      present.segments.push_back({ index[s[0]], index[s[1]] });
    }
  }

  const osm::ValidationReport report =
    osm::validate(present, mesh.vertices, mesh.triangles, options);
  std::cout << (report.ok ? "ok" : "FAIL") << ": " << report.triangles << " triangles, "
            << mesh.vertices.size() << " vertices, " << input.points.size() - missing << " of "
            << input.points.size() << " input points, " << present.segments.size()
            << " segments checked, angles " << report.minAngleDeg << " to " << report.maxAngleDeg
            << "\n";
  for (const std::string& e : report.errors)
  {
    std::cout << "  " << e << "\n";
  }
  bool ok = report.ok;
  if (domain.checkHoles)
  {
    const osm::ValidationReport d = osm::validate(input, mesh.vertices, mesh.triangles, domain);
    std::cout << (d.ok ? "ok" : "FAIL") << ": the domain's boundary and " << input.holes.size()
              << " hole seed(s)\n";
    for (const std::string& e : d.errors)
    {
      std::cout << "  " << e << "\n";
    }
    ok = ok && d.ok;
  }
  if (expectedArea >= 0.0)
  {
    double area = 0.0;
    for (const osm::Triangle& t : mesh.triangles)
    {
      const osm::Point& a = mesh.vertices[t[0]];
      const osm::Point& b = mesh.vertices[t[1]];
      const osm::Point& c = mesh.vertices[t[2]];
      area += 0.5 * ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
    }
    const bool same = std::abs(area - expectedArea) <= 1e-9 * std::max(1.0, expectedArea);
    std::cout << (same ? "ok" : "FAIL") << ": area " << area << ", expected " << expectedArea
              << "\n";
    return ok && same ? 0 : 1;
  }
  return ok ? 0 : 1;
}

int Reference(int argc, char* argv[])
{
  if (argc < 4)
  {
    Die("usage: reference INPUT OUTPUT.vtp [--domain N] [--min-angle A]");
  }
  const std::string input = argv[2];
  vtkSmartPointer<vtkAlgorithm> reader;
  const std::string ext = Extension(input);
  if (ext == ".poly" || ext == ".node")
  {
    auto r = vtkSmartPointer<vtkTrianglePolyReader>::New();
    r->SetFileName(input.c_str());
    reader = r;
  }
  else if (ext == ".vtp")
  {
    auto r = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    r->SetFileName(input.c_str());
    reader = r;
  }
  else
  {
    auto r = vtkSmartPointer<vtkPolyDataReader>::New();
    r->SetFileName(input.c_str());
    reader = r;
  }
  vtkNew<vtkOverlayStitchMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetGenerateEdges(true);
  mesher->SetGenerateOverlay(false);
  for (int i = 4; i + 1 < argc; i += 2)
  {
    const std::string arg = argv[i];
    if (arg == "--domain")
    {
      mesher->SetDomain(std::atoi(argv[i + 1]));
    }
    else if (arg == "--min-angle")
    {
      mesher->SetMinimumAngle(std::atof(argv[i + 1]));
    }
    else
    {
      Die("unknown argument " + arg);
    }
  }
  mesher->Update();
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(mesher->GetOutput());
  vtkNew<vtkFieldData> fields;
  for (int a = 0; a < mesher->GetOutput()->GetFieldData()->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = mesher->GetOutput()->GetFieldData()->GetAbstractArray(a);
    if (std::strncmp(array->GetName(), "Seconds", 7) != 0)
    {
      fields->AddArray(array);
    }
  }
  mesh->SetFieldData(fields);
  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputData(mesh);
  writer->SetFileName(argv[3]);
  writer->SetCompressionLevel(1); // as osm-mesh writes
  return writer->Write() && mesh->GetNumberOfPolys() > 0 ? 0 : 1;
}

/// Collects the error messages of an algorithm.
class ErrorRecorder : public vtkCommand
{
public:
  static ErrorRecorder* New() { return new ErrorRecorder; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    this->Messages.push_back(data ? static_cast<const char*>(data) : "");
  }
  std::vector<std::string> Messages;
};

int ReaderFailures = 0;

void Expect(bool condition, const std::string& what)
{
  std::cout << (condition ? "ok   " : "FAIL ") << what << "\n";
  ReaderFailures += condition ? 0 : 1;
}

std::vector<double> Values(vtkDataArray* array)
{
  std::vector<double> values;
  if (array)
  {
    for (vtkIdType t = 0; t < array->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < array->GetNumberOfComponents(); ++c)
      {
        values.push_back(array->GetComponent(t, c));
      }
    }
  }
  return values;
}

/// The reader's output contract (see vtkTrianglePolyReader.h), on the files
/// in DATA_DIR and on bad files written into OUT_DIR.
int ReaderContract(int argc, char* argv[])
{
  if (argc != 4)
  {
    Die("usage: reader DATA_DIR OUT_DIR");
  }
  const std::string dataDir = argv[2];
  const std::string outDir = argv[3];

  vtkNew<vtkTrianglePolyReader> reader;
  vtkNew<ErrorRecorder> errors;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  Expect(reader->GetNumberOfInputPorts() == 0, "no input port");

  reader->SetFileName((dataDir + "/square_hole.poly").c_str());
  reader->Update();
  vtkPolyData* out = reader->GetOutput();
  Expect(errors->Messages.empty(), "square_hole.poly read without error");
  Expect(out->GetNumberOfPoints() == 9, "9 points");
  double bounds[6];
  out->GetBounds(bounds);
  Expect(
    bounds[0] == 0 && bounds[1] == 10 && bounds[4] == 0 && bounds[5] == 0, "x from 0 to 10, z = 0");
  Expect(out->GetNumberOfLines() == 8, "8 line cells, one per segment");
  Expect(out->GetNumberOfVerts() == 1, "1 vertex cell (the point on no segment)");
  vtkNew<vtkGenericCell> cell;
  out->GetCell(0, cell);
  Expect(cell->GetCellType() == VTK_VERTEX && cell->GetPointId(0) == 8,
    "the vertex cell holds point 8 (file vertex 9)");
  out->GetCell(1, cell);
  Expect(cell->GetCellType() == VTK_LINE && cell->GetPointId(0) == 0 && cell->GetPointId(1) == 1,
    "the first segment is the line 0-1 (1-based file renumbered)");
  out->GetCell(8, cell);
  Expect(cell->GetPointId(0) == 7 && cell->GetPointId(1) == 4, "the last segment is 7-4");
  vtkDataArray* pointMarker = out->GetPointData()->GetArray("PointMarker");
  Expect(pointMarker && pointMarker->GetDataType() == VTK_INT &&
      Values(pointMarker) == std::vector<double>{ 1, 1, 1, 1, 2, 2, 2, 2, 0 },
    "PointMarker (int) from the file");
  vtkDataArray* attribute = out->GetPointData()->GetArray("Attribute0");
  Expect(attribute && attribute->GetDataType() == VTK_DOUBLE &&
      Values(attribute) == std::vector<double>{ 0.5, 1.5, 2.5, 3.5, 4.5, 5.5, 6.5, 7.5, 8.5 },
    "Attribute0 (double) from the file");
  Expect(!out->GetPointData()->GetArray("Attribute1"), "no Attribute1");
  vtkDataArray* segmentMarker = out->GetCellData()->GetArray("SegmentMarker");
  Expect(segmentMarker && segmentMarker->GetDataType() == VTK_INT &&
      Values(segmentMarker) == std::vector<double>{ 0, 1, 1, 1, 1, 2, 2, 2, 2 },
    "SegmentMarker (int): 0 on the vertex cell, then the file's markers");
  vtkDataArray* holes = out->GetFieldData()->GetArray("HolePoints");
  Expect(holes && holes->GetDataType() == VTK_DOUBLE && holes->GetNumberOfComponents() == 3 &&
      Values(holes) == std::vector<double>{ 5, 5, 0 },
    "field data HolePoints: (5, 5, 0)");
  vtkDataArray* firstIndex = out->GetFieldData()->GetArray("FileFirstIndex");
  Expect(firstIndex && Values(firstIndex) == std::vector<double>{ 1 },
    "field data FileFirstIndex: 1 (the file counts from 1)");
  vtkDataArray* regions = out->GetFieldData()->GetArray("RegionAttributes");
  Expect(regions && regions->GetNumberOfComponents() == 4 &&
      Values(regions) == std::vector<double>{ 1, 1, 7, 0.5 },
    "field data RegionAttributes: (1, 1, 7, 0.5)");

  // Parallel: piece 0 of 2 reads everything, piece 1 is empty with an empty HolePoints.
  reader->UpdatePiece(1, 2, 0);
  out = reader->GetOutput();
  holes = out->GetFieldData()->GetArray("HolePoints");
  Expect(out->GetNumberOfPoints() == 0 && out->GetNumberOfCells() == 0, "piece 1 of 2 is empty");
  Expect(holes && holes->GetNumberOfComponents() == 3 && holes->GetNumberOfTuples() == 0,
    "piece 1 of 2 still has HolePoints, with 0 tuples");
  reader->UpdatePiece(0, 2, 0);
  out = reader->GetOutput();
  Expect(out->GetNumberOfPoints() == 9 && out->GetNumberOfLines() == 8,
    "piece 0 of 2 holds the whole file");

  // A .node file: points only, no markers, no holes.
  reader->SetFileName((dataDir + "/split_pslg.node").c_str());
  reader->UpdatePiece(0, 1, 0);
  out = reader->GetOutput();
  holes = out->GetFieldData()->GetArray("HolePoints");
  Expect(
    out->GetNumberOfPoints() == 4 && out->GetNumberOfVerts() == 4 && out->GetNumberOfLines() == 0,
    ".node: 4 points, 4 vertex cells, no line");
  Expect(
    !out->GetPointData()->GetArray("PointMarker") && !out->GetCellData()->GetArray("SegmentMarker"),
    ".node without markers: no marker arrays");
  Expect(holes && holes->GetNumberOfTuples() == 0 && holes->GetNumberOfComponents() == 3,
    ".node: HolePoints present, 0 tuples");
  firstIndex = out->GetFieldData()->GetArray("FileFirstIndex");
  Expect(firstIndex && Values(firstIndex) == std::vector<double>{ 1 }, ".node: FileFirstIndex 1");
  Expect(errors->Messages.empty(), "no error so far");

  // A malformed file: the core's "file:line: reason" and an empty output.
  const std::string bad = outDir + "/reader-bad.poly";
  {
    std::ofstream f(bad);
    f << "3 2 0 0\n1 0 0\n2 1 0\n3 0 1\n1 0\n1 1 9\n0\n";
  }
  // The request does not fail, so that a mesher downstream runs on the empty
  // output rather than keeping its mesh of the file read before (a review).
  vtkNew<vtkOverlayStitchMesher> downstream;
  downstream->SetInputConnection(reader->GetOutputPort());
  downstream->AddObserver(vtkCommand::WarningEvent, vtkNew<ErrorRecorder>());
  reader->SetFileName((dataDir + "/square_hole.poly").c_str());
  downstream->Update();
  const vtkIdType before = downstream->GetOutput()->GetNumberOfCells();
  reader->SetFileName(bad.c_str());
  const int status = reader->UpdatePiece(0, 1, 0);
  downstream->Update();
  Expect(status == 1, "malformed file: Update() returns 1 (" + std::to_string(status) + ")");
  Expect(before > 0 && downstream->GetOutput()->GetNumberOfCells() == 0,
    "malformed file: the mesher downstream is emptied, not left with the last mesh (" +
      std::to_string(before) + " triangles before)");
  out = reader->GetOutput();
  Expect(out->GetPoints() && out->GetNumberOfPoints() == 0,
    "malformed file: empty points, not none (old bounds would stay)");
  Expect(!errors->Messages.empty() &&
      errors->Messages.front().find("reader-bad.poly:6: segment 1 refers to vertex 9") !=
        std::string::npos,
    "malformed file: error 'reader-bad.poly:6: segment 1 refers to vertex 9 ...'");
  Expect(
    out->GetNumberOfPoints() == 0 && out->GetNumberOfCells() == 0, "malformed file: empty output");

  Expect(reader->CanReadFile((dataDir + "/square_hole.poly").c_str()) == 1,
    "CanReadFile: an existing .poly");
  Expect(reader->CanReadFile((dataDir + "/split_pslg.node").c_str()) == 1,
    "CanReadFile: an existing .node");
  Expect(reader->CanReadFile((dataDir + "/wedge.vtk").c_str()) == 0, "CanReadFile: not a .vtk");
  Expect(reader->CanReadFile((dataDir + "/missing.poly").c_str()) == 0,
    "CanReadFile: not a missing file");
  std::ostringstream printed;
  reader->Print(printed);
  Expect(printed.str().find("FileName: " + bad) != std::string::npos, "PrintSelf shows FileName");

  std::cout << ReaderFailures << " failure(s)\n";
  return ReaderFailures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string command = argc > 1 ? argv[1] : "";
  if (command == "validate")
  {
    return Validate(argc, argv);
  }
  if (command == "reference")
  {
    return Reference(argc, argv);
  }
  if (command == "reader")
  {
    return ReaderContract(argc, argv);
  }
  Die("usage: osm_cli_helper validate|reference|reader ...");
}
