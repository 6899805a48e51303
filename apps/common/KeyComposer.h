#pragma once
/// \file KeyComposer.h
/// Dead accents and the Compose key, as X's input methods compose them: a
/// dead acute then "e" types "é", a dead caron then "C" types "Č", Compose
/// then "o" "c" types "©". VTK 9.1's X interactor opens no input method, so
/// a dead key reaches it as a key symbol ("dead_acute") that types nothing;
/// KeyComposer follows the sequences through the locale's Compose table
/// (xkbcommon reads the same files as libX11: XCOMPOSEFILE, ~/.XCompose,
/// then the system's table for the locale).

#include <memory>
#include <string>

namespace lkapp
{

class KeyComposer
{
public:
  /// The Compose table of `locale`, in its UTF-8 form ("cs_CZ.ISO-8859-2"
  /// reads "cs_CZ.UTF-8"), or of "C.UTF-8" where that locale has none. An
  /// empty `locale` is the user's, as X finds it: LC_ALL, LC_CTYPE, LANG.
  explicit KeyComposer(const std::string& locale = "");
  ~KeyComposer();
  KeyComposer(const KeyComposer&) = delete;
  KeyComposer& operator=(const KeyComposer&) = delete;

  /// False where no Compose table could be read: keys then type what
  /// keyCharacter says, and a dead accent nothing.
  bool hasTable() const;

  /// What the key named `keySym` (byte `keyCode`, as keyCharacter takes
  /// them) types: its character; nothing while it starts or goes on with a
  /// sequence; the composed text ("é") when it ends one; nothing when it
  /// cancels one (a dead acute then "q": the key is swallowed, as libX11
  /// does). Shift and the other modifiers leave a sequence as it is; a key
  /// pressed with Control cancels it and types nothing.
  std::u32string type(const std::string& keySym, char keyCode, bool control);

  /// True while a sequence waits for its next key.
  bool composing() const;
  /// True when the last key given to `type` cancelled a sequence.
  bool cancelled() const;
  /// The spacing accent of the sequence waiting ("´" for a dead acute, "ˇ"
  /// for a dead caron), to show where the letter will go; empty when none is
  /// waiting or the table gives the sequence no spacing form.
  std::string pending() const;
  /// Drops a sequence that waits (Escape, BackSpace, the end of typing).
  void reset();

private:
  struct Internal;
  std::unique_ptr<Internal> internal;
};

}
