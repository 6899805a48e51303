#pragma once
/// \file TextFont.h
/// A font that draws a piece's name whatever its script. VTK draws text
/// with the fonts compiled into it (Arial, Courier, Times), which hold the
/// Latin letters (Latin-1, Latin Extended-A, part of B) and no Greek,
/// Cyrillic, Hebrew, Arabic or CJK; VTK leaves out a character it has no
/// glyph for, so a name in Cyrillic showed as nothing at all.

#include <string>

class vtkTextProperty;

namespace lkapp
{

/// Makes `property` draw `text` (UTF-8). Where the compiled font of the
/// property's family has every character, that font (the property is put
/// back to Arial if an earlier text gave it a file); else the installed
/// font fontconfig picks for the text's characters, sans-serif, bold and
/// italic as the property asks (DejaVu Sans for Greek or Cyrillic, a CJK
/// font for kanji, on Debian). Returns the characters that neither has,
/// which VTK leaves out (UTF-8; empty when the whole text is drawn).
/// Lookups are kept, so calling it at every redraw costs little.
std::string useFontFor(vtkTextProperty* property, const std::string& text);

}
