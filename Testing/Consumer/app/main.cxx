// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// A user's C++ program: build line data, mesh it with vtkOverlayStitchMesher,
// write the mesh as .vtp and print its size. Exits non-zero on any error.
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkOverlayStitchMesher.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkXMLPolyDataWriter.h>

#include <iostream>

namespace
{
class ErrorCounter : public vtkCommand
{
public:
  static ErrorCounter* New() { return new ErrorCounter; }
  void Execute(vtkObject*, unsigned long, void* data) override
  {
    ++this->Errors;
    std::cerr << "error: " << (data ? static_cast<const char*>(data) : "") << "\n";
  }
  int Errors = 0;
};
}

int main(int argc, char* argv[])
{
  const char* output = argc > 1 ? argv[1] : "consumer-mesh.vtp";

  // A unit square outline with an interior slit.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0);
  points->InsertNextPoint(1.0, 0.0, 0.0);
  points->InsertNextPoint(1.0, 1.0, 0.0);
  points->InsertNextPoint(0.0, 1.0, 0.0);
  points->InsertNextPoint(0.2, 0.5, 0.0);
  points->InsertNextPoint(0.7, 0.55, 0.0);
  vtkNew<vtkCellArray> lines;
  const vtkIdType outline[] = { 0, 1, 2, 3, 0 };
  lines->InsertNextCell(5, outline);
  const vtkIdType slit[] = { 4, 5 };
  lines->InsertNextCell(2, slit);
  vtkNew<vtkPolyData> input;
  input->SetPoints(points);
  input->SetLines(lines);

  vtkNew<vtkOverlayStitchMesher> mesher;
  vtkNew<ErrorCounter> errors;
  mesher->AddObserver(vtkCommand::ErrorEvent, errors);
  mesher->SetInputData(input);
  mesher->SetMinimumAngle(30.0);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->SetInputConnection(mesher->GetOutputPort(0));
  writer->SetFileName(output);
  writer->Write();

  const vtkIdType triangles = mesher->GetOutput()->GetNumberOfCells();
  std::cout << "triangles: " << triangles << "\n";
  std::cout << "wrote " << output << "\n";
  return (errors->Errors == 0 && triangles > 0) ? 0 : 1;
}
