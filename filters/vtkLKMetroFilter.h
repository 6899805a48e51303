/**
 * @class   vtkLKMetroFilter
 * @brief   Metro-style Hausdorff distance between two triangle meshes.
 *
 * Measures how far two surfaces are apart the way Metro does (Cignoni,
 * Rocchini, Scopigno, "Metro: measuring error on simplified surfaces",
 * Computer Graphics Forum 17(2), 1998): the surface of one mesh is sampled on
 * its vertices, its edges and inside its faces, and each sample's distance to
 * the closest point of the other mesh is found through an AABB tree (CGAL).
 * Both directions are measured (A->B samples A, B->A samples B), threaded
 * with vtkSMPTools.
 *
 * Input 0 is mesh A, input 1 (SetTargetConnection / SetTargetData) is mesh B.
 * Both must be triangle meshes with finite coordinates.
 *
 * Definitions (documented choices where Metro leaves room):
 * - max is over every sample (vertex, edge and face samples);
 * - mean and RMS are surface integrals estimated from the face samples, each
 *   weighted by the area it stands for (with MeanOverAllSamples, Metro 4's own
 *   figures: every sample, vertex, edge and face, counted once);
 * - the symmetric figures take, for each statistic, the worse direction
 *   (so the symmetric max is the Hausdorff distance);
 * - percentages are relative to the diagonal of the bounding box of both
 *   meshes together, as Metro reports them.
 *
 * Sampling: NumberOfSamples face samples per direction (0: Metro's default of
 * ten per triangle of the larger mesh), or SampleDensity samples per unit
 * area when it is positive. Edge samples are spaced 1/sqrt(density). Face
 * sampling is by similar triangles (deterministic) or Monte Carlo (seeded).
 * The samples are measured a block of at most a million at a time, so their
 * memory does not grow with their number; more than 10^9 samples in a
 * direction (hours of queries) are refused.
 *
 * Output: a shallow copy of input 0 with point data "Distance" (each point of
 * A to B) and "DistanceColors" (RGB, blue small to red large, from 0 to the
 * 99th percentile of the point distances, or ColorMaximum; larger distances
 * are red too), and field data arrays of one value
 * each: BoundingBoxDiagonal; for P in {AtoB, BtoA, Hausdorff}: P_Max, P_Mean,
 * P_RMS, P_MaxPercent, P_MeanPercent, P_RMSPercent, P_Samples; and
 * AtoB_VertexSamples, AtoB_EdgeSamples, AtoB_FaceSamples (BtoA likewise).
 * With Symmetric off only AtoB is computed and Hausdorff equals it.
 */
#ifndef vtkLKMetroFilter_h
#define vtkLKMetroFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

class vtkAlgorithmOutput;
class vtkPolyData;

class LATTICEKITFILTERS_EXPORT vtkLKMetroFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKMetroFilter* New();
  vtkTypeMacro(vtkLKMetroFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum FaceSamplingMethods
  {
    SIMILAR_TRIANGLES = 0,
    MONTE_CARLO = 1
  };

  ///@{
  /// Mesh B, the second input.
  void SetTargetConnection(vtkAlgorithmOutput* output);
  void SetTargetData(vtkPolyData* pd);
  ///@}

  ///@{
  /// Face samples per direction; 0 (default) means ten per face of the larger mesh.
  vtkSetClampMacro(NumberOfSamples, vtkIdType, 0, VTK_ID_MAX);
  vtkGetMacro(NumberOfSamples, vtkIdType);
  ///@}

  ///@{
  /// Face samples per unit area; when positive it overrides NumberOfSamples.
  vtkSetMacro(SampleDensity, double);
  vtkGetMacro(SampleDensity, double);
  ///@}

  ///@{
  /// Which samples to take (all on by default).
  vtkSetMacro(VertexSampling, bool);
  vtkGetMacro(VertexSampling, bool);
  vtkBooleanMacro(VertexSampling, bool);
  vtkSetMacro(EdgeSampling, bool);
  vtkGetMacro(EdgeSampling, bool);
  vtkBooleanMacro(EdgeSampling, bool);
  vtkSetMacro(FaceSampling, bool);
  vtkGetMacro(FaceSampling, bool);
  vtkBooleanMacro(FaceSampling, bool);
  ///@}

  ///@{
  /// Monte Carlo (default: unbiased, seeded) or similar-triangle subdivision
  /// (deterministic, but its centroid rule reads a convex distance low).
  vtkSetClampMacro(FaceSamplingMethod, int, SIMILAR_TRIANGLES, MONTE_CARLO);
  vtkGetMacro(FaceSamplingMethod, int);
  void SetFaceSamplingMethodToSimilarTriangles() { this->SetFaceSamplingMethod(SIMILAR_TRIANGLES); }
  void SetFaceSamplingMethodToMonteCarlo() { this->SetFaceSamplingMethod(MONTE_CARLO); }
  ///@}

  ///@{
  /// Seed of the Monte Carlo sampler (results are reproducible for a seed).
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /// Measure B->A as well (default on).
  vtkSetMacro(Symmetric, bool);
  vtkGetMacro(Symmetric, bool);
  vtkBooleanMacro(Symmetric, bool);
  ///@}

  ///@{
  /// Mean and RMS over every sample counted once (vertex, edge and face), as
  /// Metro 4 prints them, for comparison with published Metro figures. Off
  /// (default): area-weighted over the face samples, a surface integral that
  /// does not depend on how many vertex and edge samples a mesh gets (a fine
  /// mesh has many vertex samples, and a flat mesh's vertices are often its
  /// farthest points).
  vtkSetMacro(MeanOverAllSamples, bool);
  vtkGetMacro(MeanOverAllSamples, bool);
  vtkBooleanMacro(MeanOverAllSamples, bool);
  ///@}

  ///@{
  /// Distance mapped to red in DistanceColors; 0 (default) uses the 99th
  /// percentile of the point distances.
  vtkSetClampMacro(ColorMaximum, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(ColorMaximum, double);
  ///@}

  ///@{
  /// Results of the last update (also in the output's field data).
  double GetBoundingBoxDiagonal() const { return this->Results[0]; }
  double GetForwardMaximum() const { return this->Results[1]; }
  double GetForwardMean() const { return this->Results[2]; }
  double GetForwardRMS() const { return this->Results[3]; }
  double GetBackwardMaximum() const { return this->Results[4]; }
  double GetBackwardMean() const { return this->Results[5]; }
  double GetBackwardRMS() const { return this->Results[6]; }
  double GetHausdorffDistance() const { return this->Results[7]; }
  double GetSymmetricMean() const { return this->Results[8]; }
  double GetSymmetricRMS() const { return this->Results[9]; }
  vtkIdType GetNumberOfForwardSamples() const { return this->SampleCounts[0]; }
  vtkIdType GetNumberOfBackwardSamples() const { return this->SampleCounts[1]; }
  /// The distance that DistanceColors maps to red in the last update.
  double GetEffectiveColorMaximum() const { return this->EffectiveColorMaximum; }
  ///@}

protected:
  vtkLKMetroFilter();
  ~vtkLKMetroFilter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkIdType NumberOfSamples = 0;
  double SampleDensity = 0.0;
  bool VertexSampling = true;
  bool EdgeSampling = true;
  bool FaceSampling = true;
  int FaceSamplingMethod = MONTE_CARLO;
  int RandomSeed = 5489;
  bool Symmetric = true;
  bool MeanOverAllSamples = false;
  double ColorMaximum = 0.0;
  double EffectiveColorMaximum = 0.0;
  double Results[10] = {};
  vtkIdType SampleCounts[2] = {};

private:
  vtkLKMetroFilter(const vtkLKMetroFilter&) = delete;
  void operator=(const vtkLKMetroFilter&) = delete;
};

#endif
