#pragma once
/// \file CavityFill.h
/// Enclosed cavities of a voxel mask. An iso-surface of a CT at the skin's
/// value (about -400 HU) also bounds every air space inside the head: the
/// sinuses, the airway, the mouth. Those inner sheets join the skin through
/// the nostrils and the mouth, and make a surface of genus in the hundreds
/// where a skin model (the paper's head) has genus 0. A cavity is background
/// that cannot reach the volume's border without crossing foreground: in 3D
/// (sealed spaces) or, with `perSlice`, within its own slice k (spaces open
/// only along the slice axis, such as the airway in axial slices). Filling
/// them leaves the outer surface only.
#include <cstddef>
#include <vector>

namespace lk
{
/// `background` holds one flag per voxel, x fastest (index i + nx (j + ny k)).
/// Returns one flag per voxel: background that is enclosed (6-connected
/// flood from the border; with `perSlice`, 4-connected within each slice k
/// from that slice's border, on top of the 3D cavities). Throws
/// std::invalid_argument when the sizes do not match.
std::vector<char> enclosedBackground(const std::vector<char>& background, int nx, int ny, int nz, bool perSlice);
} // namespace lk
