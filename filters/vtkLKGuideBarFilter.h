/**
 * @class   vtkLKGuideBarFilter
 * @brief   Cutting guides joined by bars over the bone between them: a
 *          resection guide, one part to print.
 *
 * A segment of bone taken out between two saw cuts (a mandible's body
 * before a fibula flap) is cut through two slots. Printed apart, the two
 * guides of vtkLKCuttingGuideFilter can each be put on a little off the
 * plan; joined, they hold the two cuts at the distance and angle the plan
 * gave them, and the bar over the segment gives the surgeon something to
 * hold. This filter makes that part. Three or more guides, given in their
 * order along the bone (a segment taken out in two pieces, a chin cut between
 * two body cuts), are joined in that order: a bar between each guide and the
 * next, all in one part.
 *
 * Method:
 * - Each guide's place comes from its field data (GuideApproach,
 *   GuidePlaneNormal, GuideSlotCentre, GuideSlotWidth, GuideThickness,
 *   GuideReach, GuideClearance, GuideScrewHoleDiameter, as
 *   vtkLKCuttingGuideFilter writes them).
 * - The bar starts at each guide's edge on the other guide's side of its
 *   slot, clear of its screw hole (so the hole still takes its screw from
 *   above), in the guide's wall there: its middle above the bone (found by
 *   a ray along the guide's approach), or higher until the bar's radius
 *   clears the bone (a bar thicker than the wall, a wall on a slope). It
 *   starts across from the slot's middle, or, where the bar would stand
 *   over the guide's label there (GuideLabelBox; the bar rising off the
 *   wall beside it, or running along the edge toward the other guide),
 *   moved along the slot away from the label, 2 mm at a time while it stays
 *   a radius inside the slot's ends, until it clears it.
 * - Its centre line starts straight from end to end and is pushed away
 *   from the bone (vtkImplicitPolyDataDistance: away from the nearest point
 *   of the bone outside it, along the guides' mean approach inside it),
 *   with smoothing between pushes, until every point of it lies at least
 *   StandOff plus the bar's radius from the bone (the radius alone near the
 *   ends, growing to that in a smooth step over 5 mm and twice StandOff
 *   from a radius past each guide's edge, so that it bends gently). So the bar
 *   arches over the bone (the chin between two cuts beside it) and touches
 *   nothing it does not have to: the periosteum is not pressed, and the
 *   guide seats on the guides' contact only.
 * - One direction must put the whole part on the bone, as it is rigid: the
 *   guides' contacts (their faces on the bone) must all face it, as each
 *   guide's contact faces its own approach. The direction that leaves the
 *   steepest contact face the most room (searched over the half sphere
 *   round the guides' mean approach) is the part's approach. Along it a
 *   few contact faces may still face back a little (a label map's steps):
 *   up to 10 degrees, over up to 5 % of the contact's area, is an undercut
 *   that printing's tolerance and the periosteum take up, and is reported;
 *   more (far round the bone: a ramus guide on each side) is refused.
 * - Guides next to each other whose edges are nearer than the bar's
 *   diameter have no room for it to arch out: it runs straight from wall
 *   to wall (refused where that would reach into the bone).
 * - Guides next to each other whose slots are nearer along the bone (along
 *   their planes' mean normal) than their two reaches overlap on it (two
 *   saw lines 12 mm apart across a short segment, a wedge): no bar fits
 *   between them, and printed apart they could not be on the bone
 *   together. They are merged into one block instead: each
 *   guide less the other's slot (a box a hundredth of a millimetre wider
 *   and longer, through the whole block along that guide's approach) and
 *   screw holes (0.05 mm wider), then joined, so that every slot and hole
 *   stays open through the block. Their slots must leave a wall of 2 mm
 *   between them; merged guides that do not meet (their slots offset along
 *   each other) are refused.
 * - Guides next to each other whose bodies overlap though their slots are
 *   far apart along the bone (saw planes that cross near it: a long guide
 *   on a ramus and one across its top, an L-shaped cut) would each stand in
 *   the other's saw path or over a screw hole, bar or not: they are one
 *   block already, and are merged the same way (refused where each less the
 *   other's slot falls apart).
 * - Guides farther apart in the order whose bodies overlap all the same,
 *   with a bar between them (the two cuts of a V whose guides meet at its
 *   point, with a third guide beyond it in the order), are each cut by the
 *   other's slot and screw holes as merged guides are, and are one with the
 *   bars. A bar that reaches into a guide other than the two it joins (one
 *   merged with either, or crossed) is cut by that guide's slot and screw
 *   holes too. Bodies overlap where a point of one, or a point 0.25 mm
 *   inside it, lies more than 0.05 mm inside the other; a bar meets a guide
 *   where its centre line comes within its radius less 0.05 mm.
 * - The bar is a tube round that line (vtkTubeFilter, capped), and the
 *   guides and the bars are joined into one closed surface (CGAL's
 *   corefinement, lk::solidUnion; the slots cut by lk::solidDifference):
 *   one part, facing outward, its volume what it looks to be.
 *
 * Inputs: port 0, the bone surface (a closed mesh) the guides were made on;
 * port 1, two or more guides (connections, vtkLKCuttingGuideFilter's
 * outputs), in their order along the bone. Output: the joined guide, a
 * closed triangle mesh oriented outward. Field data: GuideBarLength (mm
 * along each bar's centre line, one value for each bar, in order; merged
 * guides have none between them), GuideMerged (for each guide and the
 * next, 1 where they were merged into one block, else 0), GuideCrossings
 * (two components: the guides, from 0, of each pair not next to each
 * other that crossed),
 * GuideBarGap (for each bar, the least distance between it and the bone
 * where it is farthest from both its guides: StandOff, or less for guides
 * too near each other for the bar to rise that far, mm), GuideBarDiameter
 * (mm), GuideVolume (mm^3), GuideApproach (the part's, unit, away from the
 * bone), GuideInsertionMargin (degrees: how far short of square to it the
 * steepest contact face stays; negative, past it), GuideUndercutArea (mm^2
 * of contact facing back from it), and the bone's SPACE tag. The same values are
 * kept in the filter after an update.
 *
 * Warned of (the part is made): a guide's label (GuideLabel,
 * GuideLabelBox) that the part does not show as the guide did (a merged
 * neighbour's wall or a bar stands over it, a slot or a screw hole cuts
 * it), and a screw hole of a merged (or overlapping) guide whose screw
 * would lie in a neighbour's saw path (within 1 mm of its slot's plane, to
 * 10 mm into the bone).
 * vtkLKCuttingGuideFilter keeps labels clear of the neighbours' guides, and
 * leaves such holes out, when given the plan's other saw planes
 * (OtherCutPlanes).
 *
 * Errors (a VTK error and an empty output): fewer than two guides, or a
 * guide without the field data above (or with data that describe no
 * guide); a parameter out of range; two guides next to each other put on
 * from directions more than 120 degrees apart (the bar would go round the
 * bone); two guides next to each other farther apart than MaximumLength,
 * with slots too near for a wall of 2 mm between them (one saw cut twice),
 * merged without meeting (one beside the other on the bone), overlapping
 * so that one's slot cuts the other apart, or joined by
 * a straight bar that would reach into the bone; a guide whose
 * neighbours before and after it lie on one side of its slot (guides not in
 * their order along the bone: a bar would pass over a guide); guides no one
 * direction puts on the bone at once (their contacts face too far apart:
 * more undercut than above);
 * no room for
 * a bar beside a screw hole; no bone under a guide's edge (another bone); a
 * bar that cannot clear the bone, or that would bend tighter than its
 * radius; a union CGAL cannot make (a guide that crosses itself).
 */
#ifndef vtkLKGuideBarFilter_h
#define vtkLKGuideBarFilter_h

#include "LatticeKitFiltersModule.h"
#include "vtkPolyDataAlgorithm.h"

#include <array>
#include <vector>

class LATTICEKITFILTERS_EXPORT vtkLKGuideBarFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkLKGuideBarFilter* New();
  vtkTypeMacro(vtkLKGuideBarFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /// The bone on port 0; the guides on port 1 (AddInputData(1, guide)), in
  /// their order along the bone.
  /// @{
  void SetBoneData(vtkDataObject* bone) { this->SetInputData(0, bone); }
  void AddGuideData(vtkDataObject* guide) { this->AddInputData(1, guide); }
  void AddGuideConnection(vtkAlgorithmOutput* guide) { this->AddInputConnection(1, guide); }
  /// @}

  ///@{
  /// The bars' diameter: mm, default 0: the guides' wall thickness (the
  /// thinnest one's); otherwise 1 to 20.
  vtkSetMacro(Diameter, double);
  vtkGetMacro(Diameter, double);
  /// The least gap between a bar and the bone away from the guides: mm,
  /// default 2 (0 to 50).
  vtkSetMacro(StandOff, double);
  vtkGetMacro(StandOff, double);
  /// The longest bar made: mm along its centre line, default 150 (1 to
  /// 1000). Guides next to each other and farther apart are refused.
  vtkSetMacro(MaximumLength, double);
  vtkGetMacro(MaximumLength, double);
  ///@}

  ///@{
  /// After an update (zeros before, or after an error): the bars' length
  /// all together (mm), their diameter, the least of their gaps (these
  /// three 0 where every pair was merged: no bar), the part's volume (mm^3).
  vtkGetMacro(BarLength, double);
  vtkGetMacro(BarDiameter, double);
  vtkGetMacro(BarGap, double);
  vtkGetMacro(Volume, double);
  ///@}

  ///@{
  /// After an update (zeros before, or after an error): the direction the
  /// part is put on from (unit, away from the bone, as each guide's
  /// GuideApproach); how far short of square to it (degrees) the steepest
  /// face of the guides' contacts stays (the room the part has to go on
  /// along it; negative: that face reaches under the bone, by 10 degrees at
  /// most); and the contact's area (mm^2) that faces back from it, an
  /// undercut (5 % of the contact at most) that may need trimming.
  vtkGetVector3Macro(ApproachUsed, double);
  vtkGetMacro(InsertionMargin, double);
  vtkGetMacro(UndercutArea, double);
  ///@}

  ///@{
  /// After an update: how many bars (guides less one, less the pairs
  /// merged; 0 before, or after an error), and the length and gap of bar
  /// `bar` (in their order along the guides, merged pairs having none; 0
  /// for a bar there is not).
  int GetNumberOfBars() { return static_cast<int>(this->BarLengths.size()); }
  double GetBarLength(int bar);
  double GetBarGap(int bar);
  ///@}

  ///@{
  /// After an update: whether guide `pair` + 1 and the next (0 is guides 1
  /// and 2) were merged into one block rather than joined by a bar (false
  /// for a pair there is not), and how many pairs were.
  bool GetMerged(int pair);
  int GetNumberOfMerges();
  ///@}

  ///@{
  /// After an update: whether guides `a` + 1 and `b` + 1 (0 is guide 1),
  /// not next to each other in the order given, overlap with a bar between
  /// them (saw planes that cross near the bone: the two cuts of a V with a
  /// third guide beyond its point) and so were each cut by the other's slot
  /// and screw holes; and how many such pairs there were.
  bool GetCrossed(int a, int b);
  int GetNumberOfCrossings();
  ///@}

  /// After an update: how many of the guides' labels (GuideLabelBox) the
  /// part does not show as the guide did (another guide's wall or a bar over
  /// it, a slot or a screw hole through it; each is warned of). No merged
  /// neighbour's where vtkLKCuttingGuideFilter was given the plan's other
  /// saw planes (OtherCutPlanes); a bar stands over one only where no start
  /// along the slot clears it.
  vtkGetMacro(NumberOfLabelsCovered, int);
  /// After an update: how many screw holes of merged (or overlapping)
  /// guides lie in the path of a neighbour's saw (their screws within 1 mm
  /// of its slot's plane; each is warned of). 0 where vtkLKCuttingGuideFilter was given the
  /// plan's other saw planes, which leaves such holes out.
  vtkGetMacro(NumberOfScrewHolesInSawPaths, int);

protected:
  vtkLKGuideBarFilter();
  ~vtkLKGuideBarFilter() override = default;
  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  double Diameter = 0.0;
  double StandOff = 2.0;
  double MaximumLength = 150.0;
  double BarLength = 0.0;
  double BarDiameter = 0.0;
  double BarGap = 0.0;
  double Volume = 0.0;
  double ApproachUsed[3] = { 0.0, 0.0, 0.0 };
  double InsertionMargin = 0.0;
  double UndercutArea = 0.0;
  int NumberOfLabelsCovered = 0;
  int NumberOfScrewHolesInSawPaths = 0;
  std::vector<double> BarLengths;
  std::vector<double> BarGaps;
  std::vector<char> Merged;
  std::vector<std::array<int, 2>> Crossings;

private:
  vtkLKGuideBarFilter(const vtkLKGuideBarFilter&) = delete;
  void operator=(const vtkLKGuideBarFilter&) = delete;
};

#endif
