// Typed reads of the JSON files the apps take (the demo's plan, the planner's
// sessions): a field of the wrong kind (a string where a number belongs, a
// number too large for a count) is refused with a message that names it,
// instead of the exception jsoncpp's as...() throws, which ended the program.
#ifndef latticekit_apps_JsonFields_h
#define latticekit_apps_JsonFields_h

#include "AppSupport.h"  // specialFileKind
#include "ScanOnPlane.h" // HeadAndFront

#include <vtk_jsoncpp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <initializer_list>
#include <limits>
#include <string>

namespace lkapp
{
/// The members of `object` not named in `known` (a misspelt field, or one a
/// newer version writes), quoted and comma-separated; "" if none (or if
/// `object` is no object). Readers ignore them and say so.
inline std::string unknownMembers(const Json::Value& object, std::initializer_list<const char*> known)
{
  std::string names;
  if (!object.isObject())
    return names;
  for (const std::string& name : object.getMemberNames())
    if (std::none_of(known.begin(), known.end(), [&](const char* k) { return name == k; }))
      names += (names.empty() ? "\"" : ", \"") + name + "\"";
  return names;
}

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

/// Where a patient's head and face point, {"head": [x, y, z], "front": [x,
/// y, z]}: both non-zero and not parallel (isValid); `out` is kept if not.
inline bool jsonHeadAndFront(const Json::Value& v, HeadAndFront& out)
{
  HeadAndFront read;
  if (!v.isObject() || !jsonNumbers(v["head"], read.head) || !jsonNumbers(v["front"], read.front) || !isValid(read))
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
/// Reads the JSON object in `path` (a `what`: "plan", "session") and hands it
/// to `read(root, error)`. Every way it can fail is a message: the file
/// missing, not JSON, not an object, or a field of a kind `read` did not check
/// (jsoncpp throws then, and that ended the program).
template <typename Read>
bool loadJsonObject(const std::string& path, const std::string& what, Read read, std::string& error)
{
  // A device (/dev/zero) never ends: jsoncpp would read it until memory
  // runs out. A pipe (bash's <(...)) is read as it comes.
  if (specialFileKind(path) == "device")
  {
    error = "cannot read the " + what + " '" + path + "': it is a device, not a file";
    return false;
  }
  std::ifstream in(path);
  if (!in)
  {
    error = "cannot open the " + what + " '" + path + "'";
    return false;
  }
  Json::Value root;
  Json::CharReaderBuilder builder;
  std::string errs;
  if (!Json::parseFromStream(builder, in, &root, &errs) || !root.isObject())
  {
    error = "'" + path + "' is not a " + what + " (JSON object): " + errs;
    return false;
  }
  try
  {
    return read(root, error);
  }
  catch (const Json::Exception& e)
  {
    error = "'" + path + "' is not a valid " + what + ": " + e.what();
    return false;
  }
}

} // namespace lkapp

#endif
