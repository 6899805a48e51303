// Text broken into lines for the planner's window (apps/common/WrappedText.h).
#include "common/WrappedText.h"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace
{
std::vector<std::string> linesOf(const std::string& text)
{
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);)
    lines.push_back(line);
  return lines;
}
} // namespace

TEST(WrappedText, BreaksBetweenThePartsABarSeparatesSoThatANumberKeepsItsUnit)
{
  // The planner's status line of five cut lines: broken at spaces it put
  // "16.7" at one line's end and "deg" at the next one's start.
  const std::string status = "cut lines: 1: 70.4 mm, 2: 74.7 mm | 1-2: 49.0 mm apart, 33.4 deg | "
                             "1-3: 29.9 mm apart, 16.7 deg | 1-4: 44.8 mm apart, 85.3 deg";
  const std::vector<std::string> lines = linesOf(lkapp::wrapped(status, 90));
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0], "cut lines: 1: 70.4 mm, 2: 74.7 mm | 1-2: 49.0 mm apart, 33.4 deg |");
  EXPECT_EQ(lines[1], "  1-3: 29.9 mm apart, 16.7 deg | 1-4: 44.8 mm apart, 85.3 deg");
}

TEST(WrappedText, APartLongerThanALineIsBrokenAtItsSpaces)
{
  const std::string text = "view | a part of many words that is longer than any line may be | end";
  const std::vector<std::string> lines = linesOf(lkapp::wrapped(text, 24));
  ASSERT_GE(lines.size(), 3u);
  for (const std::string& line : lines)
    EXPECT_LE(line.size(), 24u + 2u) << line; // a broken line's " |" may stand past the width
  EXPECT_EQ(lines.front(), "view | a part of many");
  EXPECT_EQ(lines[lines.size() - 2], "  than any line may be |");
  EXPECT_EQ(lines.back(), "  end");
  // Every word is kept, in order.
  std::string words;
  for (const std::string& line : lines)
    words += line + " ";
  std::istringstream in(words), original(text);
  for (std::string a, b; original >> a;)
  {
    ASSERT_TRUE(static_cast<bool>(in >> b));
    EXPECT_EQ(a, b);
  }
}

TEST(WrappedText, CountsCharactersNotBytesAndKeepsShortLinesAndLongWords)
{
  // Ten Cyrillic letters are twenty bytes: they fit a line of 12.
  const std::string name = "\xd0\x9f\xd1\x80\xd0\xb0\xd0\xb2\xd0\xb0\xd1\x8f\xd1\x87\xd0\xb0\xd1\x81\xd1\x82\xd1\x8c";
  EXPECT_EQ(lkapp::wrapped(name.substr(0, 20), 12), name.substr(0, 20));
  EXPECT_EQ(lkapp::wrapped("short | lines\nstay", 40), "short | lines\nstay");
  EXPECT_EQ(lkapp::wrapped("averyveryverylongword x", 5), "averyveryverylongword\n  x");
  EXPECT_EQ(lkapp::wrapped("", 10), "");
}
