#pragma once
/// \file TestSupport.h
/// Shared helpers of the filter tests: the sample data folder, conversion to
/// the core mesh type, and recorders of VTK errors and progress.

#include "latticekit/ManifoldRepair.h"
#include "latticekit/TriangleMesh.h"
#include "vtkLKBoneSurfaceFilter.h"
#include "vtkLKMedicalImageReader.h"
#include "vtkLKPolyDataConversion.h"

#include <gtest/gtest.h>

#include <vtkAlgorithm.h>
#include <vtkCallbackCommand.h>
#include <vtkCleanPolyData.h>
#include <vtkCubeSource.h>
#include <vtkLinearSubdivisionFilter.h>
#include <vtkTriangleFilter.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFeatureEdges.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <string>
#include <vector>

#ifndef LATTICEKIT_SAMPLE_DATA
#error "LATTICEKIT_SAMPLE_DATA must be defined"
#endif

namespace lktest
{
/// A closed box of the given sizes centred at the origin, in triangles that
/// share their corners, each face cut into 4^subdivisions x 2 triangles.
inline vtkSmartPointer<vtkPolyData> triangulatedBox(double x, double y, double z, int subdivisions)
{
  vtkNew<vtkCubeSource> cube;
  cube->SetXLength(x);
  cube->SetYLength(y);
  cube->SetZLength(z);
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(cube->GetOutputPort());
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkLinearSubdivisionFilter> finer;
  finer->SetInputConnection(merged->GetOutputPort());
  finer->SetNumberOfSubdivisions(subdivisions);
  finer->Update();
  auto out = vtkSmartPointer<vtkPolyData>::New();
  out->ShallowCopy(finer->GetOutput());
  return out;
}


inline std::string sampleData(const std::string& relative)
{
  return std::string(LATTICEKIT_SAMPLE_DATA) + "/" + relative;
}

/// A bundled TCIA mandible (0522c0017 or TCGA-CV-7236) as
/// vtkLKBoneSurfaceFilter makes it with its defaults (12,994 points for the
/// first; 12,212 with oneVoxel); empty if it cannot be read.
/// oneVoxel: as the label map's surface was made by default until December
/// 2026 (a Gaussian of one voxel, no smoothing of the surface).
inline vtkSmartPointer<vtkPolyData> tciaMandibleSurface(const std::string& patient = "0522c0017", bool oneVoxel = false)
{
  vtkNew<vtkLKMedicalImageReader> reader;
  reader->SetFileName(sampleData("mandible-tcia/test_oncologist_" + patient + "_Mandible.nrrd").c_str());
  vtkNew<vtkLKBoneSurfaceFilter> bone;
  bone->SetInputConnection(reader->GetOutputPort());
  if (oneVoxel)
  {
    bone->SetImageSmoothing(1.0);
    bone->SetSmoothingIterations(0);
  }
  bone->Update();
  auto surface = vtkSmartPointer<vtkPolyData>::New();
  surface->ShallowCopy(bone->GetOutput());
  return surface;
}

/// The filters' own conversion; a mesh it refuses is a test failure.
inline lk::TriangleMesh toCore(vtkPolyData* pd)
{
  lk::TriangleMesh m;
  const std::string problem = lkvtk::toTriangleMesh(pd, m);
  EXPECT_EQ(problem, "");
  return m;
}

/// The volume a closed triangle surface encloses, positive when its faces
/// are ordered with their normals pointing out (the core's, on the filters'
/// conversion).
inline double signedVolume(vtkPolyData* pd)
{
  return lk::signedVolume(toCore(pd));
}

/// The edges of `pd` met by one face or by more than two (0: closed and
/// manifold).
inline vtkIdType openOrNonManifoldEdges(vtkPolyData* pd)
{
  vtkNew<vtkFeatureEdges> edges;
  edges->SetInputData(pd);
  edges->BoundaryEdgesOn();
  edges->NonManifoldEdgesOn();
  edges->FeatureEdgesOff();
  edges->ManifoldEdgesOff();
  edges->Update();
  return edges->GetOutput()->GetNumberOfLines();
}

/// Records the ErrorEvents (and their messages) of one VTK object; while it
/// observes, VTK does not print them.
class ErrorRecorder
{
public:
  explicit ErrorRecorder(vtkObject* object)
  {
    command_->SetClientData(this);
    command_->SetCallback([](vtkObject*, unsigned long event, void* cd, void* call) {
      auto* self = static_cast<ErrorRecorder*>(cd);
      const std::string text = call ? static_cast<const char*>(call) : "";
      if (event == vtkCommand::ErrorEvent)
      {
        ++self->errors;
        self->messages += text;
      }
      else
      {
        ++self->warnings;
        self->warningMessages += text;
      }
    });
    object_ = object;
    errorTag_ = object->AddObserver(vtkCommand::ErrorEvent, command_);
    warningTag_ = object->AddObserver(vtkCommand::WarningEvent, command_);
  }
  /// Stops observing: an object that outlives the recorder (one made in an
  /// inner scope) must not call back into it.
  ~ErrorRecorder()
  {
    if (object_)
    {
      object_->RemoveObserver(errorTag_);
      object_->RemoveObserver(warningTag_);
    }
  }
  ErrorRecorder(const ErrorRecorder&) = delete;
  ErrorRecorder& operator=(const ErrorRecorder&) = delete;
  int errors = 0;
  int warnings = 0;
  std::string messages;
  std::string warningMessages;

private:
  vtkNew<vtkCallbackCommand> command_;
  vtkWeakPointer<vtkObject> object_;
  unsigned long errorTag_ = 0;
  unsigned long warningTag_ = 0;
};

/// Records the ProgressEvents of one filter and, once the progress reaches
/// `stopAt`, asks the filter to stop (SetAbortExecute), as a user's cancel
/// button would.
class ProgressRecorder
{
public:
  explicit ProgressRecorder(vtkAlgorithm* filter)
  {
    command_->SetClientData(this);
    command_->SetCallback([](vtkObject* caller, unsigned long, void* cd, void* data) {
      auto* self = static_cast<ProgressRecorder*>(cd);
      const double p = *static_cast<double*>(data);
      self->progress.push_back(p);
      if (p >= self->stopAt)
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
    });
    filter_ = filter;
    tag_ = filter->AddObserver(vtkCommand::ProgressEvent, command_);
  }
  ~ProgressRecorder()
  {
    if (filter_)
      filter_->RemoveObserver(tag_);
  }
  ProgressRecorder(const ProgressRecorder&) = delete;
  ProgressRecorder& operator=(const ProgressRecorder&) = delete;
  std::vector<double> progress;
  double stopAt = 2.0; ///< above 1: never

private:
  vtkNew<vtkCallbackCommand> command_;
  vtkWeakPointer<vtkAlgorithm> filter_;
  unsigned long tag_ = 0;
};

} // namespace lktest
