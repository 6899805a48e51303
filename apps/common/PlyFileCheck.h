#pragma once
/// \file PlyFileCheck.h
/// Whether a PLY file holds everything its header declares, checked before
/// VTK reads it: Debian's vtkPLYReader (VTK 9.1) reads past the end of a
/// truncated file (binary or ASCII) and then crashes (a double free or a bad
/// memory access), where the tools must say the file is corrupt.

#include <string>

namespace lkapp
{

/// Empty when the PLY file at `path` has a header that can be read and a
/// body that holds every element and property the header declares, in its
/// format (ascii, binary_little_endian or binary_big_endian). Otherwise what
/// is wrong, for "the file is corrupt (...)": "it ends in face 49 of 96: the
/// file is truncated", "its header has no end_header line", ...
std::string plyFileProblem(const std::string& path);

} // namespace lkapp
