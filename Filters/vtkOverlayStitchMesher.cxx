// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// A thin layer: vtkPolyData -> osm::Pslg, osm::mesh(), osm::Result -> three
// vtkPolyData outputs. The mesher, the input's plane (osm::PlaneMap) and
// which input polygon holds each region (osm::innermostPolygons) are in the
// plain C++ core (Filters/Core); what geometry is left here is small: which
// way the input's point normals face the mesh (NormalsOppose), and the affine map that moves
// field data seeds with their points (OverlayStitchSeeds.cxx).
#include "vtkOverlayStitchMesher.h"

#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCompositeDataSet.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnstructuredGrid.h"
#include "vtkVersionMacros.h"

#include "Geometry.h"
#include "HugePages.h"
#include "Mesher.h"
#include "OverlayStitchArrayNames.h"
#include "OverlayStitchArrays.h"
#include "OverlayStitchCellArrays.h"
#include "OverlayStitchCellData.h"
#include "OverlayStitchGather.h"
#include "OverlayStitchInternalNames.h"
#include "OverlayStitchPointData.h"
#include "OverlayStitchSeeds.h"
#include "OverlayStitchUnstructured.h"
#include "Plane.h"
#include "Predicates.h" // RoundToNearest
#include "Pslg.h"
#include "RunContext.h"
#include "Statistics.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <exception>
#include <functional>
#include <limits>
#include <new>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <unordered_set>
#include <utility>
#include <vector>

vtkStandardNewMacro(vtkOverlayStitchMesher);
// The header's vtkSetClampMacro(MinimumAngle, ...) and the plugin XML's
// range repeat the core's: change them together.
static_assert(osm::kMinAngleDegLowest == 1.0 && osm::kMinAngleDegHighest == 35.0,
  "MinimumAngle's clamp (vtkOverlayStitchMesher.h, OverlayStitchMesher.xml) follows the core's");

namespace Names = OverlayStitchArrayNames;

namespace
{

/// What an abort says: the outputs are emptied, and the filter does not fail.
constexpr const char* kAborted =
  "Meshing aborted by the user: the outputs are empty (clear AbortExecute to mesh again)";

/// Whether the run must stop, by VTK's convention: the filter's AbortExecute
/// (or, through CheckAbort, an upstream filter's) is set. CheckAbort also marks
/// the outputs ABORTED, so that the run after the caller clears the flag meshes
/// again; the flag is the caller's and stays set. VTK before CheckAbort (9.1)
/// has only the filter's own flag.
bool AbortRequested(vtkAlgorithm* filter)
{
#if VTK_VERSION_NUMBER >= VTK_VERSION_CHECK(9, 2, 20230101)
  return filter->CheckAbort();
#else
  return filter->GetAbortExecute() != 0;
#endif
}

/// The input's field data on an output, as VTK's filters pass it; the
/// output's own arrays (the statistics, EdgeClassNames) win a name clash.
/// Arrays without values are left out: a parallel run's gather cannot carry
/// them (OverlayStitchPieceToSend), and the outputs are the serial run's.
/// So is the reader's FileFirstIndex, the numbering of the file the input
/// came from: the outputs number from 0, as VTK does, and a mesh written
/// and read again must not claim its file's numbering (a user review); and
/// the reader's SeedReferencePoints, ids and coordinates of input points that
/// the outputs number otherwise (a review: a second mesher downstream would
/// move the seeds by a map of unrelated points).
void PassFieldData(vtkFieldData* in, vtkPolyData* output)
{
  vtkFieldData* out = output->GetFieldData();
  for (int a = 0; in && a < in->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = in->GetAbstractArray(a);
    const char* name = array->GetName();
    if (array->GetNumberOfTuples() > 0 &&
      !(name && std::strcmp(name, Names::FileFirstIndex) == 0) &&
      !(name && std::strcmp(name, OverlayStitchSeedReferenceName) == 0) &&
      !OverlayStitchIsInternalName(name) && (!name || !out->GetAbstractArray(name)))
    {
      out->AddArray(array);
    }
  }
}

/// The outputs of a run that meshes nothing. Empty points, not none: a point
/// set without points keeps reporting its old bounds.
void ClearOutputs(std::initializer_list<vtkPolyData*> outputs)
{
  for (vtkPolyData* output : outputs)
  {
    output->Initialize();
    output->SetPoints(vtkNew<vtkPoints>());
  }
}

/// Forwards the core's progress to the algorithm, mapped into [begin, end] of
/// the whole run, and polls the abort flag.
class ProgressAdapter : public osm::Progress
{
public:
  ProgressAdapter(vtkOverlayStitchMesher* filter, double begin, double end)
    : Filter(filter)
    , Begin(begin)
    , End(end)
  {}

  void report(double fraction, const char* phase) override
  {
    if (phase && this->Phase != phase)
    {
      this->Phase = phase;
      this->Filter->SetProgressText(phase);
    }
    this->Filter->UpdateProgress(this->Begin + (this->End - this->Begin) * fraction);
  }

  bool aborted() override
  {
    this->Aborted = this->Aborted || AbortRequested(this->Filter);
    return this->Aborted;
  }

private:
  vtkOverlayStitchMesher* Filter;
  double Begin;
  double End;
  std::string Phase;
  bool Aborted = false;
};

/// Cells that give no segment, counted by kind for the one warning about them.
struct IgnoredCells
{
  vtkIdType Strips = 0;
  vtkIdType Empty = 0;
  vtkIdType ShortLines = 0;
  vtkIdType ShortPolygons = 0;
  vtkIdType First = -1; ///< the first ignored cell (in the input the user gave)
  /// The ids the cells carry from the dataset the user gave (an unstructured
  /// grid renumbered as polydata, one with ghost cells) and their blocks: the
  /// first is by those (block, then id), else by the input's cell ids.
  vtkIdTypeArray* OwnIds = nullptr;
  vtkIdTypeArray* BlockIds = nullptr;

  /// Counts cell `cellId` in `count` when `ignore`.
  void Note(bool ignore, vtkIdType& count, vtkIdType cellId)
  {
    if (ignore)
    {
      ++count;
      if (this->First < 0 || this->Own(cellId) < this->Own(this->First))
      {
        this->First = cellId;
      }
    }
  }

  std::pair<vtkIdType, vtkIdType> Own(vtkIdType cellId) const
  {
    const auto in = [cellId](vtkIdTypeArray* ids) {
      return ids && cellId < ids->GetNumberOfTuples() ? ids->GetValue(cellId) : vtkIdType(-1);
    };
    const vtkIdType own = in(this->OwnIds);
    return { in(this->BlockIds), own >= 0 ? own : cellId };
  }

  vtkIdType Total() const
  {
    return this->Strips + this->Empty + this->ShortLines + this->ShortPolygons;
  }
  /// The warning, naming the first ignored cell of input by its id (in its
  /// block, or in the input with its ghost cells, where it carries those).
  std::string Describe(vtkPolyData* input) const
  {
    std::ostringstream msg;
    const std::string source =
      OverlayStitchSource(input->GetCellData(), OverlayStitchSourceCellIdName, this->First, "cell");
    msg << "Ignored " << this->Total() << " input cell(s), the first "
        << (source.empty() ? "cell " + std::to_string(this->First) : source) << ":";
    const char* separator = " ";
    auto item = [&](vtkIdType n, const char* what) {
      if (n > 0)
      {
        msg << separator << n << " " << what;
        separator = ", ";
      }
    };
    item(this->Strips, "triangle strip(s)");
    item(this->Empty, "empty cell(s) without points");
    item(this->ShortLines, "line(s) with a single point");
    item(this->ShortPolygons,
      "polygon(s) with fewer than 3 points (a last point repeating the first not counted)");
    msg << ". Segments come from line, polyline and polygon cells; every input point is "
           "meshed.";
    return msg.str();
  }
};

/// Reads the input's points. Returns an error message, or "" on success.
std::string ReadPoints(vtkPolyData* input, osm::Array<osm::Vec3>& points)
{
  const vtkIdType numberOfPoints = input->GetNumberOfPoints();
  if (numberOfPoints > static_cast<vtkIdType>(std::numeric_limits<int>::max()))
  {
    return "the input has " + std::to_string(numberOfPoints) +
      " points; the mesher accepts at most " + std::to_string(std::numeric_limits<int>::max());
  }
  points.resize(static_cast<std::size_t>(numberOfPoints));
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    input->GetPoint(i, p);
    const osm::Vec3 q{ p[0], p[1], p[2] };
    if (!std::isfinite(q.x) || !std::isfinite(q.y) || !std::isfinite(q.z))
    {
      return "input point " + std::to_string(i) + " has a non-finite coordinate " +
        osm::formatPoint3(q);
    }
    points[static_cast<std::size_t>(i)] = q;
  }
  return std::string();
}

/// Where a segment of the PSLG comes from: its cell (a vtkPolyData cell id)
/// and its two point ids.
struct SegmentSource
{
  vtkIdType Cell;
  vtkIdType A;
  vtkIdType B;
};

/// Whether a message names a point, segment, cell, hole or region by its
/// number ("point 4", "segment 12"), as opposed to counting them ("3 point(s)").
bool NamesNumberedItems(const std::string& message)
{
  for (const char* word : { "point ", "segment ", "cell ", "hole ", "region " })
  {
    for (std::size_t at = message.find(word); at != std::string::npos;
         at = message.find(word, at + 1))
    {
      const std::size_t next = at + std::strlen(word);
      if (next < message.size() && std::isdigit(static_cast<unsigned char>(message[next])))
      {
        return true;
      }
    }
  }
  return false;
}

/// The messages count points, segments and cells from 0 in input order; when
/// the input comes from a .poly or .node file that counts from 1 (the reader's
/// field data FileFirstIndex), those naming one say so.
std::string NumberingNote(vtkPolyData* input)
{
  return OverlayStitchCountsFromOne(input->GetFieldData())
    ? " (numbers of points, segments, cells, holes and regions in this message count from 0; "
      "the input counts from 1)"
    : "";
}

std::string Numbered(const std::string& message, const std::string& note)
{
  return NamesNumberedItems(message) ? message + note : message;
}

/// The distinct numbers below `count` that text names after `word` ("segment
/// 7"), in order, at most 4.
std::vector<std::size_t> NamedNumbers(
  const std::string& text, const std::string& word, std::size_t count)
{
  std::vector<std::size_t> named;
  for (std::size_t at = text.find(word); at != std::string::npos; at = text.find(word, at + 1))
  {
    std::size_t end = at + word.size();
    std::size_t index = 0;
    bool digits = false;
    while (end < text.size() && std::isdigit(static_cast<unsigned char>(text[end])))
    {
      index = index * 10 + static_cast<std::size_t>(text[end++] - '0');
      digits = true;
    }
    if (digits && index < count && std::find(named.begin(), named.end(), index) == named.end() &&
      named.size() < 4)
    {
      named.push_back(index);
    }
  }
  return named;
}

/// The core numbers hole seeds in the order the filter passes them: the
/// HolePoints property's first, then the input's. With both kinds, append
/// which one each named hole is.
std::string ExplainHoles(const std::string& text, std::size_t propertySeeds, std::size_t seeds)
{
  const std::vector<std::size_t> named = NamedNumbers(text, "hole ", seeds);
  if (propertySeeds == 0 || named.empty())
  {
    return text;
  }
  std::ostringstream out;
  out << text << " [";
  for (std::size_t k = 0; k < named.size(); ++k)
  {
    out << (k ? "; " : "") << "hole " << named[k] << " is seed ";
    if (named[k] < propertySeeds)
    {
      out << named[k] << " of the HolePoints property";
    }
    else
    {
      out << named[k] - propertySeeds << " of the input's field data HolePoints";
    }
  }
  out << "]";
  return out.str();
}

/// In a combined composite input, or a dataset without its ghost cells,
/// append which block and point each point the text names ("point 7") is.
std::string ExplainPoints(const std::string& text, vtkPolyData* input)
{
  std::ostringstream out;
  bool any = false;
  for (std::size_t point : NamedNumbers(text, "point ", input->GetNumberOfPoints()))
  {
    const std::string source = OverlayStitchSource(input->GetPointData(),
      OverlayStitchSourcePointIdName, static_cast<vtkIdType>(point), "point");
    // A dataset's point that kept its id needs no note.
    const bool renamed = OverlayStitchSourceId(input->GetPointData(), OverlayStitchBlockIdName,
                           static_cast<vtkIdType>(point)) >= 0 ||
      OverlayStitchSourceId(input->GetPointData(), OverlayStitchSourcePointIdName,
        static_cast<vtkIdType>(point)) != static_cast<vtkIdType>(point);
    if (!source.empty() && renamed)
    {
      out << (any ? "; " : " [") << "point " << point << " is " << source;
      any = true;
    }
  }
  return any ? text + out.str() + "]" : text;
}

/// The core names segments by their index in the PSLG ("input segment 7"):
/// append which cell and points each named segment is. In a combined input
/// (the blocks of a composite, the pieces of a parallel run) cell and point
/// ids count through the combination, not through any block the user sees,
/// and in a .poly's polydata cell ids are no numbers of the file's (lone
/// vertices come first): there the segment's ends are given by their
/// coordinates instead, after its cell's block and id in it where the input
/// is a composite.
std::string ExplainSegments(const std::string& text, const osm::Array<SegmentSource>& sources,
  vtkPolyData* input, bool byCoordinates)
{
  const std::vector<std::size_t> named = NamedNumbers(text, "segment ", sources.size());
  if (named.empty())
  {
    return text;
  }
  std::ostringstream out;
  out << text << " [";
  for (std::size_t k = 0; k < named.size(); ++k)
  {
    const SegmentSource& source = sources[named[k]];
    out << (k ? "; " : "") << "segment " << named[k];
    if (byCoordinates)
    {
      double a[3], b[3];
      input->GetPoint(source.A, a);
      input->GetPoint(source.B, b);
      const std::string cell = OverlayStitchSource(
        input->GetCellData(), OverlayStitchSourceCellIdName, source.Cell, "cell");
      if (!cell.empty())
      {
        out << " is " << cell << ",";
      }
      out << " runs from " << osm::formatPoint3({ a[0], a[1], a[2] }) << " to "
          << osm::formatPoint3({ b[0], b[1], b[2] });
    }
    else
    {
      // A dataset without its ghost cells carries its own ids (OverlayStitchGather.h).
      auto own = [](vtkDataSetAttributes* data, const char* name, vtkIdType i) {
        const vtkIdType id = OverlayStitchSourceId(data, name, i);
        return id >= 0 ? id : i;
      };
      out << " is cell " << own(input->GetCellData(), OverlayStitchSourceCellIdName, source.Cell)
          << " from point " << own(input->GetPointData(), OverlayStitchSourcePointIdName, source.A)
          << " to point " << own(input->GetPointData(), OverlayStitchSourcePointIdName, source.B);
    }
  }
  out << "]";
  return out.str();
}

/// Whether a note on arrays of this kind matters: "point" and "cell" arrays
/// when the filter carries them; any other kind (field data) always.
bool Carries(const std::string& kind, bool pointData, bool cellData)
{
  return kind == "point" ? pointData : kind == "cell" ? cellData : true;
}

/// The arrays that combining blocks or pieces left out and the filter would
/// carry (point data when interpolating, cell data when passing it), listed.
std::string ArraysLeftOut(
  std::initializer_list<const OverlayStitchGatherSummary*> summaries, bool pointData, bool cellData)
{
  std::string names;
  std::set<OverlayStitchArrayName> named; // blocks and ranks may both leave one out
  for (const OverlayStitchGatherSummary* summary : summaries)
  {
    for (const OverlayStitchArrayName& item : summary->ArraysLeftOut)
    {
      // An array some piece had too few tuples of is named once, with those.
      const bool noted = std::any_of(summary->NotCarried.begin(), summary->NotCarried.end(),
        [&item](const OverlayStitchNote& n) { return n.Array == item; });
      if (Carries(item.Kind, pointData, cellData) && !noted && named.insert(item).second)
      {
        names += (names.empty() ? "" : ", ") + item.Kind + " data " + item.Name;
      }
    }
  }
  return names;
}

/// Warns of the notes about what combining or gathering left out, but for
/// arrays the filter would not carry anyway.
void WarnOf(vtkOverlayStitchMesher* filter, const std::vector<OverlayStitchNote>& notes)
{
  for (const OverlayStitchNote& note : notes)
  {
    // Notes on the input's hole seeds (combining blocks or ranks) matter only where they are used.
    if (note.Array.Kind == "field" && note.Array.Name == "HolePoints" &&
      !filter->GetUseInputHolePoints())
    {
      continue;
    }
    if (Carries(note.Array.Kind, filter->GetInterpolatePointData(), filter->GetPassCellData()))
    {
      vtkWarningWithObjectMacro(filter, << note.Text);
    }
  }
}

/// Reads the input's cells into segments, counting the cells that give none.
void ReadSegments(
  vtkPolyData* input, osm::Pslg& pslg, osm::Array<SegmentSource>& sources, IgnoredCells& ignored)
{
  // vtkPolyData numbers its cells verts first, then lines, polygons, strips.
  vtkIdType cellId = input->GetNumberOfVerts();
  auto addSegment = [&](vtkIdType a, vtkIdType b) {
    pslg.segments.push_back({ static_cast<int>(a), static_cast<int>(b) });
    sources.push_back({ cellId, a, b });
  };
  // Lines and polylines: one segment per consecutive pair of points (a
  // repeated point gives a zero-length segment, which the core drops and counts).
  if (vtkCellArray* lines = input->GetLines())
  {
    auto it = vtk::TakeSmartPointer(lines->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      ignored.Note(n == 0, ignored.Empty, cellId);
      ignored.Note(n == 1, ignored.ShortLines, cellId);
      for (vtkIdType k = 0; k + 1 < n; ++k)
      {
        addSegment(ids[k], ids[k + 1]);
      }
      ++cellId;
    }
  }
  // Polygons: their closed edge loops (a last point equal to the first, as
  // some writers repeat it, closes the loop without a zero-length segment).
  // Neighbouring polygons of a map share edges: each shared edge is one
  // segment, of the first polygon, not a duplicate the core would warn of.
  if (vtkCellArray* polys = input->GetPolys())
  {
    std::unordered_set<std::uint64_t> polygonEdges;
    auto addPolygonEdge = [&](vtkIdType a, vtkIdType b) {
      const auto lo = static_cast<std::uint64_t>(std::min(a, b));
      const auto hi = static_cast<std::uint64_t>(std::max(a, b));
      if (polygonEdges.insert((lo << 32) | hi).second) // ids fit in 31 bits: the Pslg's are int
      {
        addSegment(a, b);
      }
    };
    auto it = vtk::TakeSmartPointer(polys->NewIterator());
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell())
    {
      vtkIdType n;
      const vtkIdType* ids;
      it->GetCurrentCell(n, ids);
      if (n >= 2 && ids[n - 1] == ids[0])
      {
        --n;
      }
      if (n < 3)
      {
        ignored.Note(n == 0, ignored.Empty, cellId);
        ignored.Note(n > 0, ignored.ShortPolygons, cellId);
      }
      for (vtkIdType k = 0; n >= 3 && k < n; ++k)
      {
        addPolygonEdge(ids[k], ids[(k + 1) % n]);
      }
      ++cellId;
    }
  }
  // Vertex and polyvertex cells need nothing: every input point is meshed.
  if (vtkCellArray* verts = input->GetVerts())
  {
    auto it = vtk::TakeSmartPointer(verts->NewIterator());
    vtkIdType vertId = 0;
    for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell(), ++vertId)
    {
      ignored.Note(it->GetCurrentCell()->GetNumberOfIds() == 0, ignored.Empty, vertId);
    }
  }
  if (vtkCellArray* strips = input->GetStrips())
  {
    for (vtkIdType k = 0; k < strips->GetNumberOfCells(); ++k)
    {
      ignored.Note(true, ignored.Strips, cellId + k);
    }
  }
}

/// Whether the field data's array of that name holds no numbers (a
/// vtkStringArray, say): such seeds are ignored with a warning, as a numeric
/// array of the wrong shape is (a review: they were ignored without a word).
std::string NotNumeric(vtkFieldData* field, const char* name)
{
  vtkAbstractArray* array = field->GetAbstractArray(name);
  if (!array || vtkArrayDownCast<vtkDataArray>(array))
  {
    return std::string();
  }
  return std::string("The input's field data array ") + name + " holds no numbers (a " +
    array->GetClassName() + "): ignored; give its seeds as a numeric array.";
}

/// The regional attributes of a .poly file, as vtkTrianglePolyReader puts them
/// in the field data: "RegionAttributes", a tuple (x, y, attribute, maximum
/// area) per region seed; (x, y, attribute) is read too. Returns a warning for
/// an array of another shape, which is ignored.
std::string ReadRegionAttributes(vtkPolyData* input, const osm::PlaneMap& map, osm::Pslg& pslg)
{
  vtkDataArray* regions = input->GetFieldData()->GetArray(Names::RegionAttributes);
  if (!regions)
  {
    return NotNumeric(input->GetFieldData(), Names::RegionAttributes);
  }
  const int components = regions->GetNumberOfComponents();
  if (!Names::IsRegionAttributesShape(components))
  {
    return "The input's field data array RegionAttributes has " + std::to_string(components) +
      " components (4 expected: x, y, attribute, maximum area): ignored.";
  }
  if (!map.seedXYDefined())
  {
    return "The input's points lie in a plane that contains the z direction, where the (x, y) "
           "seeds of its field data RegionAttributes name no single point: they are ignored "
           "(no region attribute or maximum area is applied).";
  }
  for (vtkIdType i = 0; i < regions->GetNumberOfTuples(); ++i)
  {
    double tuple[4] = { 0.0, 0.0, 0.0, -1.0 };
    regions->GetTuple(i, tuple);
    pslg.regions.push_back({ map.seedXY(tuple[0], tuple[1]), tuple[2], tuple[3] });
  }
  return std::string();
}

/// Output arrays live in the core's huge-page mappings (HugePages.h), like the
/// core's own arrays: a mesh of 10^6 triangles fills about 100 MB of them, and
/// each first touch of a small page costs about 10 us on a virtual machine.
/// VTK's free function gets only the values' address, so the mapping's size
/// sits in a header just before them.
constexpr std::size_t kHeaderBytes = 64;

void FreeMapping(void* values)
{
  char* base = static_cast<char*>(values) - kHeaderBytes;
  std::size_t bytes = 0;
  std::memcpy(&bytes, base, sizeof bytes);
  osm::pages::unmap(base, bytes);
}

/// array->SetNumberOfTuples(tuples), in a mapping of its own if that large.
template <typename ArrayT>
void Allocate(ArrayT* array, vtkIdType tuples)
{
  using T = typename ArrayT::ValueType;
  const vtkIdType values = tuples * array->GetNumberOfComponents();
  const std::size_t bytes = kHeaderBytes + static_cast<std::size_t>(values) * sizeof(T);
  if (values <= 0 || !osm::pages::ownMapping(bytes))
  {
    array->SetNumberOfTuples(tuples);
    if (array->GetNumberOfTuples() != tuples)
    {
      throw std::bad_alloc(); // as the mapping below does; RequestData reports it
    }
    return;
  }
  char* base = static_cast<char*>(osm::pages::map(bytes));
  std::memcpy(base, &bytes, sizeof bytes);
  array->SetArray(reinterpret_cast<T*>(base + kHeaderBytes), values, 0,
    vtkAbstractArray::VTK_DATA_ARRAY_USER_DEFINED);
  array->SetArrayFreeFunction(&FreeMapping);
}

/// Reports the fraction done of one step of the output and returns true to
/// stop it (an abort): the step then returns nothing. Steps poll every 2^16
/// items, so that an abort is seen within milliseconds at any size.
using Poll = std::function<bool(double)>;

/// The part [a, b] of poll's range, for a sub-step (a copy of poll: it may outlive it).
Poll Part(const Poll& poll, double a, double b)
{
  return [poll, a, b](double fraction) { return poll(a + (b - a) * fraction); };
}

/// Whether item i of n is one to poll at, and poll says stop.
bool ShouldStop(std::size_t i, std::size_t n, const Poll& poll)
{
  return (i & 0xffff) == 0xffff && poll(static_cast<double>(i) / static_cast<double>(n));
}

/// Builds a vtkCellArray in bulk from offsets and connectivity, in VTK's
/// default 64-bit storage. Not the 32-bit storage, 16 bytes less per
/// triangle: VTK's subdivision filters (Loop, Linear) refuse any mesh in it
/// as "non-manifold" (a review; in ParaView 5.11 a plane's 24 triangles in
/// 32-bit storage fail, the same in 64-bit do not).
template <typename VertexOf>
vtkSmartPointer<vtkCellArray> MakeCells(
  std::size_t numberOfCells, int cellSize, const VertexOf& vertexOf, const Poll& poll)
{
  vtkNew<vtkIdTypeArray> offsets;
  Allocate(offsets.Get(), static_cast<vtkIdType>(numberOfCells) + 1);
  vtkNew<vtkIdTypeArray> connectivity;
  Allocate(connectivity.Get(), static_cast<vtkIdType>(numberOfCells) * cellSize);
  vtkIdType next = 0;
  for (std::size_t c = 0; c < numberOfCells; ++c)
  {
    if (ShouldStop(c, numberOfCells, poll))
    {
      return nullptr;
    }
    offsets->SetValue(static_cast<vtkIdType>(c), next);
    for (int k = 0; k < cellSize; ++k)
    {
      connectivity->SetValue(next++, static_cast<vtkIdType>(vertexOf(c, k)));
    }
  }
  offsets->SetValue(static_cast<vtkIdType>(numberOfCells), next);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, connectivity);
  return cells;
}

/// The output points, in bulk; inputOf[i] is the input point that vertex i is, or -1.
vtkSmartPointer<vtkPoints> MakePoints(const osm::Array<osm::Point>& vertices,
  const osm::PlaneMap& map, const Poll& poll, const osm::Array<long long>* inputOf = nullptr)
{
  vtkNew<vtkDoubleArray> coordinates;
  coordinates->SetNumberOfComponents(3);
  Allocate(coordinates.Get(), static_cast<vtkIdType>(vertices.size()));
  for (std::size_t i = 0; i < vertices.size(); ++i)
  {
    if (ShouldStop(i, vertices.size(), poll))
    {
      return nullptr;
    }
    const osm::Vec3 q = map.toSpace(vertices[i], inputOf ? (*inputOf)[i] : -1);
    const double p[3] = { q.x, q.y, q.z };
    coordinates->SetTypedTuple(static_cast<vtkIdType>(i), p);
  }
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetData(coordinates);
  return points;
}

/// Points, then triangles, each half of poll's range; false if stopped.
/// reversed: each triangle wound the other way round (NormalsOppose).
bool MakeTriangles(const osm::TriMesh& mesh, const osm::PlaneMap& map, vtkPolyData* output,
  const Poll& poll, const osm::Array<long long>* inputOf = nullptr, bool reversed = false)
{
  auto points = MakePoints(mesh.vertices, map, Part(poll, 0.0, 0.5), inputOf);
  if (!points || poll(0.5))
  {
    return false;
  }
  output->SetPoints(points);
  auto cells = MakeCells(
    mesh.triangles.size(), 3,
    [&mesh, reversed](std::size_t c, int k) {
      return static_cast<vtkIdType>(mesh.triangles[c][reversed && k > 0 ? 3 - k : k]);
    },
    Part(poll, 0.5, 1.0));
  if (!cells)
  {
    return false;
  }
  output->SetPolys(cells);
  return true;
}

template <typename ArrayT>
vtkSmartPointer<ArrayT> MakeArray(const char* name, vtkIdType size)
{
  auto array = vtkSmartPointer<ArrayT>::New();
  array->SetName(name);
  Allocate(array.Get(), size);
  return array;
}

/// Whether point normals (3 components, the input's, carried to the mesh) point
/// mostly to the side from which the mesh's triangles, all wound one way in
/// the plane, are clockwise: they are then reversed, so that the winding and
/// the carried normals agree (a review: a Plane source's normals, -z, on
/// triangles counter-clockwise seen from +z).
bool NormalsOppose(vtkDataArray* normals, const osm::TriMesh& mesh, const osm::PlaneMap& map)
{
  if (!normals || normals->GetNumberOfComponents() != 3 || mesh.triangles.empty())
  {
    return false;
  }
  const osm::Triangle& t = mesh.triangles[0];
  const osm::Vec3 a = map.toSpace(mesh.vertices[t[0]]), b = map.toSpace(mesh.vertices[t[1]]),
                  c = map.toSpace(mesh.vertices[t[2]]);
  const double ab[3] = { b.x - a.x, b.y - a.y, b.z - a.z };
  const double ac[3] = { c.x - a.x, c.y - a.y, c.z - a.z };
  double side[3];
  vtkMath::Cross(ab, ac, side);
  double sum = 0.0;
  for (vtkIdType i = 0; i < normals->GetNumberOfTuples(); ++i)
  {
    double n[3];
    normals->GetTuple(i, n);
    const double d = vtkMath::Dot(n, side);
    sum += std::isfinite(d) ? d : 0.0;
  }
  return sum < 0.0;
}

/// Fills the Mesh output; stops early when poll says so. reversed: the
/// triangles wound the other way round (NormalsOppose).
void FillMesh(const osm::Result& result, const osm::PlaneMap& map, vtkPolyData* output,
  const Poll& poll, bool reversed)
{
  // Each mesh vertex that is an input point gets that point's original
  // coordinates (the first of merged points): by index, not by a round trip.
  osm::Array<long long> inputOf(result.mesh.vertices.size(), -1);
  for (std::size_t i = 0; i < result.inputVertex.size(); ++i)
  {
    const int v = result.inputVertex[i];
    if (v >= 0 && inputOf[static_cast<std::size_t>(v)] < 0)
    {
      inputOf[static_cast<std::size_t>(v)] = static_cast<long long>(i);
    }
  }
  if (!MakeTriangles(result.mesh, map, output, Part(poll, 0.0, 0.4), &inputOf, reversed))
  {
    return;
  }

  const auto numberOfVertices = static_cast<vtkIdType>(result.mesh.vertices.size());
  auto origin = MakeArray<vtkUnsignedCharArray>(Names::VertexOrigin, numberOfVertices);
  for (vtkIdType i = 0; i < numberOfVertices; ++i)
  {
    const auto value = static_cast<std::size_t>(i) < result.vertexOrigin.size()
      ? result.vertexOrigin[static_cast<std::size_t>(i)]
      : osm::VertexOrigin::Other;
    origin->SetValue(i, static_cast<unsigned char>(value));
  }
  output->GetPointData()->AddArray(origin);
  auto inputPoint = MakeArray<vtkIdTypeArray>(Names::InputPointId, numberOfVertices);
  std::copy(inputOf.begin(), inputOf.end(), inputPoint->GetPointer(0));
  output->GetPointData()->AddArray(inputPoint);

  const auto numberOfTriangles = static_cast<vtkIdType>(result.mesh.triangles.size());
  auto minAngle = MakeArray<vtkDoubleArray>(Names::MinAngle, numberOfTriangles);
  auto maxAngle = MakeArray<vtkDoubleArray>(Names::MaxAngle, numberOfTriangles);
  auto regionId = MakeArray<vtkIntArray>(Names::RegionId, numberOfTriangles);
  const double degrees = 180.0 / std::acos(-1.0);
  const auto& v = result.mesh.vertices;
  const Poll arrays = Part(poll, 0.4, 1.0);
  for (vtkIdType t = 0; t < numberOfTriangles; ++t)
  {
    if (ShouldStop(
          static_cast<std::size_t>(t), static_cast<std::size_t>(numberOfTriangles), arrays))
    {
      return;
    }
    const osm::Triangle& tri = result.mesh.triangles[static_cast<std::size_t>(t)];
    double lo = 0.0;
    double hi = 0.0;
    osm::angleRange(v[tri[0]], v[tri[1]], v[tri[2]], lo, hi);
    lo *= degrees;
    hi *= degrees;
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
  if (!result.regionAttribute.empty())
  {
    auto attribute = MakeArray<vtkDoubleArray>(Names::RegionAttribute, numberOfTriangles);
    std::copy(
      result.regionAttribute.begin(), result.regionAttribute.end(), attribute->GetPointer(0));
    output->GetCellData()->AddArray(attribute);
  }

  for (const auto& item : result.stats.items())
  {
    auto value = MakeArray<vtkDoubleArray>(item.first.c_str(), 1);
    value->SetValue(0, item.second);
    output->GetFieldData()->AddArray(value);
  }
}

/// Fills the Edges output; stops early when poll says so.
void FillEdges(
  const osm::Result& result, const osm::PlaneMap& map, vtkPolyData* output, const Poll& poll)
{
  auto points = MakePoints(result.edgeVertices, map, Part(poll, 0.0, 0.2));
  if (!points)
  {
    return;
  }
  output->SetPoints(points);
  auto cells = MakeCells(
    result.edges.size(), 2,
    [&result](std::size_t c, int k) {
      return static_cast<vtkIdType>(k == 0 ? result.edges[c].a : result.edges[c].b);
    },
    Part(poll, 0.2, 0.5));
  if (!cells)
  {
    return;
  }
  output->SetLines(cells);

  const auto numberOfEdges = static_cast<vtkIdType>(result.edges.size());
  auto overlay = MakeArray<vtkUnsignedCharArray>(Names::Overlay, numberOfEdges);
  auto kept = MakeArray<vtkUnsignedCharArray>(Names::Kept, numberOfEdges);
  auto discarded = MakeArray<vtkUnsignedCharArray>(Names::Discarded, numberOfEdges);
  auto isInput = MakeArray<vtkUnsignedCharArray>(Names::Input, numberOfEdges);
  auto edgeClass = MakeArray<vtkUnsignedCharArray>(Names::EdgeClass, numberOfEdges);
  const Poll arrays = Part(poll, 0.5, 1.0);
  for (vtkIdType e = 0; e < numberOfEdges; ++e)
  {
    if (ShouldStop(static_cast<std::size_t>(e), static_cast<std::size_t>(numberOfEdges), arrays))
    {
      return;
    }
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
  output->GetCellData()->SetActiveScalars(Names::EdgeClass);

  // The names of the EdgeClass categories, indexed by value.
  vtkNew<vtkStringArray> names;
  names->SetName(Names::EdgeClassNames);
  for (auto c : { osm::EdgeClass::Uncrossed, osm::EdgeClass::Kept, osm::EdgeClass::Discarded,
         osm::EdgeClass::Input })
  {
    names->InsertNextValue(osm::edgeClassName(c));
  }
  output->GetFieldData()->AddArray(names);
}

} // namespace

//------------------------------------------------------------------------------
vtkOverlayStitchMesher::vtkOverlayStitchMesher()
  : MinimumAngle(30.0)
  , MaximumEdgeLength(0.0)
  , Domain(DOMAIN_AUTO)
  , ResolveIntersections(1)
  , MergeTolerance(0.0)
  , ProjectToXYPlane(0)
  , UseInputHolePoints(1)
  , ReportFailureToPipeline(1)
  , ApplyRegionAreas(0)
  , GapRatioOverlay(0)
  , MaximumSteinerPoints(0)
  , InterpolatePointData(1)
  , PassCellData(1)
  , GenerateEdges(1)
  , GenerateOverlay(1)
  , Controller(nullptr)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(3);
  this->SetController(vtkMultiProcessController::GetGlobalController());
}

//------------------------------------------------------------------------------
vtkOverlayStitchMesher::~vtkOverlayStitchMesher()
{
  this->SetController(nullptr);
}

//------------------------------------------------------------------------------
vtkCxxSetObjectMacro(vtkOverlayStitchMesher, Controller, vtkMultiProcessController);

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::AddHolePoint(double x, double y)
{
  this->HolePoints.push_back(x);
  this->HolePoints.push_back(y);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::AddHolePointCoordinate(double value)
{
  this->HolePoints.push_back(value);
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
    vtkErrorMacro("GetHolePoint: no hole point " << i << " (there are "
                                                 << this->GetNumberOfHolePoints() << ")");
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
    // Composite input is accepted whole and combined into one graph
    // (RequestData): meshed block by block, its blocks would overlap with
    // seams, and under MPI the ranks would gather once per local block, a
    // different number of times each, and hang.
    // Other datasets (image data, structured grids) are accepted here only to
    // be refused once with a remedy (LocalPiece): the pipeline's own type
    // error names no remedy and is printed once per pipeline pass.
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkDataSet");
    info->Append(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkCompositeDataSet");
    return 1;
  }
  return 0;
}

//------------------------------------------------------------------------------
namespace
{
/// What RequestData returns after reporting an error: 0, VTK's failure, in a
/// serial run, so that Update() returns 0 too (unless the filter's
/// ReportFailureToPipeline is off, as in ParaView); 1 in a parallel one,
/// whose other ranks return 1 with empty outputs: a failure on rank 0 alone
/// would stop the filters downstream there, while on the other ranks they
/// would wait for rank 0 in their collective steps.
bool Parallel(vtkOverlayStitchMesher* self)
{
  vtkMultiProcessController* controller = self->GetController();
  return controller && controller->GetNumberOfProcesses() > 1;
}

int Failure(vtkOverlayStitchMesher* self)
{
  return Parallel(self) || !self->GetReportFailureToPipeline() ? 1 : 0;
}
} // namespace

//------------------------------------------------------------------------------
/// One run of RequestData: the input made ready (cleaned, combined,
/// gathered), read as a PSLG, meshed, and the outputs filled. Each step
/// reports its own errors; one that ends the run returns what RequestData
/// returns.
class vtkOverlayStitchMesher::MeshRun
{
public:
  MeshRun(vtkOverlayStitchMesher* self, vtkPolyData* mesh, vtkPolyData* edges, vtkPolyData* overlay)
    : Self(self)
    , Mesh(mesh)
    , Edges(edges)
    , Overlay(overlay)
    , AbortSaidBefore(std::exchange(self->AbortSaid, false)) // set again if this run aborts
  {}

  int Execute(vtkDataObject* data)
  {
    if (auto stop = this->Prepare(data))
    {
      return *stop;
    }
    if (auto stop = this->ReadPslg())
    {
      return *stop;
    }
    this->KeepInputZ();
    const bool interpolate = this->Self->GetInterpolatePointData() &&
      OverlayStitchHasUserArrays(this->Input->GetPointData());
    if (auto stop = this->MeshPslg(interpolate))
    {
      return *stop;
    }
    return this->FillOutputs(interpolate);
  }

private:
  std::optional<int> Prepare(vtkDataObject* data);
  vtkSmartPointer<vtkPolyData> LocalPiece(vtkDataObject* data, std::string& refused);
  std::optional<int> ReadPslg();
  void KeepInputZ();
  std::optional<int> ReadHoleSeeds();
  osm::Options MakeOptions(bool interpolate) const;
  std::optional<int> MeshPslg(bool interpolate);
  int FillOutputs(bool interpolate);
  /// The input cells of the segments, where point or cell data are carried.
  std::vector<vtkIdType> SegmentCells() const;
  /// The Mesh output and its data, from lo to hi of the run; false if aborted.
  bool FillMeshOutput(
    bool interpolate, const std::vector<vtkIdType>& segmentCells, double lo, double hi);
  void AddFieldCounts();
  void FillEdgesOutput(const std::vector<vtkIdType>& segmentCells, double lo, double hi);
  /// An output's own arrays, which an input array may not take the name of
  /// (InputBlockId only for a composite input, which alone has it).
  template <std::size_t N>
  std::vector<std::string> OwnNames(const std::array<const char*, N>& own) const
  {
    std::vector<std::string> names(own.begin(), own.end());
    if (this->Composite)
    {
      names.emplace_back(Names::InputBlockId);
    }
    return names;
  }
  bool Aborted();
  void SayAborted();
  /// Where the output phase starts in the run's progress: the Edges and
  /// Overlay outputs take about a quarter of a run to fill (us48.poly: the
  /// output phase took 35% of the time with both, 10% without).
  double OutputStart() const
  {
    return 0.9 - (this->Self->GenerateEdges ? 0.15 : 0.0) -
      (this->Self->GenerateOverlay ? 0.1 : 0.0);
  }

  vtkOverlayStitchMesher* Self;
  vtkPolyData* Mesh;
  vtkPolyData* Edges;
  vtkPolyData* Overlay;
  bool AbortSaidBefore;                      // by the run before, itself aborted (SayAborted)
  vtkSmartPointer<vtkDataObject> WellFormed; // the input, cleaned of what it cannot hold
  vtkSmartPointer<vtkPolyData> Gathered;     // the whole input, on the rank that meshes
  vtkPolyData* Input = nullptr;              // = Gathered
  bool Composite = false;
  OverlayStitchGatherSummary Combination; // of this rank's blocks
  OverlayStitchGatherSummary Gather;      // of the ranks' pieces
  osm::Array<osm::Vec3> Points;           // the input's, which Map refers to
  osm::PlaneMap Map;
  osm::Pslg Pslg;
  osm::Array<SegmentSource> SegmentSources;
  IgnoredCells Ignored;
  vtkIdType InputHoles = 0;
  std::string Numbering; // the note on numbers that error messages end with
  osm::Result Result;
  // Carrying point data takes its scratch memory from the pages the mesher
  // frees (kept while this lives) instead of fresh ones, whose first touch
  // costs most of its time on a virtual machine.
  std::optional<osm::pages::Reuse> Reuse;
};

/// This rank's piece of the input, cleaned (internal names, malformed cell
/// arrays), a grid read as polydata, a composite's blocks combined; refused
/// says why it is refused, if it is.
vtkSmartPointer<vtkPolyData> vtkOverlayStitchMesher::MeshRun::LocalPiece(
  vtkDataObject* data, std::string& refused)
{
  vtkOverlayStitchMesher* self = this->Self;
  if (vtkDataSet::SafeDownCast(data) && !vtkPolyData::SafeDownCast(data) &&
    !vtkUnstructuredGrid::SafeDownCast(data))
  {
    // Still gathered, as a refused piece, so that no rank waits for this one.
    refused = data->GetClassName();
    vtkErrorWithObjectMacro(self,
      "Cannot mesh a " << refused
                       << ": the filter meshes points and line segments, of polydata or an "
                          "unstructured grid. Apply Contour first to mesh its isolines, or "
                          "Extract Surface to mesh the edges of its cells.");
    return OverlayStitchRefusedPiece();
  }
  // Field data seeds written with reference points (the .poly reader's)
  // follow the points through Transform and the like.
  std::string stayed;
  const vtkSmartPointer<vtkDataObject> seedsFollowing =
    OverlayStitchWithBlocksReplaced(data, [&stayed](vtkDataObject* block, int index) {
      std::string note;
      vtkSmartPointer<vtkDataObject> moved = OverlayStitchSeedsFollowingPoints(block, note);
      if (!note.empty() && stayed.empty())
      {
        stayed = (index < 0 ? "Of the input: " : "Of block " + std::to_string(index) + ": ") + note;
      }
      return moved;
    });
  if (!stayed.empty())
  {
    vtkWarningWithObjectMacro(self, << stayed << ".");
  }
  // Arrays named like those the filter adds would stand for them.
  std::vector<std::string> internalNames;
  const vtkSmartPointer<vtkDataObject> withoutInternal =
    OverlayStitchWithoutInternalArrays(seedsFollowing, internalNames);
  if (!internalNames.empty())
  {
    vtkWarningWithObjectMacro(
      self, << "Ignored " << internalNames.size()
            << " input array(s) named like those the filter gives its input internally, e.g. the "
            << internalNames.front() << ". Rename them to have them carried to the outputs.");
  }
  // Malformed cell arrays are said here, on the rank that holds them, and
  // their datasets marked and emptied: every rank still gathers, and the
  // rank that meshes refuses the input.
  std::string& malformed = refused;
  this->WellFormed = OverlayStitchWithWellFormedCells(withoutInternal, malformed);
  if (!malformed.empty())
  {
    vtkErrorWithObjectMacro(
      self, "Cannot mesh the input: a cell array is malformed (" << malformed << ").");
  }
  vtkDataObject* inputObject = this->WellFormed;
  vtkSmartPointer<vtkPolyData> local = vtkPolyData::SafeDownCast(inputObject);
  if (auto* grid = vtkUnstructuredGrid::SafeDownCast(inputObject))
  {
    // Its cells' ids, as polydata renumbers them, only in a serial run: a
    // rank's piece of a single dataset has ids of its own (as for ghost
    // cells). Each rank says what it leaves out of its piece.
    vtkMultiProcessController* controller = self->GetController();
    const int ranks = controller ? controller->GetNumberOfProcesses() : 1;
    const std::string where =
      ranks > 1 ? "the piece of rank " + std::to_string(controller->GetLocalProcessId()) : "";
    std::vector<OverlayStitchNote> notes;
    vtkIdType ignoredCells = 0;
    local = OverlayStitchPolyDataOf(grid, ranks <= 1, where, notes, ignoredCells);
    WarnOf(self, notes);
    if (ignoredCells > 0)
    {
      // Counted on every rank, summed by the gather.
      local = OverlayStitchWithIgnoredCells(local, ignoredCells);
    }
  }
  // A composite input is one graph: this rank's polydata (and grid) blocks, combined.
  if (auto* composite = vtkCompositeDataSet::SafeDownCast(inputObject))
  {
    this->Composite = true;
    std::vector<std::string> ignoredBlocks;
    local = OverlayStitchCombineBlocks(composite, ignoredBlocks, &this->Combination);
    if (!ignoredBlocks.empty())
    {
      vtkWarningWithObjectMacro(self,
        << "Ignored " << ignoredBlocks.size()
        << " block(s) of the composite input that are neither polydata nor unstructured grids "
           "(the first: "
        << ignoredBlocks.front()
        << "); segments come from the polydata and unstructured grid blocks, which are meshed "
           "together.");
    }
    // Said here, on the rank that holds the blocks: other ranks' notes do
    // not reach rank 0.
    WarnOf(self, this->Combination.NotCarried);
  }
  return local;
}

/// This rank's piece, gathered with the others' on the rank that meshes.
std::optional<int> vtkOverlayStitchMesher::MeshRun::Prepare(vtkDataObject* data)
{
  vtkOverlayStitchMesher* self = this->Self;
  std::string refused;
  vtkSmartPointer<vtkPolyData> local;
  try
  {
    local = this->LocalPiece(data, refused);
  }
  catch (const std::bad_alloc&)
  {
    // Still gathered, as a refused piece: a rank that left the gather would
    // leave the others waiting for it (a review).
    refused = "out of memory";
    vtkErrorWithObjectMacro(self, "Cannot mesh the input: out of memory while reading it.");
    local = OverlayStitchRefusedPiece();
  }
  // Parallel runs (pvbatch, pvserver): every rank takes part in gathering the whole input
  // on rank 0, which meshes it; the other ranks keep empty outputs (OverlayStitchGather.h).
  // A rank whose blocks are invalid still takes part, or the others would wait for it.
  const bool meshHere =
    OverlayStitchGatherInput(self->GetController(), local, this->Gathered, &this->Gather);
  // Cells naming points their piece lacks: said with the piece's own ids (this
  // rank's blocks first), since combining leaves such an id as -1.
  const OverlayStitchGatherSummary& invalid =
    this->Combination.InvalidCells > 0 || !meshHere ? this->Combination : this->Gather;
  if (invalid.InvalidCells > 0)
  {
    vtkErrorWithObjectMacro(self,
      "Cannot mesh the input: " << invalid.FirstInvalidCell << " (" << invalid.InvalidCells
                                << " cell(s) refer to points that do not exist).");
  }
  this->Input = this->Gathered;
  if (!meshHere)
  {
    return 1;
  }
  // Another rank's refusal was said there (rank 0 tells which).
  if (refused.empty() && this->Gather.MalformedPieces > 0)
  {
    vtkErrorWithObjectMacro(self,
      "Cannot mesh the input: " << this->Gather.FirstMalformedPiece
                                << " was refused on its rank (a malformed cell array, or too "
                                   "little memory: that rank's error says which).");
  }
  if (this->Combination.InvalidCells > 0 || this->Gather.InvalidCells > 0 || !refused.empty() ||
    this->Gather.MalformedPieces > 0)
  {
    return Failure(self);
  }
  if (!this->Input)
  {
    vtkErrorWithObjectMacro(self, "No input polydata.");
    return Failure(self);
  }
  WarnOf(self, this->Gather.NotCarried);
  const std::string leftOut = ArraysLeftOut({ &this->Combination, &this->Gather },
    self->GetInterpolatePointData(), self->GetPassCellData());
  if (!leftOut.empty())
  {
    vtkWarningWithObjectMacro(
      self, << "Not carried to the outputs, since not every block or rank's piece of the input has "
               "them (with the same type and components): "
            << leftOut << ".");
  }
  return std::nullopt;
}

/// Input projected onto XY keeps its z as the point array InputZ, carried
/// to the mesh as other point data, so that contour lines at their heights
/// give a terrain (Warp By Scalar) instead of a plane at the mean z. An input
/// array of that name is carried instead.
void vtkOverlayStitchMesher::MeshRun::KeepInputZ()
{
  vtkPointData* pointData = this->Input->GetPointData();
  if (!this->Map.isProjected() || !this->Self->GetInterpolatePointData() ||
    pointData->GetAbstractArray(Names::InputZ) ||
    static_cast<vtkIdType>(this->Points.size()) != this->Input->GetNumberOfPoints())
  {
    return;
  }
  auto z = vtkSmartPointer<vtkDoubleArray>::New();
  z->SetName(Names::InputZ);
  z->SetNumberOfValues(static_cast<vtkIdType>(this->Points.size()));
  for (std::size_t i = 0; i < this->Points.size(); ++i)
  {
    z->SetValue(static_cast<vtkIdType>(i), this->Points[i].z);
  }
  // On a copy: the input may be the caller's own dataset.
  auto withZ = vtkSmartPointer<vtkPolyData>::New();
  withZ->ShallowCopy(this->Input);
  withZ->GetPointData()->AddArray(z);
  this->Gathered = withZ;
  this->Input = withZ;
}

/// Phase "input": the points, the plane they lie in, the segments, the hole
/// seeds and the regional attributes, into Pslg.
std::optional<int> vtkOverlayStitchMesher::MeshRun::ReadPslg()
{
  vtkOverlayStitchMesher* self = this->Self;
  vtkPolyData* input = this->Input;
  self->SetProgressText("input");
  self->UpdateProgress(0.0);
  osm::Array<osm::Vec3>& points = this->Points;
  std::string inputError = ReadPoints(input, points);
  // Float coordinates are rounded to 2^-24 of themselves: a tilted plane's
  // points, as a slice gives them, lie that far off it.
  const bool floats = (input->GetPoints() && input->GetPoints()->GetDataType() == VTK_FLOAT) ||
    this->Combination.FloatPoints || this->Gather.FloatPoints;
  const double roundoff = floats ? 0x1p-24 : 0.0;
  if (inputError.empty())
  {
    inputError = this->Map.choose(points, self->GetProjectToXYPlane() != 0, roundoff);
  }
  // Composite blocks and the pieces of a parallel run are meshed as one
  // combined input, whose numbers are not any single block's.
  // A composite's cells and points carry their blocks' ids: messages add them.
  const bool combined = this->Composite || this->Gather.Ranks > 1;
  this->Numbering = !combined ? NumberingNote(input)
    : this->Composite
    ? std::string(" (numbers of points, segments and cells in this message count through the "
                  "combined input: every polydata or unstructured grid block, or every rank's "
                  "piece, in turn; blocks are named by their flat index, as InputBlockId does") +
      (this->Combination.CountsFromOne
          ? "; a block's cells count from 0, also where its file counts from 1)"
          : ")")
    : " (numbers of points, segments and cells in this message count through the combined "
      "input: every rank's piece in turn)";
  if (!inputError.empty())
  {
    vtkErrorWithObjectMacro(self,
      "Cannot mesh the input: " << Numbered(ExplainPoints(inputError, input), this->Numbering));
    return Failure(self);
  }
  this->Pslg.points.reserve(points.size());
  for (const osm::Vec3& p : points)
  {
    this->Pslg.points.push_back(this->Map.toPlane(p));
  }
  this->Map.indexInputPoints(this->Pslg.points);
  if (this->Map.isProjected())
  {
    vtkWarningWithObjectMacro(
      self, << "The input points are not in a plane z = constant: projected onto the XY plane "
               "(ProjectToXYPlane); the outputs lie at z = "
            << this->Map.z() << ", the mean z"
            << (self->GetInterpolatePointData()
                   ? ", and the mesh carries the input's z as the point array InputZ."
                   : "."));
  }
  this->Ignored.OwnIds =
    vtkIdTypeArray::SafeDownCast(input->GetCellData()->GetArray(OverlayStitchSourceCellIdName));
  this->Ignored.BlockIds =
    vtkIdTypeArray::SafeDownCast(input->GetCellData()->GetArray(OverlayStitchBlockIdName));
  ReadSegments(input, this->Pslg, this->SegmentSources, this->Ignored);
  if (this->Ignored.Total() > 0)
  {
    vtkWarningWithObjectMacro(self, << this->Ignored.Describe(input));
  }
  if (auto stop = this->ReadHoleSeeds())
  {
    return stop;
  }
  const std::string regionsWarning = ReadRegionAttributes(input, this->Map, this->Pslg);
  if (!regionsWarning.empty())
  {
    vtkWarningWithObjectMacro(self, << regionsWarning);
  }
  if (AbortRequested(self))
  {
    this->SayAborted();
    return 1;
  }
  self->UpdateProgress(0.05);
  return std::nullopt;
}

/// The hole seeds of the HolePoints property, (x, y), and of the input's
/// field data, (x, y, z) or (x, y).
std::optional<int> vtkOverlayStitchMesher::MeshRun::ReadHoleSeeds()
{
  vtkOverlayStitchMesher* self = this->Self;
  // In a plane that contains the z direction, an (x, y) seed names a whole
  // vertical line of the plane: refused rather than placed at some height.
  vtkFieldData* field = this->Input->GetFieldData();
  vtkDataArray* fieldHoles =
    self->GetUseInputHolePoints() ? field->GetArray(Names::HolePoints) : nullptr;
  // (Region seeds there are left out with a warning (ReadRegionAttributes):
  // they label and size regions, and a .poly's region line refused every
  // mesh of its file turned upright, a review.)
  const char* xySeeds = !self->HolePoints.empty()            ? "the HolePoints property"
    : fieldHoles && fieldHoles->GetNumberOfComponents() == 2 ? "the input's 2-component HolePoints"
                                                             : nullptr;
  if (xySeeds && !this->Map.seedXYDefined())
  {
    vtkErrorWithObjectMacro(self,
      "Cannot mesh the input: its points lie in a plane that contains the z direction, where a "
      "seed given as (x, y), as in "
        << xySeeds
        << ", names no single point; give hole seeds as the input's field data HolePoints with 3 "
           "components (x, y, z).");
    return Failure(self);
  }
  const std::vector<double>& property = self->HolePoints;
  if (property.size() % 2 != 0)
  {
    vtkWarningWithObjectMacro(self, << "HolePoints has an odd number of values (" << property.size()
                                    << "): seeds are (x, y) pairs, and the last value, "
                                    << property.back() << ", has no y; it is ignored.");
  }
  for (std::size_t i = 0; i + 1 < property.size(); i += 2)
  {
    this->Pslg.holes.push_back(this->Map.seedXY(property[i], property[i + 1]));
  }
  if (!fieldHoles)
  {
    if (self->GetUseInputHolePoints())
    {
      if (const std::string said = NotNumeric(field, Names::HolePoints); !said.empty())
      {
        vtkWarningWithObjectMacro(self, << said);
      }
    }
    return std::nullopt;
  }
  const int components = fieldHoles->GetNumberOfComponents();
  if (!Names::IsHolePointsShape(components))
  {
    vtkWarningWithObjectMacro(
      self, << "The input's field data array HolePoints has " << components
            << " components (2 or 3 expected: x, y and perhaps z): ignored.");
    return std::nullopt;
  }
  this->InputHoles = fieldHoles->GetNumberOfTuples();
  for (vtkIdType i = 0; i < this->InputHoles; ++i)
  {
    double seed[3] = { 0.0, 0.0, 0.0 };
    fieldHoles->GetTuple(i, seed);
    this->Pslg.holes.push_back(components == 3 && this->Map.isFitted()
        ? this->Map.toPlane(osm::Vec3{ seed[0], seed[1], seed[2] })
        : this->Map.seedXY(seed[0], seed[1]));
  }
  return std::nullopt;
}

/// The core's options, from the filter's properties.
osm::Options vtkOverlayStitchMesher::MeshRun::MakeOptions(bool interpolate) const
{
  const vtkOverlayStitchMesher* self = this->Self;
  osm::Options options;
  options.minAngleDeg = self->MinimumAngle;
  options.maxEdgeLength = self->MaximumEdgeLength;
  switch (self->Domain)
  {
    case vtkOverlayStitchMesher::DOMAIN_ENCLOSED:
      options.domain = osm::Domain::Enclosed;
      break;
    case vtkOverlayStitchMesher::DOMAIN_HULL:
      options.domain = osm::Domain::Hull;
      break;
    case vtkOverlayStitchMesher::DOMAIN_BOX:
      options.domain = osm::Domain::Box;
      break;
    default:
      options.domain = osm::Domain::Auto;
      break;
  }
  options.resolveCrossings = self->ResolveIntersections != 0;
  options.mergeTolerance = self->MergeTolerance;
  options.regionAreas = self->ApplyRegionAreas != 0;
  options.gapRatioOverlay = self->GapRatioOverlay != 0;
  options.maxSteinerPoints = static_cast<std::size_t>(self->MaximumSteinerPoints);
  // Triangle's vertex markers need the input subsegments, to know which
  // vertices lie on a marked segment.
  options.keepEdges = self->GenerateEdges != 0 ||
    (interpolate && this->Input->GetPointData()->GetArray(Names::PointMarker));
  options.keepOverlay = self->GenerateOverlay != 0;
  options.keepVertexSegments = interpolate; // the segment of each vertex, to carry data along
  if (this->Map.isFitted())
  {
    // Points named in messages in the input's 3D coordinates, not the plane's 2D frame.
    const osm::PlaneMap& map = this->Map;
    options.pointFormat = [&map](const osm::Point& p) { return osm::formatPoint3(map.toSpace(p)); };
  }
  return options;
}

/// The core's phases (clean, overlay, stitch, complete, domain), and its
/// messages with the input's names for the items they number.
std::optional<int> vtkOverlayStitchMesher::MeshRun::MeshPslg(bool interpolate)
{
  vtkOverlayStitchMesher* self = this->Self;
  const osm::Options options = this->MakeOptions(interpolate);
  ProgressAdapter progress(self, 0.05, this->OutputStart());
  if (interpolate)
  {
    this->Reuse.emplace();
  }
  try
  {
    this->Result = osm::mesh(this->Pslg, options, &progress);
  }
  catch (const std::exception& e)
  {
    vtkErrorWithObjectMacro(self, "Internal error in the mesher: " << e.what());
    return Failure(self);
  }

  // Which cells the named segments are, and which seeds the named holes.
  const std::size_t propertySeeds = self->HolePoints.size() / 2;
  const bool byCoordinates = this->Composite || this->Gather.Ranks > 1 ||
    OverlayStitchCountsFromOne(this->Input->GetFieldData());
  auto explain = [&](const std::string& text) {
    return ExplainHoles(ExplainSegments(ExplainPoints(text, this->Input), this->SegmentSources,
                          this->Input, byCoordinates),
      propertySeeds, this->Pslg.holes.size());
  };
  for (const std::string& warning : this->Result.warnings)
  {
    vtkWarningWithObjectMacro(self, << Numbered(explain(warning), this->Numbering));
  }
  if (!this->Result.ok)
  {
    // An abort is no failure of the filter's, as for VTK's own (a review),
    // nor said to be one (a second review).
    if (this->Result.error == osm::kAbortedByTheUser)
    {
      this->SayAborted();
      return 1;
    }
    vtkErrorWithObjectMacro(
      self, "Meshing failed: " << Numbered(explain(this->Result.error), this->Numbering));
    return Failure(self);
  }
  return std::nullopt;
}

/// Whether the user asked to abort; then the outputs are emptied, and said so.
bool vtkOverlayStitchMesher::MeshRun::Aborted()
{
  if (!AbortRequested(this->Self))
  {
    return false;
  }
  ClearOutputs({ this->Mesh, this->Edges, this->Overlay });
  this->SayAborted();
  return true;
}

/// An abort is said as a warning, once until a run ends otherwise: while the
/// flag stays set, the pipeline runs the filter again for every request (3
/// to 5 times in one ParaView update), and an error would present the user's
/// own cancel as a failure (a review; VTK's filters say nothing at all). The
/// filter's modification time cannot tell a new request: every aborted run
/// changes it (VTK's AbortOutput flag is set and cleared on the filter).
void vtkOverlayStitchMesher::MeshRun::SayAborted()
{
  if (!this->AbortSaidBefore && !this->Self->AbortSaid)
  {
    vtkWarningWithObjectMacro(this->Self, << kAborted);
  }
  this->Self->AbortSaid = true;
}

/// Phase "output": the three polydata, built in bulk, with the input's data
/// carried; the abort flag is polled between them (an abort empties every
/// output).
namespace
{
/// Reports the warnings of the input data carriers, and clears them.
void ReportWarnings(vtkOverlayStitchMesher* self, std::vector<std::string>& warnings)
{
  for (const std::string& warning : warnings)
  {
    vtkWarningWithObjectMacro(self, << warning);
  }
  warnings.clear();
}

/// An output step's progress, from lo to hi of the whole run; true when an
/// abort is requested.
auto ProgressSteps(vtkOverlayStitchMesher* self, double lo, double hi)
{
  return [self, lo, hi](double fraction) {
    self->UpdateProgress(lo + (hi - lo) * fraction);
    return AbortRequested(self);
  };
}
} // namespace

std::vector<vtkIdType> vtkOverlayStitchMesher::MeshRun::SegmentCells() const
{
  std::vector<vtkIdType> cells;
  if (this->Self->InterpolatePointData || (this->Self->PassCellData && this->Self->GenerateEdges))
  {
    cells.reserve(this->SegmentSources.size());
    for (const SegmentSource& source : this->SegmentSources)
    {
      cells.push_back(source.Cell);
    }
  }
  return cells;
}

bool vtkOverlayStitchMesher::MeshRun::FillMeshOutput(
  bool interpolate, const std::vector<vtkIdType>& segmentCells, double lo, double hi)
{
  vtkOverlayStitchMesher* self = this->Self;
  vtkPolyData* input = this->Input;
  std::vector<std::string> warnings;
  vtkNew<vtkPointData> carried;
  if (interpolate)
  {
    OverlayStitchInterpolatePointData(input->GetPointData(), input->GetCellData(), this->Pslg,
      this->Result, segmentCells, this->OwnNames(Names::MeshPointArrays), carried,
      ProgressSteps(self, lo, lo + 0.06), warnings);
    ReportWarnings(self, warnings);
    this->Reuse.reset();
  }
  if (this->Aborted())
  {
    return false;
  }
  // Carried point normals decide which way the triangles face (cell
  // normals would count line cells' too, which reach no triangle).
  const bool reversed =
    interpolate && NormalsOppose(input->GetPointData()->GetNormals(), this->Result.mesh, this->Map);
  FillMesh(
    this->Result, this->Map, this->Mesh, ProgressSteps(self, lo + 0.06, lo + 0.09), reversed);
  if (this->Aborted())
  {
    return false;
  }
  OverlayStitchToSourceIds(input->GetPointData(), OverlayStitchSourcePointIdName,
    vtkIdTypeArray::SafeDownCast(this->Mesh->GetPointData()->GetArray(Names::InputPointId)),
    this->Mesh->GetPointData());
  if (self->PassCellData)
  {
    OverlayStitchPassPolygonData(input, this->Pslg, this->Result, this->Map,
      this->OwnNames(Names::MeshCellArrays), this->Mesh->GetCellData(),
      ProgressSteps(self, lo + 0.09, hi), warnings);
    ReportWarnings(self, warnings);
    if (this->Aborted())
    {
      return false;
    }
  }
  OverlayStitchMovePointData(carried, this->Mesh->GetPointData());
  this->AddFieldCounts();
  return true;
}

void vtkOverlayStitchMesher::MeshRun::AddFieldCounts()
{
  vtkPolyData* mesh = this->Mesh;
  auto addCount = [mesh](const char* name, double value) {
    auto array = MakeArray<vtkDoubleArray>(name, 1);
    array->SetValue(0, value);
    mesh->GetFieldData()->AddArray(array);
  };
  addCount(Names::IgnoredCells,
    static_cast<double>(this->Ignored.Total() + OverlayStitchIgnoredCells(this->Input)));
  addCount(Names::InputHolePoints, static_cast<double>(this->InputHoles));
  addCount(Names::InputPlaneFitted, this->Map.isFitted() ? 1.0 : 0.0);
  addCount(Names::InputProjectedToXY, this->Map.isProjected() ? 1.0 : 0.0);
}

void vtkOverlayStitchMesher::MeshRun::FillEdgesOutput(
  const std::vector<vtkIdType>& segmentCells, double lo, double hi)
{
  vtkOverlayStitchMesher* self = this->Self;
  FillEdges(this->Result, this->Map, this->Edges, ProgressSteps(self, lo, lo + 0.1));
  if (self->PassCellData && !AbortRequested(self))
  {
    std::vector<std::string> warnings;
    OverlayStitchPassCellData(this->Input->GetCellData(), this->Input->GetNumberOfCells(),
      this->Pslg, this->Result, segmentCells, this->OwnNames(Names::EdgesCellArrays),
      this->Edges->GetCellData(), ProgressSteps(self, lo + 0.1, hi), warnings);
    // The input's active cell scalars came along active; the Edges output
    // opens colored by its classes all the same.
    this->Edges->GetCellData()->SetActiveScalars(Names::EdgeClass);
    ReportWarnings(self, warnings);
  }
}

int vtkOverlayStitchMesher::MeshRun::FillOutputs(bool interpolate)
{
  vtkOverlayStitchMesher* self = this->Self;
  self->SetProgressText("output");
  // The bands: the Mesh and its data take 0.1, the Edges output 0.15, the
  // Overlay output the rest.
  const double start = this->OutputStart(), edges = start + 0.1;
  const double overlay = edges + (self->GenerateEdges ? 0.15 : 0.0);
  self->UpdateProgress(start);
  if (this->Aborted())
  {
    return 1;
  }
  const std::vector<vtkIdType> segmentCells = this->SegmentCells();
  if (!this->FillMeshOutput(interpolate, segmentCells, start, edges))
  {
    return 1;
  }
  self->UpdateProgress(edges);
  if (this->Aborted())
  {
    return 1;
  }
  if (self->GenerateEdges)
  {
    this->FillEdgesOutput(segmentCells, edges, overlay);
  }
  self->UpdateProgress(overlay);
  if (this->Aborted())
  {
    return 1;
  }
  if (self->GenerateOverlay)
  {
    MakeTriangles(
      this->Result.overlay, this->Map, this->Overlay, ProgressSteps(self, overlay, 1.0));
  }
  for (vtkPolyData* output : { this->Mesh, this->Edges, this->Overlay })
  {
    PassFieldData(this->Input->GetFieldData(), output);
  }
  self->SetProgressText(nullptr);
  self->UpdateProgress(1.0);
  // An abort requested by the last progress report still counts: the flag
  // stays set, so a mesh kept here would make the next run fail instead.
  this->Aborted();
  return 1;
}

//------------------------------------------------------------------------------
int vtkOverlayStitchMesher::RequestData(vtkInformation* vtkNotUsed(request),
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkPolyData* mesh = vtkPolyData::GetData(outputVector, 0);
  vtkPolyData* edges = vtkPolyData::GetData(outputVector, 1);
  vtkPolyData* overlay = vtkPolyData::GetData(outputVector, 2);
  if (!mesh || !edges || !overlay)
  {
    vtkErrorMacro("Output data objects are missing.");
    return 0;
  }
  // Outputs stay empty unless meshing succeeds.
  ClearOutputs({ mesh, edges, overlay });
  // The plane's map to 2D and back rounds like the core (a review: under the
  // host's upward rounding, 303 of 304 points of a tilted plane moved).
  const osm::RoundToNearest rounding;
  // Whichever way the run ends, no phase is left named as current.
  const struct ProgressTextReset
  {
    vtkOverlayStitchMesher* Filter;
    ~ProgressTextReset() { this->Filter->SetProgressText(nullptr); }
  } progressTextReset{ this };
  // Reading the input and building the outputs allocate too: an exception
  // must not escape into the executive and the application (a review).
  try
  {
    MeshRun run(this, mesh, edges, overlay);
    return run.Execute(vtkDataObject::GetData(inputVector[0], 0));
  }
  catch (const std::exception& e)
  {
    // Saying so allocates too: with no memory left, the outputs stay as they
    // are and the error unsaid, rather than an exception leaving; such
    // outputs are never passed on as a success.
    bool cleared = false;
    try
    {
      ClearOutputs({ mesh, edges, overlay });
      cleared = true;
      if (dynamic_cast<const std::bad_alloc*>(&e))
      {
        vtkErrorMacro("Cannot mesh the input: out of memory while reading it or building the "
                      "outputs.");
      }
      else
      {
        vtkErrorMacro("Internal error in the filter: " << e.what());
      }
    }
    catch (...)
    {}
    return cleared || Parallel(this) ? Failure(this) : 0;
  }
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::SetMergeTolerance(double tolerance)
{
  tolerance = tolerance < 0.0 ? 0.0 : tolerance;
  // (NaN is never equal to itself: setting it again marks a change again.)
  if (this->MergeTolerance != tolerance)
  {
    this->MergeTolerance = tolerance;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkOverlayStitchMesher::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "MinimumAngle: " << this->MinimumAngle << "\n";
  os << indent << "MaximumEdgeLength: " << this->MaximumEdgeLength << "\n";
  static const char* const domains[] = { "Auto", "Enclosed", "Hull", "Box" };
  os << indent << "Domain: "
     << (this->Domain >= DOMAIN_AUTO && this->Domain <= DOMAIN_BOX ? domains[this->Domain] : "?")
     << " (" << this->Domain << ")\n";
  os << indent << "ResolveIntersections: " << (this->ResolveIntersections ? "On" : "Off") << "\n";
  os << indent << "MergeTolerance: " << this->MergeTolerance << "\n";
  os << indent << "ProjectToXYPlane: " << (this->ProjectToXYPlane ? "On" : "Off") << "\n";
  os << indent << "UseInputHolePoints: " << (this->UseInputHolePoints ? "On" : "Off") << "\n";
  os << indent << "ReportFailureToPipeline: " << (this->ReportFailureToPipeline ? "On" : "Off")
     << "\n";
  os << indent << "ApplyRegionAreas: " << (this->ApplyRegionAreas ? "On" : "Off") << "\n";
  os << indent << "GapRatioOverlay: " << (this->GapRatioOverlay ? "On" : "Off") << "\n";
  os << indent << "MaximumSteinerPoints: " << this->MaximumSteinerPoints << "\n";
  os << indent << "GenerateEdges: " << (this->GenerateEdges ? "On" : "Off") << "\n";
  os << indent << "InterpolatePointData: " << (this->InterpolatePointData ? "On" : "Off") << "\n";
  os << indent << "PassCellData: " << (this->PassCellData ? "On" : "Off") << "\n";
  os << indent << "GenerateOverlay: " << (this->GenerateOverlay ? "On" : "Off") << "\n";
  os << indent << "Controller: ";
  if (this->Controller)
  {
    os << this->Controller << " (" << this->Controller->GetNumberOfProcesses() << " processes)\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "HolePoints: " << this->GetNumberOfHolePoints() << "\n";
  for (int i = 0; i < this->GetNumberOfHolePoints(); ++i)
  {
    double p[2];
    this->GetHolePoint(i, p);
    os << indent.GetNextIndent() << "(" << p[0] << ", " << p[1] << ")\n";
  }
  if (this->HolePoints.size() % 2 != 0)
  {
    os << indent.GetNextIndent() << "(" << this->HolePoints.back()
       << ", ?): a lone coordinate (AddHolePointCoordinate), ignored\n";
  }
}
