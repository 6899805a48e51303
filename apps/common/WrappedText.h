#pragma once
/// \file WrappedText.h
/// Text broken into lines for a window's text actor, which draws each line
/// whole however wide it is; the room a text actor's text takes.

#include <array>
#include <cstddef>
#include <string>

class vtkRenderer;
class vtkTextActor;

namespace lkapp
{

/// `text` with every line broken to at most `width` characters (UTF-8
/// characters, not bytes): between the parts a " | " separates where it
/// can, so that a part stays whole (a number keeps its unit), the broken
/// line ending in " |" (which may stand past `width`); a part longer than
/// a line at its spaces (a longer word stays whole). Continuation lines are
/// indented two spaces.
std::string wrapped(const std::string& text, std::size_t width);

/// The width and height in pixels that `text`'s input takes drawn in
/// `renderer` (its font, all its lines); {0, 0} for an empty input or a
/// renderer in no window (nothing to measure in).
std::array<double, 2> textSize(vtkRenderer* renderer, vtkTextActor* text);

} // namespace lkapp
