// A rank that runs out of memory while reading its piece, under MPI: run
// with `mpirun -np 2`. Rank 1's first large allocation in the filter fails.
// Before a fix, rank 1 reported the error and left, and rank 0 waited for it
// in the gather for ever (a review; the test's time limit catches that).
// Now rank 1 gathers a refused piece: both ranks return, with empty outputs,
// and rank 0 says which rank refused its piece.
#include "FailingAllocation.h"
#include "vtkCallbackCommand.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkMPIController.h"
#include "vtkMultiBlockDataSet.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkOverlayStitchMesher.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <iostream>
#include <string>

namespace
{

/// A zigzag line of n points at height y.
vtkNew<vtkPolyData> Zigzag(int n, double y)
{
  vtkNew<vtkPolyData> line;
  vtkNew<vtkPoints> points;
  vtkNew<vtkCellArray> cells;
  for (int i = 0; i < n; ++i)
  {
    points->InsertNextPoint(i, y + (i % 2), 0.0);
  }
  for (vtkIdType i = 0; i + 1 < n; ++i)
  {
    const vtkIdType ids[2] = { i, i + 1 };
    cells->InsertNextCell(2, ids);
  }
  line->SetPoints(points);
  line->SetLines(cells);
  return line;
}

void CollectError(vtkObject*, unsigned long, void* clientData, void* callData)
{
  static_cast<std::string*>(clientData)->append(static_cast<const char*>(callData));
}

} // namespace

int main(int argc, char* argv[])
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  vtkOutputWindow::GetInstance()->SetDisplayModeToNever();
  const int rank = controller->GetLocalProcessId();
  const int ranks = controller->GetNumberOfProcesses();
  int failures = 0;
  if (ranks != 2)
  {
    std::cout << "rank " << rank << ": run with mpirun -np 2, not " << ranks << "\n";
    failures = 1;
  }
  else
  {
    // Each rank holds two blocks of a multiblock (combining them allocates).
    vtkNew<vtkMultiBlockDataSet> blocks;
    blocks->SetNumberOfBlocks(4);
    blocks->SetBlock(2 * rank, Zigzag(2000, 10.0 * rank));
    blocks->SetBlock(2 * rank + 1, Zigzag(2000, 10.0 * rank + 5));
    vtkNew<vtkOverlayStitchMesher> mesher;
    mesher->SetInputData(blocks);
    std::string errors;
    vtkNew<vtkCallbackCommand> onError;
    onError->SetCallback(CollectError);
    onError->SetClientData(&errors);
    mesher->AddObserver(vtkCommand::ErrorEvent, onError);
    failing_allocation::start(rank == 1 ? 0 : -1); // rank 1's first large one fails
    mesher->Update();
    failing_allocation::stop();
    const std::string expected =
      rank == 1 ? "out of memory while reading it" : "the piece of rank 1 was refused on its rank";
    auto check = [&](bool ok, const std::string& what) {
      std::cout << "rank " << rank << (ok ? ": ok    " : ": FAIL  ") << what << "\n";
      failures += ok ? 0 : 1;
    };
    check(errors.find(expected) != std::string::npos,
      "the error says '" + expected + "' (" + errors + ")");
    check(mesher->GetOutput()->GetNumberOfCells() == 0, "the mesh is empty");
  }
  // Every rank's verdict, on rank 0: the test passes if both ranks returned
  // and checked out.
  int total = 0;
  controller->Reduce(&failures, &total, 1, vtkCommunicator::SUM_OP, 0);
  controller->Finalize();
  if (rank == 0)
  {
    std::cout << (total == 0 ? "passed" : "FAILED") << "\n";
  }
  return rank == 0 && total != 0 ? 1 : 0;
}
