#include "common/KeyCharacter.h"

#include <xkbcommon/xkbcommon.h>

namespace lkapp
{

char32_t keyCharacter(const std::string& keySym, char keyCode, bool control)
{
  if (control)
    return 0;
  const xkb_keysym_t symbol =
    keySym.empty() ? XKB_KEY_NoSymbol : xkb_keysym_from_name(keySym.c_str(), XKB_KEYSYM_NO_FLAGS);
  // An event log cannot give a key code of none (its "0" is the digit), so
  // a symbol xkbcommon knows decides even where it types nothing.
  return symbol != XKB_KEY_NoSymbol ? xkb_keysym_to_utf32(symbol) : static_cast<unsigned char>(keyCode);
}

}
