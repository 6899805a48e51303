#include "common/WrappedText.h"

#include <vtkRenderer.h>
#include <vtkTextActor.h>

#include <algorithm>
#include <sstream>
#include <vector>

namespace lkapp
{

std::string wrapped(const std::string& text, std::size_t width)
{
  // Widths count characters, not UTF-8 bytes (a Cyrillic letter takes two).
  const auto length = [](const std::string& t) {
    return static_cast<std::size_t>(
      std::count_if(t.begin(), t.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
  };
  const std::string bar = " | ", indent = "  "; // continuation lines are indented
  std::string out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);)
  {
    std::vector<std::string> parts;
    for (std::size_t from = 0;;)
    {
      const std::size_t at = line.find(bar, from);
      parts.push_back(line.substr(from, at == std::string::npos ? std::string::npos : at - from));
      if (at == std::string::npos)
        break;
      from = at + bar.size();
    }
    std::string current;
    const auto breakLine = [&](const std::string& ending) {
      out += current + ending + "\n";
      current = indent;
    };
    for (const std::string& part : parts)
    {
      const bool fresh = current.empty() || current == indent;
      if (fresh ? length(current) + length(part) <= width : length(current) + bar.size() + length(part) <= width)
      {
        current += (fresh ? "" : bar) + part;
        continue;
      }
      if (!fresh && indent.size() + length(part) <= width)
      {
        breakLine(" |");
        current += part;
        continue;
      }
      // A part longer than a line: it goes on after the bar, broken at its
      // spaces.
      if (!fresh)
        current += " |";
      std::istringstream words(part);
      for (std::string word; words >> word;)
      {
        if (current.empty() || current == indent)
          current += word;
        else if (length(current) + 1 + length(word) > width)
        {
          breakLine("");
          current += word;
        }
        else
          current += " " + word;
      }
    }
    out += current + "\n";
  }
  if (!out.empty())
    out.pop_back();
  return out;
}

std::array<double, 2> textSize(vtkRenderer* renderer, vtkTextActor* text)
{
  std::array<double, 2> size{ 0.0, 0.0 };
  if (renderer->GetRenderWindow() && text->GetInput() && *text->GetInput())
    text->GetSize(renderer, size.data());
  return size;
}

} // namespace lkapp
