// UTF-8 text: names that go into DICOM (ROI names, a piece's name in the
// planner) and come out of it are UTF-8 in latticekit, whatever character set
// a file spells them in. Decoding checks them; encoding turns a Latin-1 key
// (what X gives for a typed letter) into UTF-8.
#ifndef vtkLKText_h
#define vtkLKText_h

#include <string>
#include <vector>

namespace lkvtk
{
/// DICOM's longest values of the text kinds a name takes: an LO (Long
/// String, such as ROIName) holds 64 characters, an SH (Short String, such
/// as StructureSetLabel) 16.
constexpr std::size_t kDICOMLongStringLength = 64;
constexpr std::size_t kDICOMShortStringLength = 16;

/// Whether `code` is a Unicode scalar value, which UTF-8 can carry: up to
/// U+10FFFF and no surrogate.
inline bool isScalarValue(char32_t code)
{
  return code <= 0x10FFFF && (code < 0xD800 || code > 0xDFFF);
}

/// The code points of `text`, appended to `points` when it is given. False
/// where `text` is not well-formed UTF-8 (a stray or missing continuation
/// byte, an overlong form, a surrogate, beyond U+10FFFF).
inline bool decodeUTF8(const std::string& text, std::vector<char32_t>* points = nullptr)
{
  static const char32_t least[] = { 0, 0, 0x80, 0x800, 0x10000 };
  for (std::size_t i = 0; i < text.size();)
  {
    const unsigned char c = static_cast<unsigned char>(text[i]);
    const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    if (n == 0 || i + n > text.size())
      return false;
    char32_t code = n == 1 ? c : c & (0x7Fu >> n);
    for (std::size_t k = 1; k < n; ++k)
    {
      const unsigned char t = static_cast<unsigned char>(text[i + k]);
      if ((t >> 6) != 0x2)
        return false;
      code = (code << 6) | (t & 0x3Fu);
    }
    if (code < least[n] || !isScalarValue(code))
      return false;
    if (points)
      points->push_back(code);
    i += n;
  }
  return true;
}

/// Whether `text` is well-formed UTF-8.
inline bool isUTF8(const std::string& text)
{
  return decodeUTF8(text);
}

/// The UTF-8 bytes of one code point (up to U+10FFFF).
inline std::string encodeUTF8(char32_t code)
{
  std::string out;
  if (code < 0x80)
    out += static_cast<char>(code);
  else if (code < 0x800)
  {
    out += static_cast<char>(0xC0 | (code >> 6));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
  else if (code < 0x10000)
  {
    out += static_cast<char>(0xE0 | (code >> 12));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
  else
  {
    out += static_cast<char>(0xF0 | (code >> 18));
    out += static_cast<char>(0x80 | ((code >> 12) & 0x3F));
    out += static_cast<char>(0x80 | ((code >> 6) & 0x3F));
    out += static_cast<char>(0x80 | (code & 0x3F));
  }
  return out;
}

/// Whether a code point is a control character: C0 (below U+0020), DEL and
/// C1 (U+0080 to U+009F). DICOM's names hold none, and a terminal that
/// printed one would act on it.
inline bool isControl(char32_t code)
{
  return code < 0x20 || (code >= 0x7F && code <= 0x9F);
}
/// `text` as a message shows it: a control character as '?' (a terminal
/// that printed one would act on it), cut after `most` characters, or where
/// it stops being UTF-8, with "..." then.
inline std::string shownText(const std::string& text, std::size_t most)
{
  std::vector<char32_t> characters;
  const bool whole = decodeUTF8(text, &characters);
  std::string out;
  for (std::size_t i = 0; i < characters.size() && i < most; ++i)
    out += isControl(characters[i]) ? std::string("?") : encodeUTF8(characters[i]);
  return whole && characters.size() <= most ? out : out + "...";
}

/// Why `text` cannot be a DICOM name of at most `most` characters
/// (kDICOMLongStringLength, kDICOMShortStringLength): not UTF-8,
/// a control character, a backslash (DICOM's value separator), too long.
/// Empty when it can.
inline std::string dicomTextProblem(const std::string& text, std::size_t most)
{
  std::vector<char32_t> characters;
  if (!decodeUTF8(text, &characters))
    return "is not UTF-8 text";
  for (const char32_t c : characters)
    if (isControl(c))
      return "holds a control character";
  if (text.find('\\') != std::string::npos)
    return "holds a backslash, which DICOM reads as a separator of values";
  if (characters.size() > most)
    return "is longer than " + std::to_string(most) + " characters";
  return std::string();
}

/// `text` made a DICOM name of at most `most` characters, for a name taken
/// from elsewhere (a segmentation's segment): bytes that are not UTF-8 read
/// as Latin-1, control characters dropped, a backslash written as '/', the
/// rest cut off, spaces at the ends trimmed.
inline std::string fittedDicomText(const std::string& text, std::size_t most)
{
  std::vector<char32_t> characters;
  if (!decodeUTF8(text, &characters))
  {
    characters.clear();
    for (const char c : text)
      characters.push_back(static_cast<unsigned char>(c));
  }
  std::string out;
  std::size_t kept = 0;
  for (const char32_t c : characters)
  {
    if (isControl(c) || (kept == 0 && c == ' '))
      continue;
    if (kept++ == most)
      break;
    out += c == '\\' ? std::string("/") : encodeUTF8(c);
  }
  while (!out.empty() && out.back() == ' ')
    out.pop_back();
  return out;
}
} // namespace lkvtk

#endif
