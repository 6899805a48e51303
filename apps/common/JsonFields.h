// Typed reads of the JSON files the apps take (the demo's plan, the planner's
// sessions): a field of the wrong kind (a string where a number belongs, a
// number too large for a count) is refused with a message that names it,
// instead of the exception jsoncpp's as...() throws, which ended the program.
#ifndef latticekit_apps_JsonFields_h
#define latticekit_apps_JsonFields_h

#include <vtk_jsoncpp.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

namespace lkapp
{
/// A finite number.
inline bool jsonNumber(const Json::Value& v, double& out)
{
  if (!v.isNumeric() || !std::isfinite(v.asDouble()))
    return false;
  out = v.asDouble();
  return true;
}

/// A whole number in [lowest, highest] (1500 or 1500.0, not 1500.5 or 1e30).
inline bool jsonInteger(const Json::Value& v, long long lowest, long long highest, long long& out)
{
  double d = 0.0;
  if (!jsonNumber(v, d) || d != std::floor(d) || d < static_cast<double>(lowest) || d > static_cast<double>(highest))
    return false;
  out = static_cast<long long>(d);
  return true;
}

inline bool jsonBool(const Json::Value& v, bool& out)
{
  if (!v.isBool())
    return false;
  out = v.asBool();
  return true;
}

inline bool jsonString(const Json::Value& v, std::string& out)
{
  if (!v.isString())
    return false;
  out = v.asString();
  return true;
}

/// N finite numbers in an array.
template <std::size_t N>
bool jsonNumbers(const Json::Value& v, std::array<double, N>& out)
{
  if (!v.isArray() || v.size() != N)
    return false;
  std::array<double, N> read{};
  for (Json::ArrayIndex i = 0; i < N; ++i)
    if (!jsonNumber(v[i], read[i]))
      return false;
  out = read;
  return true;
}

/// An optional member of an object: absent (or null) keeps `out` and is
/// fine; present, it must read, or `error` says "`where`: "`key`" must be
/// `kind`".
template <typename Read, typename T>
bool jsonMember(const Json::Value& object, const char* key, T& out, Read read, const std::string& where,
  const std::string& kind, std::string& error)
{
  if (!object.isObject() || !object.isMember(key) || object[key].isNull())
    return true;
  if (read(object[key], out))
    return true;
  error = where + ": \"" + key + "\" must be " + kind;
  return false;
}
} // namespace lkapp

#endif
