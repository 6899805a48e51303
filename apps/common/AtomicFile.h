#pragma once
/// \file AtomicFile.h
/// Files written whole or not at all. A file the tools write goes first to a
/// temporary file beside it, is flushed to the disk, and only then renamed
/// over the old one (rename is atomic within a folder). A full disk, a file
/// size limit or a killed run therefore leaves the earlier file as it was,
/// never a truncated one that looks like the new result. VTK's writers do not
/// all notice a failed write (vtkPLYWriter, vtkOBJWriter and, in file mode,
/// the XML writers' executive report none), so the bytes are written here,
/// with every write checked.

#include <string>

namespace lkapp
{

/// Writes `contents` to `path` whole or not at all (see the file comment). A
/// link is followed (its target is replaced); an existing file keeps its
/// permissions, and one without write permission is refused as it would be
/// by a plain write. False with `error` ("cannot write 'PATH': REASON").
bool writeFileAtomically(const std::string& path, const std::string& contents, std::string& error);

/// A path cut into its folder (with its trailing '/', or empty), the file
/// name's stem and its last extension (with its dot; empty for a name with
/// none or one that only starts with a dot, as ".hidden").
struct FileNameParts
{
  std::string folder, stem, extension;
};
FileNameParts splitFileName(const std::string& path);

/// A path beside `path` (the same folder, so that a rename is atomic) for a
/// writer that only writes to a file name: ".STEM.partial-PID-N.EXT" for
/// STEM.EXT. Give it to commitTemporaryFile, or remove it.
std::string temporaryPathBeside(const std::string& path);

/// Flushes the file at `temporary` to the disk and renames it over `path`
/// (as writeFileAtomically does with its own). The temporary file is removed
/// on failure. False with `error`.
bool commitTemporaryFile(const std::string& temporary, const std::string& path, std::string& error);

} // namespace lkapp
