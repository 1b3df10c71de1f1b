// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// VTK C++ tests of vtkOverlayStitchMesher, run as
//   TestOverlayStitchMesher contract    the output contract on a small PSLG
//   TestOverlayStitchMesher bad-input   bad input gives an error and empty outputs
//   TestOverlayStitchMesher large       large outputs in huge-page mappings, and given back
#include "vtkOverlayStitchMesher.h"

#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"

#include "HugePages.h"
#include "Mesher.h"
#include "Validate.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iostream>
#include <limits>
#include <map>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace
{

int Failures = 0;

void Check(bool condition, const std::string& what)
{
  if (!condition)
  {
    std::cerr << "FAILED: " << what << "\n";
    ++Failures;
  }
}

/// Counts error and warning events and keeps the last messages.
class MessageObserver : public vtkCommand
{
public:
  static MessageObserver* New() { return new MessageObserver; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    const char* text = data ? static_cast<const char*>(data) : "";
    if (event == vtkCommand::ErrorEvent)
    {
      ++this->Errors;
      this->LastError = text;
    }
    else if (event == vtkCommand::WarningEvent)
    {
      ++this->Warnings;
      this->LastWarning = text;
    }
  }
  int Errors = 0;
  int Warnings = 0;
  std::string LastError;
  std::string LastWarning;
};

/// A square [0,10]^2 (closed polyline) with an interior slit and a 3-degree
/// wedge (two segments from one point), all in the plane z = 2.5.
vtkSmartPointer<vtkPolyData> MakeInput(double z)
{
  const double t = std::tan(3.0 * std::acos(-1.0) / 180.0);
  const double xy[][2] = { { 0, 0 }, { 10, 0 }, { 10, 10 }, { 0, 10 }, // square
    { 2, 6 }, { 7, 6 },                                                // slit
    { 1, 1 }, { 9, 1 }, { 9, 1 + 8 * t } };                            // wedge
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  for (const auto& p : xy)
  {
    points->InsertNextPoint(p[0], p[1], z);
  }
  vtkNew<vtkCellArray> lines;
  const vtkIdType square[] = { 0, 1, 2, 3, 0 };
  lines->InsertNextCell(5, square);
  const vtkIdType slit[] = { 4, 5 };
  lines->InsertNextCell(2, slit);
  const vtkIdType wedge[] = { 7, 6, 8 };
  lines->InsertNextCell(3, wedge);
  auto input = vtkSmartPointer<vtkPolyData>::New();
  input->SetPoints(points);
  input->SetLines(lines);
  return input;
}

/// The input's points (x, y) and segments (every line cell's consecutive points).
osm::Pslg PslgOf(vtkPolyData* input)
{
  osm::Pslg pslg;
  for (vtkIdType i = 0; i < input->GetNumberOfPoints(); ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    pslg.points.push_back({ p[0], p[1] });
  }
  vtkCellArray* lines = input->GetLines();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (lines->InitTraversal(); lines->GetNextCell(n, ids);)
  {
    for (vtkIdType k = 0; k + 1 < n; ++k)
    {
      pslg.segments.push_back({ static_cast<int>(ids[k]), static_cast<int>(ids[k + 1]) });
    }
  }
  return pslg;
}

osm::Array<osm::Point> PointsOf(vtkPolyData* mesh)
{
  osm::Array<osm::Point> points;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    points.push_back({ p[0], p[1] });
  }
  return points;
}

osm::Array<osm::Triangle> TrianglesOf(vtkPolyData* mesh)
{
  osm::Array<osm::Triangle> triangles;
  vtkCellArray* polys = mesh->GetPolys();
  vtkIdType n = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    triangles.push_back({ static_cast<int>(ids[0]), static_cast<int>(ids[1]),
      n == 3 ? static_cast<int>(ids[2]) : -1 });
  }
  return triangles;
}

vtkDataArray* ArrayOf(vtkFieldData* data, const char* name, vtkIdType tuples)
{
  vtkDataArray* array = data->GetArray(name);
  Check(array != nullptr, std::string("array ") + name + " exists");
  if (array)
  {
    Check(array->GetNumberOfTuples() == tuples,
      std::string("array ") + name + " has " + std::to_string(tuples) + " tuples (it has " +
        std::to_string(array->GetNumberOfTuples()) + ")");
  }
  return array;
}

bool AllCellsOfType(vtkPolyData* data, int type)
{
  for (vtkIdType c = 0; c < data->GetNumberOfCells(); ++c)
  {
    if (data->GetCellType(c) != type)
    {
      return false;
    }
  }
  return true;
}

int TestContract()
{
  const double z = 2.5;
  vtkSmartPointer<vtkPolyData> input = MakeInput(z);
  vtkNew<vtkOverlayStitchMesher> mesher;
  vtkNew<MessageObserver> messages;
  mesher->AddObserver(vtkCommand::ErrorEvent, messages);
  mesher->AddObserver(vtkCommand::WarningEvent, messages);
  Check(mesher->GetNumberOfOutputPorts() == 3, "three output ports");
  Check(mesher->GetMinimumAngle() == 30.0, "MinimumAngle defaults to 30");
  mesher->SetInputData(input);
  mesher->Update();
  Check(messages->Errors == 0, "no error (got: " + messages->LastError + ")");

  // Port 0, Mesh.
  vtkPolyData* mesh = mesher->GetOutput();
  const vtkIdType triangles = mesh->GetNumberOfCells();
  std::cout << "Mesh: " << mesh->GetNumberOfPoints() << " points, " << triangles << " triangles\n";
  Check(triangles > 0, "the mesh has triangles");
  Check(mesh->GetNumberOfPolys() == triangles, "the mesh has only polygon cells");
  Check(AllCellsOfType(mesh, VTK_TRIANGLE), "every mesh cell is a triangle");
  vtkDataArray* origin = ArrayOf(mesh->GetPointData(), "VertexOrigin", mesh->GetNumberOfPoints());
  vtkDataArray* minAngle = ArrayOf(mesh->GetCellData(), "MinAngle", triangles);
  vtkDataArray* maxAngle = ArrayOf(mesh->GetCellData(), "MaxAngle", triangles);
  ArrayOf(mesh->GetCellData(), "RegionId", triangles);
  if (origin)
  {
    vtkIdType inputVertices = 0;
    for (vtkIdType i = 0; i < origin->GetNumberOfTuples(); ++i)
    {
      inputVertices += origin->GetTuple1(i) == 0 ? 1 : 0;
    }
    Check(inputVertices == input->GetNumberOfPoints(),
      "every input point is an output vertex with VertexOrigin 0 (" +
        std::to_string(inputVertices) + " of " + std::to_string(input->GetNumberOfPoints()) + ")");
  }
  if (minAngle && maxAngle && triangles > 0)
  {
    double range[2];
    maxAngle->GetRange(range, 0);
    std::cout << "MaxAngle range: " << range[0] << " .. " << range[1] << "\n";
    Check(
      range[1] <= 170.0, "no angle above 170 degrees (largest " + std::to_string(range[1]) + ")");
    minAngle->GetRange(range, 0);
    Check(range[0] > 0.0, "no zero angle");
  }
  double bounds[6];
  mesh->GetBounds(bounds);
  Check(bounds[4] == z && bounds[5] == z, "the mesh lies in the input plane z = 2.5");
  Check(mesh->GetFieldData()->GetArray("OutputTriangles") != nullptr,
    "run statistics in the field data");
  if (vtkDataArray* count = mesh->GetFieldData()->GetArray("OutputTriangles"))
  {
    Check(count->GetTuple1(0) == static_cast<double>(triangles),
      "statistic OutputTriangles matches the mesh");
  }

  // The independent validator on the filter's output: the input's
  // segments conform, every input point is a vertex, the domain is the
  // square (the slit and wedge inside; no holes), and no angle exceeds the
  // bound.
  {
    const osm::Pslg pslg = PslgOf(input);
    osm::ValidationOptions options;
    options.maxAngleDeg = 169.953;
    options.boundary = osm::DomainBoundary::Segments;
    const osm::ValidationReport report =
      osm::validate(pslg, PointsOf(mesh), TrianglesOf(mesh), options);
    Check(report.ok,
      "the mesh passes the validator" + (report.errors.empty() ? "" : ": " + report.errors[0]));
    // The overlay: a triangulation of the points and the padded box (left
    // coarse far from the input, so no angle is checked).
    osm::Pslg points;
    points.points = pslg.points;
    options.checkConformity = false;
    options.maxAngleDeg = 180.0;
    options.boundary = osm::DomainBoundary::SegmentsOrBox;
    const osm::ValidationReport overlayReport = osm::validate(points,
      PointsOf(mesher->GetOverlayOutput()), TrianglesOf(mesher->GetOverlayOutput()), options);
    Check(overlayReport.ok,
      "the overlay passes the validator" +
        (overlayReport.errors.empty() ? "" : ": " + overlayReport.errors[0]));
  }

  // Port 1, Edges.
  vtkPolyData* edges = mesher->GetEdgesOutput();
  std::cout << "Edges: " << edges->GetNumberOfCells() << " lines\n";
  Check(edges->GetNumberOfLines() > 0, "the edges output has lines");
  Check(AllCellsOfType(edges, VTK_LINE), "every edge is a line cell");
  for (const char* name : { "Overlay", "Kept", "Discarded", "Input" })
  {
    ArrayOf(edges->GetCellData(), name, edges->GetNumberOfCells());
  }
  if (vtkDataArray* edgeClass =
        ArrayOf(edges->GetCellData(), "EdgeClass", edges->GetNumberOfCells()))
  {
    bool inRange = true;
    bool hasInput = false;
    for (vtkIdType e = 0; e < edgeClass->GetNumberOfTuples(); ++e)
    {
      const double c = edgeClass->GetTuple1(e);
      inRange = inRange && c >= 0 && c <= 3;
      hasInput = hasInput || c == 3;
    }
    Check(inRange, "EdgeClass values are 0..3");
    Check(hasInput, "some edges are input subsegments (EdgeClass 3)");
  }
  auto* names =
    vtkStringArray::SafeDownCast(edges->GetFieldData()->GetAbstractArray("EdgeClassNames"));
  Check(names && names->GetNumberOfValues() == 4 && names->GetValue(0) == "Uncrossed" &&
      names->GetValue(1) == "Kept" && names->GetValue(2) == "Discarded" &&
      names->GetValue(3) == "Input",
    "EdgeClassNames names the four classes, in the order of their values");

  // Port 2, Overlay.
  vtkPolyData* overlay = mesher->GetOverlayOutput();
  std::cout << "Overlay: " << overlay->GetNumberOfCells() << " triangles\n";
  Check(overlay->GetNumberOfPolys() > 0, "the overlay output has triangles");
  Check(AllCellsOfType(overlay, VTK_TRIANGLE), "every overlay cell is a triangle");

  // The optional outputs can be switched off.
  mesher->GenerateEdgesOff();
  mesher->GenerateOverlayOff();
  mesher->Update();
  Check(mesher->GetOutput()->GetNumberOfCells() == triangles, "same mesh without edges/overlay");
  Check(mesher->GetEdgesOutput()->GetNumberOfCells() == 0, "GenerateEdges off empties port 1");
  Check(mesher->GetOverlayOutput()->GetNumberOfCells() == 0, "GenerateOverlay off empties port 2");
  return Failures == 0 ? 0 : 1;
}

bool AllOutputsEmpty(vtkOverlayStitchMesher* mesher)
{
  for (int port = 0; port < 3; ++port)
  {
    auto* out = vtkPolyData::SafeDownCast(mesher->GetOutputDataObject(port));
    if (!out || out->GetNumberOfPoints() != 0 || out->GetNumberOfCells() != 0)
    {
      return false;
    }
  }
  return true;
}

int TestBadInput()
{
  vtkNew<vtkOverlayStitchMesher> mesher;
  vtkNew<MessageObserver> messages;
  mesher->AddObserver(vtkCommand::ErrorEvent, messages);
  mesher->AddObserver(vtkCommand::WarningEvent, messages);

  // A NaN coordinate.
  vtkSmartPointer<vtkPolyData> input = MakeInput(0.0);
  input->GetPoints()->SetPoint(4, std::numeric_limits<double>::quiet_NaN(), 6.0, 0.0);
  mesher->SetInputData(input);
  mesher->Update();
  std::cout << "NaN input: " << messages->Errors << " error(s): " << messages->LastError << "\n";
  Check(messages->Errors >= 1, "a NaN coordinate is reported as an error");
  Check(AllOutputsEmpty(mesher), "a NaN coordinate leaves all outputs empty");

  // One point lifted out of the plane: not coplanar, the error names it.
  messages->Errors = 0;
  input = MakeInput(0.0);
  input->GetPoints()->SetPoint(2, 10.0, 10.0, 1.0);
  mesher->SetInputData(input);
  mesher->Update();
  std::cout << "Non-coplanar input: " << messages->LastError << "\n";
  Check(messages->Errors >= 1 && messages->LastError.find("not coplanar") != std::string::npos &&
      messages->LastError.find("point 2 at (10, 10, 1)") != std::string::npos,
    "a point out of the plane is reported as 'not coplanar', naming point 2");
  Check(AllOutputsEmpty(mesher), "non-coplanar input leaves all outputs empty");

  // Crossing segments with ResolveIntersections off.
  messages->Errors = 0;
  input = MakeInput(0.0);
  vtkNew<vtkCellArray> lines;
  lines->DeepCopy(input->GetLines());
  const vtkIdType crossing[] = { 0, 2 };
  lines->InsertNextCell(2, crossing);
  const vtkIdType other[] = { 1, 3 };
  lines->InsertNextCell(2, other);
  input->SetLines(lines);
  mesher->ResolveIntersectionsOff();
  mesher->SetInputData(input);
  mesher->Update();
  std::cout << "Crossing segments: " << messages->LastError << "\n";
  Check(messages->Errors >= 1, "crossing segments without ResolveIntersections are an error");
  Check(AllOutputsEmpty(mesher), "crossing segments leave all outputs empty");

  // The error names the crossing segments by their cell and points too.
  Check(messages->LastError.find("cell ") != std::string::npos &&
      messages->LastError.find("from point ") != std::string::npos,
    "the crossing error says which cells and points the segments are");
  mesher->ResolveIntersectionsOn();

  // An empty input is not an error.
  messages->Errors = 0;
  vtkNew<vtkPolyData> empty;
  mesher->SetInputData(empty);
  mesher->Update();
  Check(messages->Errors == 0, "an empty input is not an error (got: " + messages->LastError + ")");
  Check(AllOutputsEmpty(mesher), "an empty input gives empty outputs");
  return Failures == 0 ? 0 : 1;
}

/// Whether some mapping of /proc/self/smaps holds address a.
bool Mapped(const void* a)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(a);
  for (std::string line; std::getline(smaps, line);)
  {
    std::uintptr_t lo = 0, hi = 0;
    char dash = 0;
    std::istringstream head(line);
    if (head >> std::hex >> lo >> dash >> hi && dash == '-' && lo <= at && at < hi)
    {
      return true;
    }
  }
  return false;
}

/// The angle at b in degrees, computed here independently of the core.
double AngleDeg(const double* a, const double* b, const double* c)
{
  const double ux = a[0] - b[0], uy = a[1] - b[1], vx = c[0] - b[0], vy = c[1] - b[1];
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * 180.0 / std::acos(-1.0);
}

// 15,000 random points in a square: the output's connectivity, angle and
// region arrays (hundreds of kilobytes to megabytes) get mappings of their
// own. Their values must be right, survive the filter through a shallow copy,
// and their mappings must be given back when the last copy goes.
int TestLargeOutputs()
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  const double corners[][2] = { { 0, 0 }, { 100, 0 }, { 100, 100 }, { 0, 100 } };
  for (const auto& c : corners)
  {
    points->InsertNextPoint(c[0], c[1], 0);
  }
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(1.0, 99.0);
  for (int i = 0; i < 15000; ++i)
  {
    points->InsertNextPoint(u(rng), u(rng), 0);
  }
  vtkNew<vtkCellArray> lines;
  const vtkIdType square[] = { 0, 1, 2, 3, 0 };
  lines->InsertNextCell(5, square);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetLines(lines);

  auto held = vtkSmartPointer<vtkPolyData>::New();
  {
    vtkNew<vtkOverlayStitchMesher> mesher;
    mesher->SetInputData(input);
    mesher->Update();
    held->ShallowCopy(mesher->GetOutput());
  }
  const vtkIdType triangles = held->GetNumberOfCells();
  std::cout << "Mesh: " << held->GetNumberOfPoints() << " points, " << triangles << " triangles\n";
  Check(triangles > 100000, "a large mesh");
  vtkDataArray* minAngle = ArrayOf(held->GetCellData(), "MinAngle", triangles);
  vtkDataArray* maxAngle = ArrayOf(held->GetCellData(), "MaxAngle", triangles);
  vtkDataArray* regionId = ArrayOf(held->GetCellData(), "RegionId", triangles);
  if (!minAngle || !maxAngle || !regionId)
  {
    return 1;
  }
  // Every value, against the triangle's own angles computed here.
  vtkCellArray* polys = held->GetPolys();
  Check(polys->GetOffsetsArray()->GetNumberOfValues() == triangles + 1, "one offset per cell");
  Check(polys->IsStorage64Bit(),
    "cells in VTK's default 64-bit storage (subdivision filters "
    "refuse the 32-bit one)");
  int wrong = 0;
  for (vtkIdType t = 0; t < triangles; ++t)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    polys->GetCellAtId(t, n, ids);
    double p[3][3];
    for (int k = 0; k < 3; ++k)
    {
      held->GetPoint(ids[k], p[k]);
    }
    double lo = 180.0, hi = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      const double a = AngleDeg(p[(k + 2) % 3], p[k], p[(k + 1) % 3]);
      lo = std::min(lo, a);
      hi = std::max(hi, a);
    }
    wrong += n != 3 || std::fabs(minAngle->GetTuple1(t) - lo) > 1e-9 ||
        std::fabs(maxAngle->GetTuple1(t) - hi) > 1e-9 || regionId->GetTuple1(t) != 0
      ? 1
      : 0;
  }
  Check(wrong == 0, std::to_string(wrong) + " triangles with a wrong cell or wrong angles");

  // The first and last byte of each large array.
  std::vector<const char*> ends;
  for (vtkDataArray* a : { static_cast<vtkDataArray*>(polys->GetConnectivityArray()), minAngle })
  {
    const char* first = static_cast<const char*>(a->GetVoidPointer(0));
    ends.push_back(first);
    ends.push_back(first + a->GetDataSize() * a->GetDataTypeSize() - 1);
  }
  const char* off = std::getenv("OSM_NO_HUGE_PAGES");
  const bool expected =
    (!off || !*off || std::string(off) == "0") && std::ifstream("/proc/self/smaps").good();
  if (expected)
  {
    // Each value array follows its mapping's 64-byte header at a 2 MiB boundary.
    constexpr std::uintptr_t huge = std::uintptr_t{ 2 } << 20;
    for (std::size_t k = 0; k < ends.size(); k += 2)
    {
      Check((reinterpret_cast<std::uintptr_t>(ends[k]) - 64) % huge == 0,
        "a large output array is in a mapping of its own");
    }
    Check(std::all_of(ends.begin(), ends.end(), Mapped), "the mappings live while the copy does");
    held = nullptr;
    Check(std::none_of(ends.begin(), ends.end(), Mapped),
      "the mappings are given back whole with the last copy");
  }
  else
  {
    std::cout << "no mappings of their own here (OSM_NO_HUGE_PAGES or no /proc/self/smaps): "
                 "their checks skipped\n";
  }
  return Failures == 0 ? 0 : 1;
}

/// The defaults are written three times: the core's osm::Options, the
/// filter's constructor and the plugin's XML (what ParaView and pvpython set).
/// They must agree, but for ReportFailureToPipeline, which the XML turns off
/// on purpose (its help says why).
int TestDefaults()
{
  std::ifstream file(OSM_PLUGIN_XML);
  std::stringstream text;
  text << file.rdbuf();
  const std::string xml = text.str();
  Check(!xml.empty(), std::string("read ") + OSM_PLUGIN_XML);
  std::map<std::string, std::string> xmlDefaults;
  const std::regex property(R"re(<(?:Int|Double|IdType)VectorProperty\s([^>]*)>)re");
  const std::regex name(R"re(\bname="([^"]*)")re"), value(R"re(\bdefault_values="([^"]*)")re");
  for (auto it = std::sregex_iterator(xml.begin(), xml.end(), property);
       it != std::sregex_iterator(); ++it)
  {
    const std::string attributes = (*it)[1];
    std::smatch n, v;
    if (std::regex_search(attributes, n, name) && std::regex_search(attributes, v, value))
    {
      xmlDefaults[n[1]] = v[1];
    }
  }
  vtkNew<vtkOverlayStitchMesher> mesher;
  const osm::Options core;
  const std::map<std::string, double> filterDefaults = {
    { "MinimumAngle", mesher->GetMinimumAngle() },
    { "MaximumEdgeLength", mesher->GetMaximumEdgeLength() },
    { "Domain", mesher->GetDomain() },
    { "ResolveIntersections", mesher->GetResolveIntersections() },
    { "MergeTolerance", mesher->GetMergeTolerance() },
    { "ProjectToXYPlane", mesher->GetProjectToXYPlane() },
    { "UseInputHolePoints", mesher->GetUseInputHolePoints() },
    { "ApplyRegionAreas", mesher->GetApplyRegionAreas() },
    { "GapRatioOverlay", mesher->GetGapRatioOverlay() },
    { "MaximumSteinerPoints", static_cast<double>(mesher->GetMaximumSteinerPoints()) },
    { "InterpolatePointData", mesher->GetInterpolatePointData() },
    { "PassCellData", mesher->GetPassCellData() },
    { "GenerateEdges", mesher->GetGenerateEdges() },
    { "GenerateOverlay", mesher->GetGenerateOverlay() },
  };
  for (const auto& [property, filterValue] : filterDefaults)
  {
    const auto it = xmlDefaults.find(property);
    const std::string xmlValue = it == xmlDefaults.end() ? "(none)" : it->second;
    Check(it != xmlDefaults.end() && std::strtod(xmlValue.c_str(), nullptr) == filterValue,
      property + ": the XML's default " + xmlValue + " is the filter's " +
        std::to_string(filterValue));
  }
  Check(xmlDefaults.size() == filterDefaults.size() + 1 &&
      xmlDefaults.count("ReportFailureToPipeline") == 1,
    "every XML property with a default is compared (" + std::to_string(xmlDefaults.size()) + ")");
  Check(xmlDefaults["ReportFailureToPipeline"] == "0" && mesher->GetReportFailureToPipeline() == 1,
    "ReportFailureToPipeline: 1 in C++, 0 in ParaView");
  Check(mesher->GetNumberOfHolePoints() == 0, "no hole points");
  // The core's defaults, which osm-mesh uses too.
  Check(core.minAngleDeg == mesher->GetMinimumAngle() &&
      core.maxEdgeLength == mesher->GetMaximumEdgeLength() &&
      static_cast<int>(core.domain) == mesher->GetDomain() &&
      core.resolveCrossings == (mesher->GetResolveIntersections() != 0) &&
      core.mergeTolerance == mesher->GetMergeTolerance() &&
      core.gapRatioOverlay == (mesher->GetGapRatioOverlay() != 0) &&
      core.regionAreas == (mesher->GetApplyRegionAreas() != 0) &&
      core.maxSteinerPoints == static_cast<std::size_t>(mesher->GetMaximumSteinerPoints()),
    "the filter's defaults are osm::Options'");
  return Failures == 0 ? 0 : 1;
}

} // namespace

int main(int argc, char* argv[])
{
  const std::string test = argc > 1 ? argv[1] : "";
  int status = 1;
  if (test == "contract")
  {
    status = TestContract();
  }
  else if (test == "bad-input")
  {
    status = TestBadInput();
  }
  else if (test == "large")
  {
    status = TestLargeOutputs();
  }
  else if (test == "defaults")
  {
    status = TestDefaults();
  }
  else
  {
    std::cerr << "usage: " << argv[0] << " contract|bad-input|large|defaults\n";
    return 2;
  }
  std::cout << (status == 0 ? "PASSED" : "FAILED") << "\n";
  return status;
}
