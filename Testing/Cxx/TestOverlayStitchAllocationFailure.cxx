// Allocation failure injected into vtkOverlayStitchMesher, one large
// allocation at a time (the filter's counterpart of the core's
// AllocationFailure.cxx).
//
// Reading the input and building the outputs allocate too, outside the
// core's own guard. This executable replaces the global operator new so that
// the k-th large allocation of an Update() throws std::bad_alloc, for every k
// in turn. Each run must end either with the mesh of the run without the
// failure, or with an "out of memory" error and empty outputs: never an
// exception out of Update() (it would end the application), a crash, or a
// partial result. Run with OSM_NO_HUGE_PAGES=1, so that the core's arrays
// come from operator new too. VTK's own arrays come from malloc, which this
// does not fail: a VTK array the filter cannot size is checked in the
// filter (Allocate) but not reached here.

#include "FailingAllocation.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkIntArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObject.h"
#include "vtkOutputWindow.h"
#include "vtkOverlayStitchMesher.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <iostream>
#include <string>

namespace
{

/// A grid of k x k unit squares as line cells, with a point scalar and a
/// cell scalar to carry: about 2k^2 segments, 8k^2 output triangles.
vtkNew<vtkPolyData> GridOfSquares(int k)
{
  vtkNew<vtkPolyData> grid;
  vtkNew<vtkPoints> points;
  vtkNew<vtkDoubleArray> height;
  height->SetName("Height");
  for (int j = 0; j <= k; ++j)
  {
    for (int i = 0; i <= k; ++i)
    {
      points->InsertNextPoint(i, j, 0.0);
      height->InsertNextValue(i * 0.5 + j);
    }
  }
  vtkNew<vtkCellArray> lines;
  vtkNew<vtkIntArray> marker;
  marker->SetName("Marker");
  auto id = [k](int i, int j) { return static_cast<vtkIdType>(j * (k + 1) + i); };
  for (int j = 0; j <= k; ++j)
  {
    for (int i = 0; i <= k; ++i)
    {
      if (i < k)
      {
        const vtkIdType ids[2] = { id(i, j), id(i + 1, j) };
        lines->InsertNextCell(2, ids);
        marker->InsertNextValue(j);
      }
      if (j < k)
      {
        const vtkIdType ids[2] = { id(i, j), id(i, j + 1) };
        lines->InsertNextCell(2, ids);
        marker->InsertNextValue(i);
      }
    }
  }
  grid->SetPoints(points);
  grid->SetLines(lines);
  grid->GetPointData()->AddArray(height);
  grid->GetCellData()->AddArray(marker);
  return grid;
}

struct Outcome
{
  bool escaped = false; ///< an exception left Update()
  int status = -1;      ///< what Update() returned
  std::string errors;
  vtkIdType triangles = 0, points = 0, edges = 0, overlay = 0;
};

void CollectError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<std::string*>(clientData)->append(static_cast<const char*>(callData)).append("\n");
}

Outcome Run(vtkPolyData* input, long failure)
{
  vtkNew<vtkOverlayStitchMesher> mesher;
  mesher->SetInputData(input);
  Outcome outcome;
  vtkNew<vtkCallbackCommand> onError;
  onError->SetCallback(CollectError);
  onError->SetClientData(&outcome.errors);
  mesher->AddObserver(vtkCommand::ErrorEvent, onError);
  mesher->AddObserver(vtkCommand::WarningEvent, vtkNew<vtkCallbackCommand>()); // quiet
  failing_allocation::start(failure);
  try
  {
    outcome.status = mesher->GetExecutive()->Update();
  }
  catch (...)
  {
    outcome.escaped = true;
  }
  failing_allocation::stop();
  outcome.triangles = mesher->GetOutput()->GetNumberOfCells();
  outcome.points = mesher->GetOutput()->GetNumberOfPoints();
  outcome.edges = mesher->GetEdgesOutput()->GetNumberOfCells();
  outcome.overlay = mesher->GetOverlayOutput()->GetNumberOfCells();
  return outcome;
}

} // namespace

int main()
{
  // The executive's reports of the injected failures are expected: not shown
  // (the filter's own are observed).
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  vtkNew<vtkPolyData> input = GridOfSquares(40);
  const Outcome clean = Run(input, -1);
  const long large = failing_allocation::largeSeen.load();
  int failed = 0;
  auto check = [&failed](bool ok, const std::string& what) {
    if (!ok)
    {
      ++failed;
      std::cout << "FAILED  " << what << "\n";
    }
  };
  check(!clean.escaped && clean.errors.empty() && clean.triangles > 0 && clean.edges > 0 &&
      clean.overlay > 0,
    "the run without failures meshes (" + std::to_string(clean.triangles) + " triangles)");
  check(large >= 20, "the run makes large allocations to fail (" + std::to_string(large) + ")");
  std::cout << "mesh of " << clean.triangles << " triangles; failing each of " << large
            << " large allocations in turn\n";
  long sameMesh = 0, outOfMemory = 0;
  for (long k = 0; k < large; ++k)
  {
    const Outcome run = Run(input, k);
    const std::string which = "allocation " + std::to_string(k) + " failed: ";
    check(!run.escaped, which + "no exception leaves Update()");
    if (run.errors.empty())
    {
      check(run.triangles == clean.triangles && run.points == clean.points &&
          run.edges == clean.edges && run.overlay == clean.overlay,
        which + "without an error, the outputs are those of the clean run");
      ++sameMesh;
    }
    else
    {
      check(run.errors.find("out of memory") != std::string::npos,
        which + "the error says out of memory (" + run.errors + ")");
      check(run.triangles == 0 && run.points == 0 && run.edges == 0 && run.overlay == 0,
        which + "after the error, every output is empty");
      check(run.status == 0, which + "Update() returns 0 (" + std::to_string(run.status) + ")");
      ++outOfMemory;
    }
  }
  std::cout << sameMesh << " run(s) gave the same mesh (a fallback), " << outOfMemory
            << " the out-of-memory error\n";
  check(outOfMemory > 0, "some failure is reported as out of memory");
  std::cout << (failed == 0 ? "PASSED" : "FAILED") << "\n";
  return failed == 0 ? 0 : 1;
}
