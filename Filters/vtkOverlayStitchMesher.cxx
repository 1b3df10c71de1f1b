// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// A thin layer: vtkPolyData -> osm::Pslg, osm::mesh(), osm::Result -> three
// vtkPolyData outputs. No geometric algorithm lives here; it is all in the
// plain C++ core (Filters/Core, namespace osm).
#include "vtkOverlayStitchMesher.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include "Geometry.h"
#include "Mesher.h"
#include "Pslg.h"
#include "Statistics.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <exception>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkOverlayStitchMesher);

namespace
{

/// Forwards the core's progress to the algorithm and polls its abort flag
/// (GetAbortExecute rather than CheckAbort, which VTK 9.1 does not have).
class ProgressAdapter : public osm::Progress
{
public:
  explicit ProgressAdapter(vtkOverlayStitchMesher* filter)
    : Filter(filter)
  {}

  void report(double fraction, const char* phase) override
  {
    if (phase && this->Phase != phase)
    {
      this->Phase = phase;
      this->Filter->SetProgressText(phase);
    }
    this->Filter->UpdateProgress(fraction);
  }

  bool aborted() override { return this->Filter->GetAbortExecute() != 0; }

private:
  vtkOverlayStitchMesher* Filter;
  std::string Phase;
};

/// Reads the input into a PSLG. Returns an error message, or "" on success.
std::string ConvertInput(vtkPolyData* input, osm::Pslg& pslg, double& z, vtkIdType& ignoredCells)
{
  z = 0.0;
  ignoredCells = 0;
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints > static_cast<vtkIdType>(std::numeric_limits<int>::max()))
  {
    return "the input has " + std::to_string(numberOfPoints) +
      " points; the mesher accepts at most " + std::to_string(std::numeric_limits<int>::max());
  }
  pslg.points.resize(static_cast<std::size_t>(numberOfPoints));
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    if (!std::isfinite(p[2]))
    {
      std::ostringstream msg;
      msg << "input point " << i << " has a non-finite z coordinate (" << p[2] << ")";
      return msg.str();
    }
    if (i == 0)
    {
      z = p[2];
    }
    else if (p[2] != z)
    {
      std::ostringstream msg;
      msg << "input is not planar (z varies): point 0 has z = " << z << " but point " << i
          << " has z = " << p[2] << "; the mesher needs all points in one plane z = constant";
      return msg.str();
    }
    // x and y are passed as they are: the core reports NaN and infinite values.
    pslg.points[static_cast<std::size_t>(i)] = osm::Point{ p[0], p[1] };
  }

  auto addSegment = [&pslg](vtkIdType a, vtkIdType b) {
    if (a != b) // a repeated point id is no segment (e.g. a closing point in a polyline)
    {
      pslg.segments.push_back({ static_cast<int>(a), static_cast<int>(b) });
    }
  };

  // Lines and polylines: one segment per consecutive pair of points.
  if (vtkCellArray* lines = input->GetLines())
  {
    auto it = vtk::TakeSmartPointer(lines->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        addSegment(ids[k], ids[k + 1]);
      }
    }
  }
  // Polygons: their closed edge loops.
  if (vtkCellArray* polys = input->GetPolys())
  {
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      for (vtkIdType k = 0; n >= 2 && k < n; ++k)
      {
        addSegment(ids[k], ids[(k + 1) % n]);
      }
    }
  }
  // Vertex and polyvertex cells need nothing: every input point is meshed.
  if (vtkCellArray* strips = input->GetStrips())
  {
    ignoredCells += strips->GetNumberOfCells();
  }
  return std::string();
}

/// Builds a vtkCellArray in bulk from offsets and connectivity.
template <typename VertexOf>
vtkSmartPointer<vtkCellArray> MakeCells(
  std::size_t numberOfCells, int cellSize, const VertexOf& vertexOf)
{
  vtkNew<vtkIdTypeArray> offsets;
  offsets->SetNumberOfValues(static_cast<vtkIdType>(numberOfCells) + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  connectivity->SetNumberOfValues(static_cast<vtkIdType>(numberOfCells) * cellSize);
  vtkIdType next = 0;
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    offsets->SetValue(static_cast<vtkIdType>(c), next);
    for (int k = 0; k < cellSize; ++k)
    {
      connectivity->SetValue(next++, vertexOf(c, k));
    }
  }
  offsets->SetValue(static_cast<vtkIdType>(numberOfCells), next);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

vtkSmartPointer<vtkPoints> MakePoints(const std::vector<osm::Point>& vertices, double z)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  coordinates->SetNumberOfTuples(static_cast<vtkIdType>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    const double p[3] = { vertices[i].x, vertices[i].y, z };
    coordinates->SetTypedTuple(static_cast<vtkIdType>(i), p);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);
  return points;
}

void MakeTriangles(const osm::TriMesh& mesh, double z, vtkPolyData* output)
{
  output->SetPoints(MakePoints(mesh.vertices, z));
  output->SetPolys(MakeCells(mesh.triangles.size(), 3,
    [&mesh](std::size_t c, int k) { return static_cast<vtkIdType>(mesh.triangles[c][k]); }));
}

template <typename ArrayT>
vtkSmartPointer<ArrayT> MakeArray(const char* name, vtkIdType size)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  array->SetNumberOfTuples(size);
  return array;
}

void FillMesh(const osm::Result& result, double z, vtkPolyData* output)
{
  MakeTriangles(result.mesh, z, output);

  const auto numberOfVertices = static_cast<vtkIdType>(result.mesh.vertices.size());
  auto origin = MakeArray<vtkUnsignedCharArray>("VertexOrigin", numberOfVertices);
  for (vtkIdType i = 0; i < numberOfVertices; ++i)
  {
    const auto value = static_cast<std::size_t>(i) < result.vertexOrigin.size()
      ? result.vertexOrigin[static_cast<std::size_t>(i)]
      : osm::VertexOrigin::Other;
    origin->SetValue(i, static_cast<unsigned char>(value));
  }
  output->GetPointData()->AddArray(origin);

  const auto numberOfTriangles = static_cast<vtkIdType>(result.mesh.triangles.size());
  auto minAngle = MakeArray<vtkDoubleArray>("MinAngle", numberOfTriangles);
  auto maxAngle = MakeArray<vtkDoubleArray>("MaxAngle", numberOfTriangles);
  auto regionId = MakeArray<vtkIntArray>("RegionId", numberOfTriangles);
  const double degrees = 180.0 / std::acos(-1.0);
  const auto& v = result.mesh.vertices;
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    const osm::Triangle& tri = result.mesh.triangles[static_cast<std::size_t>(t)];
    double lo = 180.0;
    double hi = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double angle =
        degrees * osm::angleAt(v[tri[(k + 2) % 3]], v[tri[k]], v[tri[(k + 1) % 3]]);
      lo = std::min(lo, angle);
      hi = std::max(hi, angle);
    }
    minAngle->SetValue(t, lo);
    maxAngle->SetValue(t, hi);
    regionId->SetValue(t,
      static_cast<std::size_t>(t) < result.regionId.size()
        ? result.regionId[static_cast<std::size_t>(t)]
        : -1);
  }
  output->GetCellData()->AddArray(minAngle);
  output->GetCellData()->AddArray(maxAngle);
  output->GetCellData()->AddArray(regionId);

  for (const auto& item : result.stats.items())
  {
    auto value = MakeArray<vtkDoubleArray>(item.first.c_str(), 1);
    value->SetValue(0, item.second);
    output->GetFieldData()->AddArray(value);
  }
}

void FillEdges(const osm::Result& result, double z, vtkPolyData* output)
{
  output->SetPoints(MakePoints(result.edgeVertices, z));
  output->SetLines(MakeCells(result.edges.size(), 2, [&result](std::size_t c, int k) {
    return static_cast<vtkIdType>(k == 0 ? result.edges[c].a : result.edges[c].b);
  }));

  const auto numberOfEdges = static_cast<vtkIdType>(result.edges.size());
  auto overlay = MakeArray<vtkUnsignedCharArray>("Overlay", numberOfEdges);
  auto kept = MakeArray<vtkUnsignedCharArray>("Kept", numberOfEdges);
  auto discarded = MakeArray<vtkUnsignedCharArray>("Discarded", numberOfEdges);
  auto isInput = MakeArray<vtkUnsignedCharArray>("Input", numberOfEdges);
  auto edgeClass = MakeArray<vtkUnsignedCharArray>("EdgeClass", numberOfEdges);
  for (vtkIdType e = 0; e < numberOfEdges; ++e)
  {
    const std::uint8_t flags = result.edges[static_cast<std::size_t>(e)].flags;
    overlay->SetValue(e, (flags & osm::EdgeOverlay) ? 1 : 0);
    kept->SetValue(e, (flags & osm::EdgeKept) ? 1 : 0);
    discarded->SetValue(e, (flags & osm::EdgeDiscarded) ? 1 : 0);
    isInput->SetValue(e, (flags & osm::EdgeInput) ? 1 : 0);
    edgeClass->SetValue(e, static_cast<unsigned char>(osm::edgeClass(flags)));
  }
  output->GetCellData()->AddArray(overlay);
  output->GetCellData()->AddArray(kept);
  output->GetCellData()->AddArray(discarded);
  output->GetCellData()->AddArray(isInput);
  output->GetCellData()->AddArray(edgeClass);
  output->GetCellData()->SetActiveScalars("EdgeClass");

  // The names of the EdgeClass categories, indexed by value.
  vtkNew<vtkStringArray> names;
  names->SetName("EdgeClassNames");
  names->InsertNextValue("Uncrossed");
  names->InsertNextValue("Kept");
  names->InsertNextValue("Discarded");
  names->InsertNextValue("Input");
  output->GetFieldData()->AddArray(names);
}

} // namespace

//------------------------------------------------------------------------------
vtkOverlayStitchMesher::vtkOverlayStitchMesher()
  : MinimumAngle(30.0)
  , MaximumEdgeLength(0.0)
  , Domain(DOMAIN_AUTO)
  , ResolveIntersections(1)
  , MaximumSteinerPoints(0)
  , GenerateEdges(1)
  , GenerateOverlay(1)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
}

//------------------------------------------------------------------------------
vtkOverlayStitchMesher::~vtkOverlayStitchMesher() = default;

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::AddHolePoint(double x, double y)
{
  this->HolePoints.push_back(x);
  this->HolePoints.push_back(y);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::RemoveAllHolePoints()
{
  if (!this->HolePoints.empty())
  {
    this->HolePoints.clear();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkOverlayStitchMesher::GetNumberOfHolePoints() const
{
  return static_cast<int>(this->HolePoints.size() / 2);
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::GetHolePoint(int i, double point[2]) const
{
  if (i < 0 || i >= this->GetNumberOfHolePoints())
  {
    point[0] = point[1] = 0.0;
    return;
  }
  point[0] = this->HolePoints[2 * static_cast<std::size_t>(i)];
  point[1] = this->HolePoints[2 * static_cast<std::size_t>(i) + 1];
}

//------------------------------------------------------------------------------
vtkPolyData* vtkOverlayStitchMesher::GetEdgesOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkPolyData* vtkOverlayStitchMesher::GetOverlayOutput()
{
  return vtkPolyData::SafeDownCast(this->GetOutputDataObject(2));
}

//------------------------------------------------------------------------------
int vtkOverlayStitchMesher::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 0)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    return 1;
  }
  return 0;
}

//------------------------------------------------------------------------------
int vtkOverlayStitchMesher::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* mesh = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* edges = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* overlay = vtkPolyData::GetData(outputVector, 2);
  if (!mesh || !edges || !overlay)
  {
    vtkErrorMacro("Output data objects are missing.");
    return 0;
  }
  // Outputs stay empty unless meshing succeeds.
  mesh->Initialize();
  edges->Initialize();
  overlay->Initialize();
  if (!input)
  {
    vtkErrorMacro("No input polydata.");
    return 1;
  }

  osm::Pslg pslg;
  double z = 0.0;
  vtkIdType ignoredCells = 0;
  const std::string inputError = ConvertInput(input, pslg, z, ignoredCells);
  if (!inputError.empty())
  {
    vtkErrorMacro("Cannot mesh the input: " << inputError);
    return 1;
  }
  if (ignoredCells > 0)
  {
    vtkWarningMacro(<< ignoredCells
                    << " triangle strip cell(s) ignored: the input is read from its points and "
                       "its vertex, line, polyline and polygon cells.");
  }
  for (std::size_t i = 0; i + 1 < this->HolePoints.size(); i += 2)
  {
    pslg.holes.push_back(osm::Point{ this->HolePoints[i], this->HolePoints[i + 1] });
  }

  osm::Options options;
  options.minAngleDeg = this->MinimumAngle;
  options.maxEdgeLength = this->MaximumEdgeLength;
  switch (this->Domain)
  {
    case DOMAIN_ENCLOSED:
      options.domain = osm::Domain::Enclosed;
      break;
    case DOMAIN_HULL:
      options.domain = osm::Domain::Hull;
      break;
    case DOMAIN_BOX:
      options.domain = osm::Domain::Box;
      break;
    default:
      options.domain = osm::Domain::Auto;
      break;
  }
  options.resolveCrossings = this->ResolveIntersections != 0;
  options.maxSteinerPoints = static_cast<std::size_t>(this->MaximumSteinerPoints);
  options.keepEdges = this->GenerateEdges != 0;
  options.keepOverlay = this->GenerateOverlay != 0;

  ProgressAdapter progress(this);
  osm::Result result;
  try
  {
    result = osm::mesh(pslg, options, &progress);
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Internal error in the mesher: " << e.what());
    return 1;
  }
  this->SetProgressText(nullptr);
  this->UpdateProgress(1.0);

  for (const std::string& warning : result.warnings)
  {
    vtkWarningMacro(<< warning);
  }
  if (!result.ok)
  {
    vtkErrorMacro("Meshing failed: " << result.error);
    return 1;
  }

  FillMesh(result, z, mesh);
  if (this->GenerateEdges)
  {
    FillEdges(result, z, edges);
  }
  if (this->GenerateOverlay)
  {
    MakeTriangles(result.overlay, z, overlay);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  os << indent << "Domain: " << this->Domain << "\n";
  os << indent << "ResolveIntersections: " << (this->ResolveIntersections ? "On" : "Off") << "\n";
  os << indent << "MaximumSteinerPoints: " << this->MaximumSteinerPoints << "\n";
  os << indent << "GenerateEdges: " << (this->GenerateEdges ? "On" : "Off") << "\n";
  os << indent << "GenerateOverlay: " << (this->GenerateOverlay ? "On" : "Off") << "\n";
  os << indent << "HolePoints: " << this->GetNumberOfHolePoints() << "\n";
  for (int i = 0; i < this->GetNumberOfHolePoints(); ++i)
  {
    double p[2];
    this->GetHolePoint(i, p);
    os << indent.GetNextIndent() << "(" << p[0] << ", " << p[1] << ")\n";
  }
}
