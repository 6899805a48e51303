#pragma once
/// \file MeshFileCheck.h
/// Whether a mesh file holds everything its header declares, checked before
/// VTK reads it, where VTK 9.1's readers do not check it themselves:
/// - vtkPLYReader reads past the end of a truncated PLY file (binary or
///   ASCII) and then crashes (a double free or a bad memory access);
/// - vtkSTLReader reads the triangles a truncated binary STL file still
///   holds, without a word, and the tools would go on with part of a mesh.

#include <string>

namespace lkapp
{

/// Empty when the PLY file at `path` has a header that can be read and a
/// body that holds every element and property the header declares, in its
/// format (ascii, binary_little_endian or binary_big_endian). Otherwise what
/// is wrong, for "the file is corrupt (...)": "it ends in face 49 of 96: the
/// file is truncated", "its header has no end_header line", ...
std::string plyFileProblem(const std::string& path);

/// Empty for an ASCII STL file (vtkSTLReader checks those: no NUL byte in
/// its first 512 bytes) and for a binary one at least as long as its
/// triangle count says (84 + 50 bytes per triangle; bytes beyond are
/// ignored, as VTK and other programs ignore them). Otherwise what is wrong:
/// "it declares 1,000 triangles (50,084 bytes) but has 20,000 bytes: the
/// file is truncated".
std::string stlFileProblem(const std::string& path);

} // namespace lkapp
