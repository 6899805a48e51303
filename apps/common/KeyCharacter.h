#pragma once
/// \file KeyCharacter.h
/// The character a key types, on every keyboard. VTK 9.1's X interactor
/// gives a key as the name of its key symbol ("Ccaron", "Cyrillic_ya",
/// "Shift_L") and XLookupString's byte, which is Latin-1 only: "a" with two
/// dots is 0xE4, a Czech c with a caron or any Greek or Cyrillic letter no
/// byte at all. The symbol's name says them all.

#include <string>

namespace lkapp
{

/// The character typed by the key whose symbol is named `keySym` (VTK's
/// GetKeySym) and whose byte is `keyCode` (GetKeyCode): the symbol's, as
/// xkbcommon knows it ("Ccaron" U+010C, "Greek_alpha" U+03B1, "KP_0" '0',
/// "space" ' ', "U20AC" the euro sign), or the byte where there is no symbol
/// xkbcommon knows. 0 for a key that types nothing: Shift, an arrow, a
/// function key, a dead accent (KeyComposer composes it with the next key),
/// and any key pressed with Control. Return, Tab and the like give their
/// control characters (U+000D, U+0009).
char32_t keyCharacter(const std::string& keySym, char keyCode, bool control);

}
