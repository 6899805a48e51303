#pragma once
/// \file DicomTestFiles.h
/// DICOM files the filter tests make: a CT series written by vtkDICOM, and
/// the SeriesInstanceUID of a file.

#include <vtkDICOMCTGenerator.h>
#include <vtkDICOMMetaData.h>
#include <vtkDICOMParser.h>
#include <vtkDICOMWriter.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>

#include <cstdio>
#include <string>

namespace lktest
{

/// The SeriesInstanceUID of a DICOM file.
inline std::string seriesUIDOf(const std::string& file)
{
  vtkNew<vtkDICOMMetaData> meta;
  vtkNew<vtkDICOMParser> parser;
  parser->SetFileName(file.c_str());
  parser->SetMetaData(meta);
  parser->Update();
  return meta->Get(DC::SeriesInstanceUID).AsString();
}

/// Writes `image` as a DICOM CT series into `dir`, its files named by
/// `pattern` (of the folder and the slice number, from 1), its data
/// coordinates mapped to patient mm by `matrix` when one is given, and
/// `description` as its SeriesDescription and `studyUID` as its
/// StudyInstanceUID when given, and the attributes of `attributes` (a
/// character set and a patient's name in it, say). Returns its
/// SeriesInstanceUID.
inline std::string writeCT(const std::string& dir, vtkImageData* image, vtkMatrix4x4* matrix = nullptr,
  const char* pattern = "%s/ct_%03d.dcm", const char* description = nullptr, const char* studyUID = nullptr,
  vtkDICOMMetaData* attributes = nullptr)
{
  vtkNew<vtkDICOMCTGenerator> generator;
  vtkNew<vtkDICOMMetaData> meta;
  if (attributes)
    for (vtkDICOMDataElementIterator e = attributes->Begin(); e != attributes->End(); ++e)
      meta->Set(e->GetTag(), e->GetValue());
  if (description)
    meta->Set(DC::SeriesDescription, description);
  if (studyUID)
    meta->Set(DC::StudyInstanceUID, studyUID);
  vtkNew<vtkDICOMWriter> writer;
  writer->SetInputData(image);
  writer->SetGenerator(generator);
  writer->SetMetaData(meta);
  if (matrix)
    writer->SetPatientMatrix(matrix);
  writer->SetFilePrefix(dir.c_str());
  writer->SetFilePattern(pattern);
  writer->Write();
  char first[4096];
  std::snprintf(first, sizeof first, pattern, dir.c_str(), 1);
  return seriesUIDOf(first);
}

} // namespace lktest
