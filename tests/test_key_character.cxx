// lkapp::keyCharacter: the character a key types, from its key symbol's
// name (xkbcommon) or X's Latin-1 byte, as VTK's interactor passes them.
#include "common/KeyCharacter.h"

#include <gtest/gtest.h>

using lkapp::keyCharacter;

TEST(KeyCharacter, LettersBeyondLatin1ComeFromTheSymbol)
{
  // X gives these no byte (key code 0).
  EXPECT_EQ(keyCharacter("Ccaron", 0, false), U'\u010C');
  EXPECT_EQ(keyCharacter("lstroke", 0, false), U'\u0142');
  EXPECT_EQ(keyCharacter("Cyrillic_CHE", 0, false), U'\u0427');
  EXPECT_EQ(keyCharacter("Greek_alphaaccent", 0, false), U'\u03AC');
  EXPECT_EQ(keyCharacter("hebrew_aleph", 0, false), U'\u05D0');
  EXPECT_EQ(keyCharacter("U20AC", 0, false), U'\u20AC');
  EXPECT_EQ(keyCharacter("U1F600", 0, false), U'\U0001F600');
}

TEST(KeyCharacter, Latin1AndAsciiAgreeWithXsByte)
{
  EXPECT_EQ(keyCharacter("adiaeresis", static_cast<char>(0xE4), false), U'\u00E4');
  EXPECT_EQ(keyCharacter("S", 'S', false), U'S');
  EXPECT_EQ(keyCharacter("backslash", '\\', false), U'\\');
  EXPECT_EQ(keyCharacter("space", ' ', false), U' ');
  EXPECT_EQ(keyCharacter("KP_7", '7', false), U'7');
}

TEST(KeyCharacter, EventLogsNameWhatTheirKeyCodesCannotSay)
{
  // An event log's key code "0" is the digit: the symbol decides.
  EXPECT_EQ(keyCharacter("space", '0', false), U' ');
  EXPECT_EQ(keyCharacter("KP_0", '0', false), U'0');
  EXPECT_EQ(keyCharacter("Cyrillic_ya", '0', false), U'\u044F');
  EXPECT_EQ(keyCharacter("Shift_L", '0', false), 0U);
  EXPECT_EQ(keyCharacter("0", '0', false), U'0');
}

TEST(KeyCharacter, KeysThatTypeNothing)
{
  EXPECT_EQ(keyCharacter("Shift_L", 0, false), 0U);
  EXPECT_EQ(keyCharacter("Left", 0, false), 0U);
  EXPECT_EQ(keyCharacter("F5", 0, false), 0U);
  EXPECT_EQ(keyCharacter("dead_acute", 0, false), 0U); // KeyComposer composes it
  EXPECT_EQ(keyCharacter("a", '\x01', true), 0U);      // Control+a
  EXPECT_EQ(keyCharacter("Cyrillic_a", 0, true), 0U);
  // Return and Tab give their control characters, which a caller refuses.
  EXPECT_EQ(keyCharacter("Return", '\r', false), U'\r');
  EXPECT_EQ(keyCharacter("Tab", '\t', false), U'\t');
}

TEST(KeyCharacter, WithoutAKnownSymbolTheByteCounts)
{
  EXPECT_EQ(keyCharacter("", 'q', false), U'q');
  EXPECT_EQ(keyCharacter("no-such-key-symbol", 'x', false), U'x');
  EXPECT_EQ(keyCharacter("", 0, false), 0U);
  EXPECT_EQ(keyCharacter("no-such-key-symbol", static_cast<char>(0xF6), false), U'\u00F6');
}
