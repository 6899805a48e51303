/**
 * @class   vtkLKCuttingGuideFilter
 * @brief   A cutting guide for a planar osteotomy: a shell that sits on the
 *          bone across the cut's plane, with a slot the saw blade runs in.
 *
 * A planned cut reaches the patient through a guide printed from the plan:
 * its inner face is the bone's own surface, so it seats in one place only,
 * and the saw passes through its slot in the planned plane. This filter
 * makes the guide of one plane cut (a saw line of the planner, the main
 * job's cut plane).
 *
 * Method (VTK's cutter and cell locator, then its extrusion):
 * - The approach: the side of the bone the guide is put on, a direction in
 *   the cut's plane toward the surgeon. Given (Approach), it is projected
 *   into the plane. Left at 0, 0, 0 it is the short axis of the bone's
 *   section in the plane (the loop of vtkCutter's section nearest
 *   PlaneOrigin), turned to the bone's outer side: the half of the
 *   section that lies the shallower inside the bone's convex hull
 *   (lk::ConvexHull, CGAL's), by 1 mm on average at least, where one of
 *   the section's ends along that axis lies 2 mm or more inside it. A
 *   mandible's lingual side and its ramus' medial side face the inside of
 *   its arch, so its body and ramus get the guide on the outer (buccal,
 *   lateral) side and the chin on its front, on a mandible alone or on a
 *   whole skull, however the cut is slanted. Where both ends lie on the
 *   hull (a bone with no inner side, a cut along the arch such as a
 *   horizontal cut through the chin), away from the centre of the bone
 *   round the cut instead (within twice the section's size, 30 mm at
 *   least).
 * - Its extent along the plane: the run of the section around its point
 *   farthest along the approach that faces the approach within
 *   MaximumContactAngle (the outward normal of the section's chord over 3
 *   mm, so that a label map's staircase does not break the run) and that
 *   no other part of the bone hides.
 * - The contact: over the rectangle within Reach of the plane on either
 *   side and that extent along it, a grid of rays (every 0.25 mm) along the
 *   approach toward the bone, each stopped at the first face it meets
 *   (vtkStaticCellLocator): the bone as the surgeon sees it, a height field
 *   along the approach. So the guide can be put on and taken off along the
 *   approach, never reaches round an edge of the bone, and has straight
 *   edges. A ray that meets no bone within Reach below the section's part
 *   leaves its cells out (beside the bone's edge), as does a part joined by
 *   no cell side to the cells nearest the section's outermost point on
 *   either side of the plane (an island where rays met a far part of the
 *   bone).
 * - Its edges away from the slot: where they cross the grid obliquely on a
 *   steep face, the cells' steps would stand as teeth along the approach on
 *   the swept shell's side (a 0.25 mm step on a face 65 degrees from the
 *   approach rises 0.5 mm). Where the face at an edge turns more than 30
 *   degrees from the approach (fully beyond 45, averaged over 1 mm), the
 *   contact ends instead along a smooth line about 0.4 mm inside it
 *   (vtkClipPolyData of the cells' distance to the edge, averaged over 1 mm
 *   each way), its new points put back on the bone along their rays. These
 *   lengths shrink in proportion with a Reach under 8 mm (a small model),
 *   and a contact the line would take whole stays as the grid gave it. A
 *   part the line cuts off across a narrow neck of the contact (on a
 *   ramus' edge) goes, as it would be loose in the printed guide.
 * - The slot: the grid's cells within SlotWidth / 2 of the plane, except
 *   for Bridge millimetres at each of the extent's ends, which keep the
 *   guide in one piece (the saw starts the cut in the slot; the last
 *   millimetres past its ends are finished with the guide off, as with any
 *   printed guide). Bridge 0 leaves two blocks.
 * - The screw holes (ScrewHoleDiameter, 2.1 mm; 0: none): one on each side
 *   of the slot, halfway between it and the guide's edge across the plane,
 *   at the middle of the extent along it, through the guide along the
 *   approach (the contact clipped by a vtkCylinder, so they are round, to
 *   0.015 mm, the clip's chords across the 0.25 mm grid): the
 *   screws that hold the guide while the saw runs, and whose holes in the
 *   bone can take the plate's screws after the cut. Given the plan's other
 *   saw planes (OtherCutPlanes), a hole whose screw (to 10 mm into the
 *   bone) would come within 1 mm of the kerf of a saw cutting the bone
 *   nearby is left out with a warning (two cuts a few millimetres apart:
 *   the blade would meet the screw).
 * - The shell: the contact moved Clearance along the approach (room for the
 *   periosteum, or for the printer's tolerance) and swept Thickness along it
 *   by vtkLinearExtrusionFilter, capped, oriented outward by
 *   vtkPolyDataNormals. The slot's walls are planes parallel to the cut's,
 *   SlotWidth apart, Thickness deep along the approach.
 * - The label (Label, none by default): the text raised 0.6 mm on the
 *   guide's outer face, LabelHeight tall (3 mm; less where the room beside
 *   the slot is narrower, 1.5 mm at least), its strokes 0.6 mm wide at
 *   least, reading along the slot as seen from the approach, beside the
 *   slot between a screw hole and an end of the guide (the first of the
 *   four such places the text fits on whole, on a face within 60 degrees of
 *   the approach), sunk 1 mm into the wall and joined to it into one solid
 *   (CGAL's corefinement, lk::solidUnion). Parts printed for one plan are
 *   told apart by it (the planner writes each saw line's stroke number).
 *   Given the plan's other saw planes (OtherCutPlanes), the label keeps off
 *   where their guides lie (bone within this guide's Reach of such a plane,
 *   near where that plane cuts the bone): it goes to the side of the slot
 *   away from a saw line nearby, moved out toward the guide's edge, or made
 *   smaller, as the room left asks. So on a block merged with a neighbour's
 *   guide (vtkLKGuideBarFilter) no wall of the other's covers it and its
 *   slot and screw holes do not cut it. A label with nothing to draw
 *   (vtkVectorText draws printable ASCII), longer than 40 characters or
 *   without room is left out with a warning; the guide is made without it.
 *
 * Input: a bone surface (polygons; a closed mesh, so that its outside is
 * known). Output: the guide, a closed triangle mesh oriented outward (ready
 * for STL). Field data: GuideApproach (3 values, unit), GuideSlotLength
 * (mm, along the plane), GuideContactArea (mm^2 of bone surface under the
 * guide, the slot and the holes left out), GuideVolume (mm^3),
 * GuideScrewHoles (a 3-value tuple for each hole: where its axis meets the
 * bone); what places the guide for other filters (vtkLKGuideBarFilter):
 * GuidePlaneNormal (unit), GuideSlotCentre (the middle of the slot on the
 * bone), GuideSlotWidth, GuideThickness, GuideReach, GuideClearance and
 * GuideScrewHoleDiameter (0: no holes); GuideLabel (a string array, the
 * label's text, only when it was put on) and GuideLabelBox (three 3-value
 * tuples: a corner of the text's rectangle in the plane through
 * PlaneOrigin square to the approach, the text's width along its reading
 * direction and its height along its up; the label lies on the outer face
 * over that rectangle along the approach); and the input's SPACE tag. The same values are kept in the filter
 * after an update.
 *
 * Errors (a VTK error and an empty output): a plane normal or an approach
 * that is zero, not finite or (the approach) along the normal; an other
 * cut plane with such a normal or origin; a parameter out of its range; an
 * input without polygons; a plane that meets no part
 * of the bone; no face at the section facing the approach; a contact too
 * short along the plane for a slot and two bridges.
 */
#ifndef vtkLKCuttingGuideFilter_h
#define vtkLKCuttingGuideFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for PutOnLabel

#include <array>  // for PutOnLabel
#include <functional> // for PutOnLabel
#include <string> // for PutOnLabel

class vtkPlaneCollection;

class LATTICEKITFILTERS_EXPORT vtkLKCuttingGuideFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKCuttingGuideFilter* New();
  vtkTypeMacro(vtkLKCuttingGuideFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /// The cut's plane: a point of it (the section loop nearest this point is
  /// the one the guide goes on) and its normal (finite, not zero; its length
  /// does not matter). Default: the plane x = 0.
  vtkSetVector3Macro(PlaneOrigin, double);
  vtkGetVector3Macro(PlaneOrigin, double);
  vtkSetVector3Macro(PlaneNormal, double);
  vtkGetVector3Macro(PlaneNormal, double);
  ///@}

  ///@{
  /// The side the guide goes on: a direction from the bone toward the
  /// surgeon, projected into the plane. Default 0, 0, 0: the section's short
  /// axis, toward the bone's outer side (see above).
  vtkSetVector3Macro(Approach, double);
  vtkGetVector3Macro(Approach, double);
  /// The guide on the other side of the bone: the approach (given or
  /// chosen) reversed (a lingual guide; default off).
  vtkSetMacro(OtherSide, bool);
  vtkGetMacro(OtherSide, bool);
  vtkBooleanMacro(OtherSide, bool);
  ///@}

  ///@{
  /// The guide's wall, along the approach: mm, default 4 (0.1 to 100).
  vtkSetMacro(Thickness, double);
  vtkGetMacro(Thickness, double);
  /// How far the guide reaches on each side of the plane: mm, default 8
  /// (more than SlotWidth / 2, at most 200).
  vtkSetMacro(Reach, double);
  vtkGetMacro(Reach, double);
  /// The slot's width: the saw blade and its play, mm, default 1.2 (0.05 to 20).
  vtkSetMacro(SlotWidth, double);
  vtkGetMacro(SlotWidth, double);
  /// The guide's material left at each end of the slot: mm, default 3 (0 to 100).
  vtkSetMacro(Bridge, double);
  vtkGetMacro(Bridge, double);
  /// The gap between the bone and the guide along the approach: mm,
  /// default 0 (0 to 10).
  vtkSetMacro(Clearance, double);
  vtkGetMacro(Clearance, double);
  /// The screw holes' diameter, mm: one hole on each side of the slot fixes
  /// the guide to the bone (2.1 mm: a 2.0 mm screw through it; 0: none;
  /// at most 10, and 1 mm less than the guide's reach beside the slot).
  vtkSetMacro(ScrewHoleDiameter, double);
  vtkGetMacro(ScrewHoleDiameter, double);
  /// The largest angle between a face's normal and the approach for the
  /// guide to rest on it: degrees, default 70 (1 to 89).
  vtkSetMacro(MaximumContactAngle, double);
  vtkGetMacro(MaximumContactAngle, double);
  /// The text raised on the guide's outer face (see above; default none).
  vtkSetStringMacro(Label);
  vtkGetStringMacro(Label);
  /// The label's height: mm, default 3 (1.5 to 20; less where it has no
  /// room, down to 1.5).
  vtkSetMacro(LabelHeight, double);
  vtkGetMacro(LabelHeight, double);
  /// The plan's other saw planes (default none): the label keeps off where
  /// their guides lie, taken to reach as far as this one's, and a screw
  /// hole their saws would meet is left out (see above). This guide's own
  /// plane among them is passed over.
  void SetOtherCutPlanes(vtkPlaneCollection* planes);
  vtkGetObjectMacro(OtherCutPlanes, vtkPlaneCollection);
  ///@}

  /// Also the other cut planes' modification times.
  vtkMTimeType GetMTime() override;

  ///@{
  /// After an update (zeros before, or after an error): the approach used
  /// (unit), the slot's length along the plane, the bone surface's area
  /// under the guide and the guide's volume.
  vtkGetVector3Macro(ApproachUsed, double);
  vtkGetMacro(SlotLength, double);
  vtkGetMacro(ContactArea, double);
  vtkGetMacro(Volume, double);
  /// The screw holes made (0 to 2: a hole whose ray meets no bone is left out).
  vtkGetMacro(NumberOfScrewHoles, int);
  /// The screw holes left out because another cut plane's saw would meet
  /// their screws (0 to 2; each is warned of).
  vtkGetMacro(NumberOfScrewHolesLeftOut, int);
  /// Whether the label was put on (false without one, or without room),
  /// and its height there (mm; 0 without).
  vtkGetMacro(LabelPlaced, bool);
  vtkGetMacro(LabelHeightUsed, double);
  ///@}

protected:
  vtkLKCuttingGuideFilter() = default;
  ~vtkLKCuttingGuideFilter() override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double PlaneOrigin[3] = { 0.0, 0.0, 0.0 };
  double PlaneNormal[3] = { 1.0, 0.0, 0.0 };
  double Approach[3] = { 0.0, 0.0, 0.0 };
  bool OtherSide = false;
  double Thickness = 4.0;
  double Reach = 8.0;
  double SlotWidth = 1.2;
  double Bridge = 3.0;
  double Clearance = 0.0;
  double MaximumContactAngle = 70.0;
  double ScrewHoleDiameter = 2.1;
  char* Label = nullptr;
  double LabelHeight = 3.0;
  vtkPlaneCollection* OtherCutPlanes = nullptr;
  int NumberOfScrewHoles = 0;
  int NumberOfScrewHolesLeftOut = 0;
  bool LabelPlaced = false;
  double LabelHeightUsed = 0.0;
  double LabelBox[9] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 };
  double ApproachUsed[3] = { 0.0, 0.0, 0.0 };
  double SlotLength = 0.0;
  double ContactArea = 0.0;
  double Volume = 0.0;

private:
  /// Raises the label on `shell` (the guide, replaced by the union) at the
  /// first place it fits (o, n, e, d: the plane's point and normal, the
  /// direction along the plane and the approach; low, high: the guide's
  /// extent along e), clear of where `underOther` (a point of the outer
  /// face, a margin in mm) says another saw line's guide lies (none if
  /// empty); empty, or why it was left out.
  std::string PutOnLabel(vtkSmartPointer<vtkPolyData>& shell, const std::array<double, 3>& o,
    const std::array<double, 3>& n, const std::array<double, 3>& e, const std::array<double, 3>& d, double low,
    double high, const std::function<bool(const std::array<double, 3>&, double)>& underOther);

  vtkLKCuttingGuideFilter(const vtkLKCuttingGuideFilter&) = delete;
  void operator=(const vtkLKCuttingGuideFilter&) = delete;
};

#endif
