// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// A thin layer over the core's parser (osm::readPolyFile): it only turns an
// osm::PolyFile into vtkPolyData.
#include "vtkTrianglePolyReader.h"

#include "OverlayStitchSeeds.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "OverlayStitchArrayNames.h"
#include "PolyReader.h"

#include <algorithm>
#include <cctype>
#include <fstream>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkTrianglePolyReader);

namespace
{

/// The always-present field data array of hole seeds, (x, y, 0) per hole.
void AddHolePoints(const osm::PolyFile* file, vtkPolyData* output)
{
  vtkNew<vtkDoubleArray> holes;
  holes->SetName(OverlayStitchArrayNames::HolePoints);
  holes->SetNumberOfComponents(3);
  if (file)
  {
    holes->SetNumberOfTuples(static_cast<vtkIdType>(file->pslg.holes.size()));
    for (std::size_t i = 0; i < file->pslg.holes.size(); ++i)
    {
      const osm::Point& h = file->pslg.holes[i];
      holes->SetTuple3(static_cast<vtkIdType>(i), h.x, h.y, 0.0);
    }
  }
  output->GetFieldData()->AddArray(holes);
}

/// The points, a vertex cell for each point on no segment (in point order),
/// then a line cell per segment.
void SetGeometry(const osm::Pslg& pslg, vtkPolyData* output)
{
  const auto numberOfPoints = static_cast<vtkIdType>(pslg.points.size());

  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(numberOfPoints);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    const osm::Point& p = pslg.points[static_cast<std::size_t>(i)];
    points->SetPoint(i, p.x, p.y, 0.0);
  }
  output->SetPoints(points);

  // Vertex cells for the points on no segment, in point order.
  std::vector<char> onSegment(pslg.points.size(), 0);
  for (const osm::Segment& s : pslg.segments)
  {
    onSegment[static_cast<std::size_t>(s[0])] = 1;
    onSegment[static_cast<std::size_t>(s[1])] = 1;
  }
  vtkNew<vtkCellArray> verts;
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    if (!onSegment[static_cast<std::size_t>(i)])
    {
      verts->InsertNextCell(1, &i);
    }
  }
  vtkNew<vtkCellArray> lines;
  lines->AllocateExact(
    static_cast<vtkIdType>(pslg.segments.size()), 2 * static_cast<vtkIdType>(pslg.segments.size()));
  for (const osm::Segment& s : pslg.segments)
  {
    const vtkIdType ids[2] = { s[0], s[1] };
    lines->InsertNextCell(2, ids);
  }
  output->SetVerts(verts);
  output->SetLines(lines);
}

/// PointMarker and the attributes, Attribute0, Attribute1, ...
void AddPointArrays(const osm::PolyFile& file, vtkPolyData* output)
{
  const auto numberOfPoints = static_cast<vtkIdType>(file.pslg.points.size());
  // A file with segment markers but none on its vertices has vertex markers
  // 0 to Triangle, which then gives vertices their segments' markers.
  if (!file.pointMarkers.empty() || !file.segmentMarkers.empty())
  {
    vtkNew<vtkIntArray> markers;
    markers->SetName(OverlayStitchArrayNames::PointMarker);
    markers->SetNumberOfTuples(numberOfPoints);
    for (vtkIdType i = 0; i < numberOfPoints; ++i)
    {
      markers->SetValue(
        i, file.pointMarkers.empty() ? 0 : file.pointMarkers[static_cast<std::size_t>(i)]);
    }
    output->GetPointData()->AddArray(markers);
  }

  std::size_t numberOfAttributes = 0;
  for (const std::vector<double>& a : file.pointAttributes)
  {
    numberOfAttributes = std::max(numberOfAttributes, a.size());
  }
  if (file.pointAttributes.size() == file.pslg.points.size())
  {
    for (std::size_t k = 0; k < numberOfAttributes; ++k)
    {
      vtkNew<vtkDoubleArray> attribute;
      attribute->SetName(("Attribute" + std::to_string(k)).c_str());
      attribute->SetNumberOfTuples(numberOfPoints);
      for (vtkIdType i = 0; i < numberOfPoints; ++i)
      {
        const std::vector<double>& a = file.pointAttributes[static_cast<std::size_t>(i)];
        attribute->SetValue(i, k < a.size() ? a[k] : 0.0);
      }
      output->GetPointData()->AddArray(attribute);
    }
  }
}

/// SegmentMarker, over every cell: the vertex cells (first) get marker 0.
void AddSegmentMarkers(const osm::PolyFile& file, vtkPolyData* output)
{
  if (!file.segmentMarkers.empty())
  {
    const vtkIdType numberOfVerts = output->GetNumberOfVerts();
    vtkNew<vtkIntArray> markers;
    markers->SetName(OverlayStitchArrayNames::SegmentMarker);
    markers->SetNumberOfTuples(numberOfVerts + output->GetNumberOfLines());
    for (vtkIdType c = 0; c < numberOfVerts; ++c)
    {
      markers->SetValue(c, 0);
    }
    for (std::size_t s = 0; s < file.segmentMarkers.size(); ++s)
    {
      markers->SetValue(numberOfVerts + static_cast<vtkIdType>(s), file.segmentMarkers[s]);
    }
    output->GetCellData()->AddArray(markers);
  }
}

/// The holes, the file's first index and its regions, as field data.
void AddFieldArrays(const osm::PolyFile& file, vtkPolyData* output)
{
  AddHolePoints(&file, output);

  // The numbering the file used (0 or 1), so that tools can quote its numbers.
  vtkNew<vtkIntArray> firstIndex;
  firstIndex->SetName(OverlayStitchArrayNames::FileFirstIndex);
  firstIndex->InsertNextValue(file.firstIndex);
  output->GetFieldData()->AddArray(firstIndex);

  if (!file.pslg.regions.empty())
  {
    vtkNew<vtkDoubleArray> regions;
    regions->SetName(OverlayStitchArrayNames::RegionAttributes);
    regions->SetNumberOfComponents(4);
    regions->SetNumberOfTuples(static_cast<vtkIdType>(file.pslg.regions.size()));
    for (std::size_t r = 0; r < file.pslg.regions.size(); ++r)
    {
      const osm::RegionAttribute& region = file.pslg.regions[r];
      regions->SetTuple4(
        static_cast<vtkIdType>(r), region.seed.x, region.seed.y, region.attribute, region.maxArea);
    }
    output->GetFieldData()->AddArray(regions);
  }
  // So that the seeds follow the points through Transform and the like.
  if (!file.pslg.holes.empty() || !file.pslg.regions.empty())
  {
    OverlayStitchAddSeedReference(output);
  }
}

void FillOutput(const osm::PolyFile& file, vtkPolyData* output)
{
  SetGeometry(file.pslg, output);
  AddPointArrays(file, output);
  AddSegmentMarkers(file, output);
  AddFieldArrays(file, output);
}

} // namespace

vtkTrianglePolyReader::vtkTrianglePolyReader()
  : FileName(nullptr)
{
  this->SetNumberOfInputPorts(0);
}

vtkTrianglePolyReader::~vtkTrianglePolyReader()
{
  this->SetFileName(nullptr);
}

int vtkTrianglePolyReader::CanReadFile(const char* fileName)
{
  if (!fileName)
  {
    return 0;
  }
  std::string extension(fileName);
  const std::size_t dot = extension.find_last_of('.');
  if (dot == std::string::npos)
  {
    return 0;
  }
  extension = extension.substr(dot);
  for (char& c : extension)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  if (extension != ".poly" && extension != ".node")
  {
    return 0;
  }
  std::ifstream file(fileName);
  return file.good() ? 1 : 0;
}

int vtkTrianglePolyReader::RequestInformation(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** vtkNotUsed(inputVector), vtkInformationVector* outputVector)
{
  // Said explicitly: this reader answers every piece request itself. Piece 0
  // gets the whole file and the other pieces are empty, so that a parallel
  // run (pvbatch under MPI) holds the data exactly once.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkAlgorithm::CAN_HANDLE_PIECE_REQUEST(), 1);
  return 1;
}

int vtkTrianglePolyReader::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** vtkNotUsed(inputVector), vtkInformationVector* outputVector)
{
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("The output data object is missing.");
    return 0;
  }
  // Empty points, not none: a point set without points keeps its old bounds.
  output->Initialize();
  output->SetPoints(vtkNew<vtkPoints>());

  int piece = 0;
  if (outInfo->Has(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()))
  {
    piece = outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER());
  }
  if (piece > 0)
  {
    AddHolePoints(nullptr, output);
    return 1;
  }

  // A file that cannot be read gives an error and an empty output, not a
  // failed request: the filters downstream then run on the empty output
  // (after a failed request they would not run, and keep their last outputs,
  // a mesh of the file read before: a review), and under MPI a filter
  // downstream that gathers (the mesher) would wait forever for the rank
  // whose request failed; the other pieces cannot know of it.
  if (!this->FileName || !*this->FileName)
  {
    vtkErrorMacro("No file name: set FileName to a .poly or .node file.");
    AddHolePoints(nullptr, output);
    return 1;
  }

  this->UpdateProgress(0.0);
  const osm::PolyFile file = osm::readPolyFile(this->FileName);
  if (!file.ok)
  {
    vtkErrorMacro(<< file.error);
    AddHolePoints(nullptr, output);
    return 1;
  }
  this->UpdateProgress(0.5);
  FillOutput(file, output);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkTrianglePolyReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
}
