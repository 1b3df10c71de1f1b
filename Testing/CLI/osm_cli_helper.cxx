// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// Test helper for the osm-mesh tests and the consumer test.
//
//   osm_cli_helper validate INPUT MESH [--allow-missing] [--max-angle A]
//     Reads the input PSLG (.poly/.node with the core's reader, .vtp/.vtk
//     with VTK's readers: lines, polylines and polygon edges are segments)
//     and a mesh (.vtp, .vtu, .vtk with VTK's readers, or Triangle's
//     .node + .ele, 1-based), and checks the mesh with the core's independent
//     validator osm::validate. Input points are matched to mesh vertices by
//     their coordinates; every input point must be present unless
//     --allow-missing (holes and the enclosed domain leave points out).
//     Prints one summary line; exit 0 iff the mesh is valid.
//
//   osm_cli_helper reference INPUT OUTPUT.vtp [--domain N] [--min-angle A]
//     The C++ pipeline osm-mesh is meant to be: vtkTrianglePolyReader (or
//     VTK's readers) -> vtkOverlayStitchMesher (Edges on, Overlay off) ->
//     vtkXMLPolyDataWriter, timings left out of the field data.
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellType.h"
#include "vtkDataSet.h"
#include "vtkFieldData.h"
#include "vtkGenericCell.h"
#include "vtkNew.h"
#include "vtkOverlayStitchMesher.h"
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
  std::vector<osm::Point> vertices;
  std::vector<osm::Triangle> triangles;
};

/// Triangle's .node + .ele, 1-based, as osm-mesh writes them.
Mesh ReadTriangleFiles(const std::string& nodePath)
{
  Mesh mesh;
  osm::PolyFile nodes = osm::readPolyFile(nodePath);
  if (!nodes.ok)
  {
    Die(nodes.error);
  }
  if (nodes.firstIndex != 1)
  {
    Die(nodePath + ": numbered from " + std::to_string(nodes.firstIndex) + ", not 1");
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
    if (!(ele >> index >> a >> b >> c) || index != t + 1)
    {
      Die(elePath + ": bad triangle line " + std::to_string(t + 1));
    }
    const long long n = static_cast<long long>(mesh.vertices.size());
    for (long long v : { a, b, c })
    {
      if (v < 1 || v > n)
      {
        Die(elePath + ": triangle " + std::to_string(index) + " refers to vertex " +
          std::to_string(v) + " of 1.." + std::to_string(n));
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
      { static_cast<int>(a - 1), static_cast<int>(b - 1), static_cast<int>(c - 1) });
  }
  return mesh;
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

int Validate(int argc, char* argv[])
{
  if (argc < 4)
  {
    Die("usage: validate INPUT MESH [--allow-missing] [--max-angle A]");
  }
  bool allowMissing = false;
  osm::ValidationOptions options;
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
    else
    {
      Die("unknown argument " + arg);
    }
  }
  const osm::Pslg input = ReadInput(argv[2]);
  const Mesh mesh = ReadMesh(argv[3]);
  if (mesh.triangles.empty())
  {
    std::cout << "FAIL: " << argv[3] << " has no triangles\n";
    return 1;
  }

  // Input points present in the mesh, found by their exact coordinates.
  std::vector<std::pair<osm::Point, int>> byPoint;
  for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
  {
    byPoint.push_back({ mesh.vertices[v], static_cast<int>(v) });
  }
  std::sort(
    byPoint.begin(), byPoint.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  osm::Pslg present;
  std::vector<int> index(input.points.size(), -1);
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    const osm::Point& p = input.points[i];
    auto it = std::lower_bound(byPoint.begin(), byPoint.end(), p,
      [](const auto& a, const osm::Point& q) { return a.first < q; });
    if (it != byPoint.end() && it->first == p)
    {
      index[i] = static_cast<int>(present.points.size());
      present.points.push_back(p);
    }
  }
  const std::size_t missing = input.points.size() - present.points.size();
  if (missing > 0 && !allowMissing)
  {
    std::cout << "FAIL: " << missing << " input point(s) are not mesh vertices\n";
    return 1;
  }
  for (const osm::Segment& s : input.segments)
  {
    if (index[s[0]] >= 0 && index[s[1]] >= 0)
    {
      present.segments.push_back({ index[s[0]], index[s[1]] });
    }
  }

  const osm::ValidationReport report =
    osm::validate(present, mesh.vertices, mesh.triangles, options);
  std::cout << (report.ok ? "ok" : "FAIL") << ": " << report.triangles << " triangles, "
            << mesh.vertices.size() << " vertices, " << present.points.size() << " of "
            << input.points.size() << " input points, " << present.segments.size()
            << " segments checked, angles " << report.minAngleDeg << " to " << report.maxAngleDeg
            << "\n";
  for (const std::string& e : report.errors)
  {
    std::cout << "  " << e << "\n";
  }
  return report.ok ? 0 : 1;
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
  return writer->Write() && mesh->GetNumberOfPolys() > 0 ? 0 : 1;
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
  Die("usage: osm_cli_helper validate|reference ...");
}
