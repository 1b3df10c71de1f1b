// An MPI application that meshes on one rank only: run with `mpirun -np 2`.
// The filter takes the global controller by default, and with it a run is
// collective. A review found rank 0 waiting for ever in the filter's gather
// while rank 1 went on to its own collectives (one of them consumed). With
// SetController(nullptr), rank 0 meshes its input alone; then both ranks
// meet in a collective of their own (the test's time limit catches a hang).
#include "vtkCellArray.h"
#include "vtkExecutive.h"
#include "vtkMPIController.h"
#include "vtkNew.h"
#include "vtkOutputWindow.h"
#include "vtkOverlayStitchMesher.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <iostream>
#include <string>

namespace
{
/// The outline of a square with a point inside.
vtkNew<vtkPolyData> Square()
{
  vtkNew<vtkPolyData> square;
  vtkNew<vtkPoints> points;
  for (const auto& p :
    { std::pair{ 0.0, 0.0 }, { 1.0, 0.0 }, { 1.0, 1.0 }, { 0.0, 1.0 }, { 0.3, 0.6 } })
  {
    points->InsertNextPoint(p.first, p.second, 0.0);
  }
  vtkNew<vtkCellArray> lines;
  for (vtkIdType i = 0; i < 4; ++i)
  {
    const vtkIdType ids[2] = { i, (i + 1) % 4 };
    lines->InsertNextCell(2, ids);
  }
  vtkNew<vtkCellArray> verts;
  const vtkIdType inside = 4;
  verts->InsertNextCell(1, &inside);
  square->SetPoints(points);
  square->SetLines(lines);
  square->SetVerts(verts);
  return square;
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
  auto check = [&](bool ok, const std::string& what) {
    std::cout << "rank " << rank << (ok ? ": ok    " : ": FAIL  ") << what << "\n";
    failures += ok ? 0 : 1;
  };
  if (ranks != 2)
  {
    check(false, "run with mpirun -np 2, not " + std::to_string(ranks));
  }
  else if (rank == 0)
  {
    vtkNew<vtkOverlayStitchMesher> mesher;
    check(
      mesher->GetController() == controller.GetPointer(), "the global controller is the default");
    mesher->SetController(nullptr);
    mesher->SetInputData(Square());
    check(mesher->GetExecutive()->Update() == 1, "Update() succeeds");
    const vtkIdType triangles = mesher->GetOutput()->GetNumberOfCells();
    check(triangles >= 4,
      "rank 0 meshed its square alone: " + std::to_string(triangles) + " triangles");
  }
  // Both ranks meet here: with the global controller, rank 0 would still be
  // waiting for rank 1 in the filter's gather.
  int total = 0;
  controller->Reduce(&failures, &total, 1, vtkCommunicator::SUM_OP, 0);
  controller->Finalize();
  if (rank == 0)
  {
    std::cout << (total == 0 ? "passed" : "FAILED") << "\n";
  }
  return rank == 0 && total != 0 ? 1 : 0;
}
