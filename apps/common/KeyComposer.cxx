#include "common/KeyComposer.h"

#include "common/KeyCharacter.h"
#include "vtkLKText.h"

#include <xkbcommon/xkbcommon-compose.h>
#include <xkbcommon/xkbcommon.h>

#include <cstdlib>
#include <vector>

namespace lkapp
{

namespace
{

/// The locale X reads the Compose table of: LC_ALL, LC_CTYPE, LANG.
std::string userLocale()
{
  for (const char* name : { "LC_ALL", "LC_CTYPE", "LANG" })
    if (const char* value = std::getenv(name); value != nullptr && *value != '\0')
      return value;
  return "C";
}

/// "cs_CZ.ISO-8859-2" -> "cs_CZ.UTF-8", "sr_RS@latin" -> "sr_RS.UTF-8@latin":
/// names are kept in UTF-8, whatever the locale's own character set.
std::string utf8Locale(const std::string& locale)
{
  const std::size_t at = locale.find('@');
  const std::string modifier = at == std::string::npos ? "" : locale.substr(at);
  std::string base = locale.substr(0, at);
  base = base.substr(0, base.find('.'));
  if (base.empty() || base == "POSIX")
    base = "C";
  return base + ".UTF-8" + modifier;
}

/// The table's results are UTF-8 (xkbcommon refuses a table that is not).
std::u32string decode(const char* text)
{
  std::vector<char32_t> characters;
  lkvtk::decodeUTF8(text, &characters);
  return std::u32string(characters.begin(), characters.end());
}

}

struct KeyComposer::Internal
{
  xkb_context* context = nullptr;
  xkb_compose_table* table = nullptr;
  xkb_compose_state* state = nullptr;
  std::vector<xkb_keysym_t> sequence; // the keys of the sequence waiting
  bool cancelled = false;

  ~Internal()
  {
    xkb_compose_state_unref(state);
    xkb_compose_table_unref(table);
    xkb_context_unref(context);
  }
};

KeyComposer::KeyComposer(const std::string& locale)
  : internal(std::make_unique<Internal>())
{
  Internal& in = *internal;
  in.context = xkb_context_new(XKB_CONTEXT_NO_FLAGS);
  if (in.context == nullptr)
    return;
  // A locale without a table of its own is not an error to print.
  xkb_context_set_log_level(in.context, XKB_LOG_LEVEL_CRITICAL);
  for (const std::string& name : { utf8Locale(locale.empty() ? userLocale() : locale), std::string("C.UTF-8") })
    if ((in.table = xkb_compose_table_new_from_locale(in.context, name.c_str(), XKB_COMPOSE_COMPILE_NO_FLAGS)))
      break;
  if (in.table != nullptr)
    in.state = xkb_compose_state_new(in.table, XKB_COMPOSE_STATE_NO_FLAGS);
}

KeyComposer::~KeyComposer() = default;

bool KeyComposer::hasTable() const
{
  return internal->state != nullptr;
}

std::u32string KeyComposer::type(const std::string& keySym, char keyCode, bool control)
{
  Internal& in = *internal;
  in.cancelled = false;
  const char32_t plain = keyCharacter(keySym, keyCode, control);
  const std::u32string own = plain != 0 ? std::u32string(1, plain) : std::u32string(); // the key's own character
  if (in.state == nullptr)
    return own;
  if (control)
  {
    in.cancelled = composing();
    reset();
    return {};
  }
  xkb_keysym_t symbol =
    keySym.empty() ? XKB_KEY_NoSymbol : xkb_keysym_from_name(keySym.c_str(), XKB_KEYSYM_NO_FLAGS);
  if (symbol == XKB_KEY_NoSymbol && plain != 0)
    symbol = xkb_utf32_to_keysym(plain); // a key known by its byte only
  if (symbol == XKB_KEY_NoSymbol || xkb_compose_state_feed(in.state, symbol) == XKB_COMPOSE_FEED_IGNORED)
    return composing() ? std::u32string() : own;
  switch (xkb_compose_state_get_status(in.state))
  {
    case XKB_COMPOSE_COMPOSING:
      in.sequence.push_back(symbol);
      return {};
    case XKB_COMPOSE_COMPOSED:
    {
      char buffer[64] = {};
      xkb_compose_state_get_utf8(in.state, buffer, sizeof buffer);
      reset();
      return decode(buffer);
    }
    case XKB_COMPOSE_CANCELLED:
      in.cancelled = true;
      reset();
      return {};
    default:
      return own;
  }
}

bool KeyComposer::composing() const
{
  return internal->state != nullptr && xkb_compose_state_get_status(internal->state) == XKB_COMPOSE_COMPOSING;
}

bool KeyComposer::cancelled() const
{
  return internal->cancelled;
}

std::string KeyComposer::pending() const
{
  const Internal& in = *internal;
  if (!composing())
    return {};
  // A dead key's spacing accent is what the table composes of the key
  // pressed twice (dead acute twice: "´"); another key of the sequence
  // (after Compose) shows as its own character.
  std::string text;
  xkb_compose_state* scratch = xkb_compose_state_new(in.table, XKB_COMPOSE_STATE_NO_FLAGS);
  for (const xkb_keysym_t symbol : in.sequence)
  {
    xkb_compose_state_reset(scratch);
    xkb_compose_state_feed(scratch, symbol);
    xkb_compose_state_feed(scratch, symbol);
    char buffer[64] = {};
    if (xkb_compose_state_get_status(scratch) == XKB_COMPOSE_COMPOSED &&
      xkb_compose_state_get_utf8(scratch, buffer, sizeof buffer) > 0)
      text += buffer;
    else if (const char32_t c = xkb_keysym_to_utf32(symbol); c != 0 && !lkvtk::isControl(c))
      text += lkvtk::encodeUTF8(c);
  }
  xkb_compose_state_unref(scratch);
  return text;
}

void KeyComposer::reset()
{
  if (internal->state != nullptr)
    xkb_compose_state_reset(internal->state);
  internal->sequence.clear();
}

}
