#include "common/TextFont.h"

#include "vtkLKText.h"

#include <vtkFreeTypeTools.h>
#include <vtkTextProperty.h>
#include <vtk_freetype.h>
#include FT_FREETYPE_H

#include <fontconfig/fontconfig.h>

#include <algorithm>
#include <map>
#include <tuple>
#include <vector>

namespace lkapp
{
namespace
{

/// Whether VTK's compiled font for `property` (family, bold, italic) has a
/// glyph for `c`. The faces stay open for the program's life, one each.
bool compiledFontHas(vtkTextProperty* property, char32_t c)
{
  static FT_Library library = nullptr;
  static bool tried = false;
  if (!tried)
  {
    tried = true;
    if (FT_Init_FreeType(&library) != 0)
      library = nullptr;
  }
  if (library == nullptr)
    return c < 0x80;
  static std::map<std::tuple<int, int, int>, FT_Face> faces;
  const auto key = std::make_tuple(property->GetFontFamily(), property->GetBold(), property->GetItalic());
  auto found = faces.find(key);
  if (found == faces.end())
  {
    FT_Face face = nullptr;
    if (!vtkFreeTypeTools::LookupFace(property, library, &face))
      face = nullptr;
    found = faces.emplace(key, face).first;
  }
  return found->second != nullptr ? FT_Get_Char_Index(found->second, c) != 0 : c < 0x80;
}

struct InstalledFont
{
  std::string file;           // empty when fontconfig found none
  std::vector<char32_t> lacks; // the characters it has no glyph for
};

/// The installed sans-serif font fontconfig picks for `characters` (its
/// match ranks covering the characters above the family), kept per
/// character set and style.
const InstalledFont& installedFontFor(const std::vector<char32_t>& characters, bool bold, bool italic)
{
  static std::map<std::tuple<std::vector<char32_t>, bool, bool>, InstalledFont> kept;
  const auto key = std::make_tuple(characters, bold, italic);
  if (const auto found = kept.find(key); found != kept.end())
    return found->second;
  InstalledFont font;
  static FcConfig* config = FcInitLoadConfigAndFonts();
  FcPattern* pattern = config != nullptr ? FcPatternCreate() : nullptr;
  FcCharSet* wanted = FcCharSetCreate();
  if (pattern != nullptr && wanted != nullptr)
  {
    for (const char32_t c : characters)
      FcCharSetAddChar(wanted, c);
    FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>("sans-serif"));
    FcPatternAddCharSet(pattern, FC_CHARSET, wanted);
    FcPatternAddInteger(pattern, FC_WEIGHT, bold ? FC_WEIGHT_BOLD : FC_WEIGHT_REGULAR);
    FcPatternAddInteger(pattern, FC_SLANT, italic ? FC_SLANT_ITALIC : FC_SLANT_ROMAN);
    FcConfigSubstitute(config, pattern, FcMatchPattern);
    FcDefaultSubstitute(pattern);
    FcResult result = FcResultNoMatch;
    if (FcPattern* match = FcFontMatch(config, pattern, &result))
    {
      FcChar8* file = nullptr;
      FcCharSet* has = nullptr;
      if (FcPatternGetString(match, FC_FILE, 0, &file) == FcResultMatch && file != nullptr)
        font.file = reinterpret_cast<const char*>(file);
      const bool known = FcPatternGetCharSet(match, FC_CHARSET, 0, &has) == FcResultMatch;
      for (const char32_t c : characters)
        if (font.file.empty() || !known || !FcCharSetHasChar(has, c))
          font.lacks.push_back(c);
      FcPatternDestroy(match);
    }
  }
  if (font.file.empty())
    font.lacks = characters;
  if (wanted != nullptr)
    FcCharSetDestroy(wanted);
  if (pattern != nullptr)
    FcPatternDestroy(pattern);
  return kept.emplace(key, font).first->second;
}

}

std::string useFontFor(vtkTextProperty* property, const std::string& text)
{
  if (property->GetFontFamily() == VTK_FONT_FILE)
    property->SetFontFamily(VTK_ARIAL);
  // The distinct characters beyond ASCII that draw: every font has ASCII,
  // so the lookups (kept, and a status line's changing digits would
  // otherwise multiply them) go by the rest.
  std::vector<char32_t> characters;
  lkvtk::decodeUTF8(text, &characters);
  characters.erase(std::remove_if(characters.begin(), characters.end(),
                     [](char32_t c) { return c < 0x80 || lkvtk::isControl(c); }),
    characters.end());
  std::sort(characters.begin(), characters.end());
  characters.erase(std::unique(characters.begin(), characters.end()), characters.end());
  std::vector<char32_t> lacking;
  for (const char32_t c : characters)
    if (!compiledFontHas(property, c))
      lacking.push_back(c);
  if (lacking.empty())
    return std::string();
  const InstalledFont& font = installedFontFor(characters, property->GetBold() != 0, property->GetItalic() != 0);
  std::vector<char32_t> left = lacking;
  if (!font.file.empty() && font.lacks.size() < lacking.size())
  {
    property->SetFontFamily(VTK_FONT_FILE);
    property->SetFontFile(font.file.c_str());
    left = font.lacks;
  }
  std::string out;
  for (const char32_t c : left)
    out += lkvtk::encodeUTF8(c);
  return out;
}

}
