// lkapp::KeyComposer: dead accents and the Compose key, through the Compose
// table of the locale (here always "C.UTF-8", which is en_US.UTF-8's table,
// so the test does not depend on the machine's language).
#include "common/KeyComposer.h"

#include <gtest/gtest.h>

#include <cstdlib>

using lkapp::KeyComposer;

namespace
{

class KeyComposerTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    // A user's own Compose file must not change what the test sees.
    setenv("XCOMPOSEFILE", "/nonexistent/Compose", 1);
    composer = std::make_unique<KeyComposer>("C.UTF-8");
    ASSERT_TRUE(composer->hasTable()) << "no Compose table (libx11-data)";
  }
  std::u32string type(const std::string& keySym, char keyCode = 0, bool control = false)
  {
    return composer->type(keySym, keyCode, control);
  }
  std::unique_ptr<KeyComposer> composer;
};

}

TEST_F(KeyComposerTest, PlainKeysTypeTheirCharacter)
{
  EXPECT_EQ(type("a", 'a'), U"a");
  EXPECT_EQ(type("Ccaron"), U"\u010C");
  EXPECT_EQ(type("Cyrillic_ya", '0'), U"\u044F");
  EXPECT_EQ(type("Shift_L"), U"");
  EXPECT_EQ(type("F5"), U"");
  EXPECT_EQ(type("", 'q'), U"q"); // a key known by its byte only
  EXPECT_FALSE(composer->composing());
  EXPECT_FALSE(composer->cancelled());
}

TEST_F(KeyComposerTest, DeadAccentsComposeWithTheNextLetter)
{
  EXPECT_EQ(type("dead_acute"), U"");
  EXPECT_TRUE(composer->composing());
  EXPECT_EQ(composer->pending(), "\u00B4");
  EXPECT_EQ(type("e", 'e'), U"\u00E9");
  EXPECT_FALSE(composer->composing());
  EXPECT_EQ(composer->pending(), "");

  EXPECT_EQ(type("dead_caron"), U"");
  EXPECT_EQ(composer->pending(), "\u02C7");
  EXPECT_EQ(type("Shift_L"), U""); // Shift waits with the accent
  EXPECT_TRUE(composer->composing());
  EXPECT_EQ(type("C", 'C'), U"\u010C");

  // Two accents on one letter (Vietnamese), the accent alone, the ring.
  EXPECT_EQ(type("dead_circumflex"), U"");
  EXPECT_EQ(type("dead_acute"), U"");
  EXPECT_EQ(composer->pending(), "^\u00B4");
  EXPECT_EQ(type("a", 'a'), U"\u1EA5");
  EXPECT_EQ(type("dead_acute"), U"");
  EXPECT_EQ(type("dead_acute"), U"\u00B4");
  EXPECT_EQ(type("dead_abovering"), U"");
  EXPECT_EQ(type("a", 'a'), U"\u00E5");
}

TEST_F(KeyComposerTest, TheComposeKey)
{
  EXPECT_EQ(type("Multi_key"), U"");
  EXPECT_EQ(type("O", 'O'), U"");
  EXPECT_EQ(composer->pending(), "O"); // Compose itself has no glyph
  EXPECT_EQ(type("slash", '/'), U"\u00D8");
  EXPECT_EQ(type("Multi_key"), U"");
  EXPECT_EQ(type("o", 'o'), U"");
  EXPECT_EQ(type("c", 'c'), U"\u00A9");
}

TEST_F(KeyComposerTest, AKeyThatFitsNoSequenceCancelsIt)
{
  EXPECT_EQ(type("dead_acute"), U"");
  EXPECT_EQ(type("q", 'q'), U""); // swallowed, as libX11 does
  EXPECT_TRUE(composer->cancelled());
  EXPECT_FALSE(composer->composing());
  EXPECT_EQ(type("q", 'q'), U"q");
  EXPECT_FALSE(composer->cancelled());

  EXPECT_EQ(type("dead_caron"), U"");
  EXPECT_EQ(type("Left"), U"");
  EXPECT_TRUE(composer->cancelled());

  // Control cancels too and types nothing.
  EXPECT_EQ(type("dead_acute"), U"");
  EXPECT_EQ(type("e", '\x05', true), U"");
  EXPECT_TRUE(composer->cancelled());
  EXPECT_EQ(type("e", 'e'), U"e");
}

TEST_F(KeyComposerTest, ResetDropsTheAccentThatWaits)
{
  EXPECT_EQ(type("dead_acute"), U"");
  composer->reset();
  EXPECT_FALSE(composer->composing());
  EXPECT_EQ(composer->pending(), "");
  EXPECT_EQ(type("e", 'e'), U"e");
}

TEST(KeyComposer, LocalesFindAUTF8Table)
{
  setenv("XCOMPOSEFILE", "/nonexistent/Compose", 1);
  // A Latin-2 locale reads its UTF-8 table; a locale X has no table for
  // falls back to C.UTF-8's; both compose the same Czech letter.
  for (const char* locale : { "cs_CZ.ISO-8859-2", "xx_YY", "POSIX", "de_DE.UTF-8@euro" })
  {
    KeyComposer composer(locale);
    ASSERT_TRUE(composer.hasTable()) << locale;
    composer.type("dead_caron", 0, false);
    EXPECT_EQ(composer.type("c", 'c', false), U"\u010D") << locale;
  }
}
