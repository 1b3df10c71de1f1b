// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// A user's C++ program: read a Triangle .poly file with vtkTrianglePolyReader,
// mesh it with vtkOverlayStitchMesher (the file's holes are used as hole
// seeds), write the mesh as .vtp and print its size. Exits non-zero on any
// error.
//
//   osm_consumer INPUT.poly OUTPUT.vtp
#include <vtkCommand.h>
#include <vtkNew.h>
#include <vtkOverlayStitchMesher.h>
#include <vtkPolyData.h>
#include <vtkTrianglePolyReader.h>
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
  if (argc != 3)
  {
    std::cerr << "usage: osm_consumer INPUT.poly OUTPUT.vtp\n";
    return 2;
  }
  vtkNew<ErrorCounter> errors;

  vtkNew<vtkTrianglePolyReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(argv[1]);

  vtkNew<vtkOverlayStitchMesher> mesher;
  mesher->AddObserver(vtkCommand::ErrorEvent, errors);
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetMinimumAngle(30.0);

  vtkNew<vtkXMLPolyDataWriter> writer;
  writer->AddObserver(vtkCommand::ErrorEvent, errors);
  writer->SetInputConnection(mesher->GetOutputPort(0));
  writer->SetFileName(argv[2]);
  writer->Write();

  const vtkIdType triangles = mesher->GetOutput()->GetNumberOfCells();
  std::cout << "read " << reader->GetOutput()->GetNumberOfPoints() << " points and "
            << reader->GetOutput()->GetNumberOfLines() << " segments from " << argv[1] << "\n";
  std::cout << "triangles: " << triangles << "\n";
  std::cout << "wrote " << argv[2] << "\n";
  return (errors->Errors == 0 && triangles > 0) ? 0 : 1;
}
