#include "MeshFileCheck.h"

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace lkapp
{
namespace
{
/// Bytes of a PLY scalar type, 0 for a name that is none.
std::size_t typeSize(const std::string& type)
{
  if (type == "char" || type == "uchar" || type == "int8" || type == "uint8")
    return 1;
  if (type == "short" || type == "ushort" || type == "int16" || type == "uint16")
    return 2;
  if (type == "int" || type == "uint" || type == "int32" || type == "uint32" || type == "float" || type == "float32")
    return 4;
  if (type == "double" || type == "float64")
    return 8;
  return 0;
}

bool signedType(const std::string& type)
{
  return type == "char" || type == "int8" || type == "short" || type == "int16" || type == "int" || type == "int32";
}

struct Property
{
  std::size_t size = 0;      ///< a scalar's bytes, or a list's item bytes
  std::size_t countSize = 0; ///< a list's count bytes; 0 for a scalar
  bool countSigned = false;
};

struct Element
{
  std::string name;
  std::uint64_t count = 0;
  std::vector<Property> properties;
};

/// A list's count at `at` (`bytes` bytes, the file's byte order).
long long readCount(const unsigned char* at, const Property& p, bool bigEndian)
{
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < p.countSize; ++i)
    v |= static_cast<std::uint64_t>(at[bigEndian ? p.countSize - 1 - i : i]) << (8 * i);
  if (p.countSigned && p.countSize < 8 && (v >> (8 * p.countSize - 1)) != 0)
    return -1; // negative
  return static_cast<long long>(v);
}

std::string where(const Element& e, std::uint64_t i)
{
  return "it ends in " + e.name + " " + std::to_string(i + 1) + " of " + std::to_string(e.count) +
    ": the file is truncated";
}
} // namespace

std::string plyFileProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return "it cannot be opened";
  std::string line;
  if (!std::getline(in, line) || line.substr(0, 3) != "ply")
    return "it does not start with \"ply\"";
  std::string format;
  std::vector<Element> elements;
  bool ended = false;
  while (std::getline(in, line))
  {
    if (!line.empty() && line.back() == '\r')
      line.pop_back();
    std::istringstream words(line);
    std::string key;
    words >> key;
    if (key == "end_header")
    {
      ended = true;
      break;
    }
    if (key == "format")
      words >> format;
    else if (key == "element")
    {
      Element e;
      std::string count;
      words >> e.name >> count;
      if (count.empty() || count.find_first_not_of("0123456789") != std::string::npos || count.size() > 18)
        return "its header gives element " + e.name + " the count '" + count + "'";
      e.count = std::stoull(count);
      elements.push_back(e);
    }
    else if (key == "property")
    {
      if (elements.empty())
        return "its header has a property before any element";
      std::string type;
      words >> type;
      Property p;
      if (type == "list")
      {
        std::string countType, itemType;
        words >> countType >> itemType;
        p.countSize = typeSize(countType);
        p.countSigned = signedType(countType);
        p.size = typeSize(itemType);
        if (p.countSize == 0 || p.size == 0)
          return "its header has a list of unknown type '" + countType + " " + itemType + "'";
      }
      else if ((p.size = typeSize(type)) == 0)
        return "its header has a property of unknown type '" + type + "'";
      elements.back().properties.push_back(p);
    }
  }
  if (!ended)
    return "its header has no end_header line";
  const std::string body((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (format == "ascii")
  {
    // vtkPLY reads an ASCII element from one line: every line must hold its
    // properties' words.
    std::istringstream lines(body);
    // A short last line is where the file was cut; a short line inside is
    // corrupt.
    auto shortLine = [&](const Element& e, std::uint64_t i) {
      return lines.peek() == std::char_traits<char>::eof()
        ? where(e, i)
        : e.name + " " + std::to_string(i + 1) + " of " + std::to_string(e.count) +
          " has fewer values than the header declares";
    };
    for (const Element& e : elements)
      for (std::uint64_t i = 0; i < e.count; ++i)
      {
        if (!std::getline(lines, line))
          return where(e, i);
        std::istringstream words(line);
        for (const Property& p : e.properties)
        {
          std::string word;
          if (!(words >> word))
            return shortLine(e, i);
          if (p.countSize == 0)
            continue;
          char* end = nullptr;
          const long long n = std::strtoll(word.c_str(), &end, 10);
          if (*end != '\0' || n < 0)
            return e.name + " " + std::to_string(i + 1) + " has the list length '" + word + "'";
          for (long long k = 0; k < n; ++k)
            if (!(words >> word))
              return shortLine(e, i);
        }
      }
    return {};
  }
  if (format != "binary_little_endian" && format != "binary_big_endian")
    return "its header gives the unknown format '" + format + "'";
  const bool bigEndian = format == "binary_big_endian";
  const auto* data = reinterpret_cast<const unsigned char*>(body.data());
  const std::size_t size = body.size();
  std::size_t at = 0;
  for (const Element& e : elements)
  {
    bool lists = false;
    std::size_t fixed = 0;
    for (const Property& p : e.properties)
    {
      lists = lists || p.countSize > 0;
      fixed += p.size;
    }
    if (!lists)
    {
      // Every instance the same size: one comparison (a header count
      // beyond the file's size is caught here, before any allocation).
      if (fixed > 0 && e.count > (size - at) / fixed)
        return where(e, (size - at) / fixed);
      at += static_cast<std::size_t>(e.count) * fixed;
      continue;
    }
    for (std::uint64_t i = 0; i < e.count; ++i)
      for (const Property& p : e.properties)
      {
        if (p.countSize == 0)
        {
          if (size - at < p.size)
            return where(e, i);
          at += p.size;
          continue;
        }
        if (size - at < p.countSize)
          return where(e, i);
        const long long n = readCount(data + at, p, bigEndian);
        at += p.countSize;
        if (n < 0)
          return e.name + " " + std::to_string(i + 1) + " has a negative list length";
        if (static_cast<unsigned long long>(n) > (size - at) / p.size)
          return where(e, i);
        at += static_cast<std::size_t>(n) * p.size;
      }
  }
  return {};
}

std::string stlFileProblem(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
    return "it cannot be opened";
  char start[512];
  in.read(start, sizeof(start));
  const std::streamsize got = in.gcount();
  if (std::memchr(start, '\0', static_cast<std::size_t>(got)) == nullptr)
    return {}; // ASCII (a binary file has NUL bytes in its header or its triangles)
  in.clear();
  in.seekg(0, std::ios::end);
  const auto size = static_cast<unsigned long long>(in.tellg());
  if (size < 84)
    return "it has " + std::to_string(size) + " bytes, fewer than a binary STL header's 84";
  const auto* b = reinterpret_cast<const unsigned char*>(start);
  const unsigned long long triangles = static_cast<unsigned long long>(b[80]) | (static_cast<unsigned long long>(b[81]) << 8) |
    (static_cast<unsigned long long>(b[82]) << 16) | (static_cast<unsigned long long>(b[83]) << 24);
  const unsigned long long needed = 84 + 50 * triangles;
  if (size < needed)
    return "it declares " + std::to_string(triangles) + " triangles (" + std::to_string(needed) + " bytes) but has " +
      std::to_string(size) + " bytes: the file is truncated";
  return {};
}

} // namespace lkapp
