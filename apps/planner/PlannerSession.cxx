#include "planner/PlannerSession.h"

#include "common/AppSupport.h"
#include "common/AtomicFile.h"
#include "common/JsonFields.h"
#include "common/ScanPicture.h"
#include "vtkLKText.h"

#include <vtkMath.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>
#include <sstream>

namespace lkplanner
{
Json::Value triple(const std::array<double, 3>& v)
{
  Json::Value j(Json::arrayValue);
  for (double c : v)
    j.append(c);
  return j;
}

std::string strokeKey(const Stroke& st)
{
  std::ostringstream os;
  os.precision(17);
  os << st.mode << ":";
  for (const auto& p : st.points)
    os << p[0] << "," << p[1] << "," << p[2] << ";";
  if (st.saw)
    os << "saw" << st.sawOrigin[0] << "," << st.sawOrigin[1] << "," << st.sawOrigin[2] << "," << st.sawNormal[0]
       << "," << st.sawNormal[1] << "," << st.sawNormal[2];
  return os.str();
}

std::string cutKey(const Session& s)
{
  std::string key;
  for (const Stroke& st : s.strokes)
    key += strokeKey(st) + "|";
  return key + std::to_string(s.cut) + std::to_string(s.capping);
}

double bumpFalloff(double radius)
{
  return std::log(100.0) / (radius * radius);
}

const char* modeName(int mode)
{
  switch (mode)
  {
    case vtkLKStrokeFeatureLineFilter::PAINT:
      return "paint";
    case vtkLKStrokeFeatureLineFilter::SNAP:
      return "snap";
    case vtkLKStrokeFeatureLineFilter::SPLIT:
      return "split";
    default:
      return "nearest";
  }
}

int modeOf(const std::string& name)
{
  if (name == "paint")
    return vtkLKStrokeFeatureLineFilter::PAINT;
  if (name == "snap")
    return vtkLKStrokeFeatureLineFilter::SNAP;
  if (name == "split")
    return vtkLKStrokeFeatureLineFilter::SPLIT;
  return vtkLKStrokeFeatureLineFilter::NEAREST_EDGES;
}

std::string sessionText(const Session& s)
{
  Json::Value root;
  for (const Stroke& st : s.strokes)
  {
    Json::Value js;
    js["mode"] = modeName(st.mode);
    for (const auto& p : st.points)
    {
      Json::Value jp(Json::arrayValue);
      for (double c : p)
        jp.append(c);
      js["points"].append(jp);
    }
    if (st.saw)
    {
      js["saw"]["origin"] = triple(st.sawOrigin);
      js["saw"]["normal"] = triple(st.sawNormal);
      if (st.guideOtherSide)
        js["guideOtherSide"] = true;
    }
    root["strokes"].append(js);
  }
  root["cut"] = s.cut;
  root["capping"] = s.capping;
  root["lattice"] = s.lattice;
  root["latticeVertices"] = static_cast<Json::Int64>(s.latticeVertices);
  root["metro"] = s.metro;
  root["mirror"] = s.mirror;
  if (s.guides)
    root["guides"] = true;
  if (s.guidesOtherSide)
    root["guidesOtherSide"] = true;
  if (s.guidesJoined)
    root["guidesJoined"] = true;
  if (s.scanOnLine > 0)
    root["scanOnLine"] = s.scanOnLine;
  if (s.scanAcross)
    root["scanAcross"] = true;
  if (s.softTissueWindow)
    root["scanWindow"] = "soft tissue";
  if (s.scanWindowWidth > 0.0)
  {
    root["scanWindowLevel"].append(s.scanWindowWidth);
    root["scanWindowLevel"].append(s.scanWindowLevel);
  }
  if (s.scanOffset != 0.0)
    root["scanOffset"] = s.scanOffset;
  if (s.patientGiven)
  {
    root["patient"]["head"] = triple(s.patient.head);
    root["patient"]["front"] = triple(s.patient.front);
  }
  for (const auto& p : s.mirrorPlane)
    root["mirrorPlane"].append(triple(p));
  if (s.segment >= 0)
  {
    root["segment"]["piece"] = s.segment;
    for (double v : s.segmentMatrix)
      root["segment"]["matrix"].append(v);
    if (s.segmentAnchored)
      root["segment"]["at"] = triple(s.segmentAnchor);
  }
  for (const Deformation& d : s.deformations)
  {
    Json::Value jd;
    jd["tool"] = d.tool;
    jd["piece"] = d.piece;
    jd["centre"] = triple(d.centre);
    jd["radius"] = d.radius;
    if (d.tool == "smooth")
    {
      jd["iterations"] = d.iterations;
      if (d.stroke > 0)
        jd["stroke"] = d.stroke;
    }
    else
    {
      jd["normal"] = triple(d.normal);
      jd["amount"] = d.amount;
    }
    if (d.tool == "bump")
      jd["falloff"] = d.falloff;
    root["deformations"].append(jd);
  }
  for (const PieceName& n : s.names)
  {
    Json::Value jn;
    jn["name"] = n.name;
    jn["at"] = triple(n.at);
    root["names"].append(jn);
  }
  for (const Measurement& m : s.measurements)
  {
    Json::Value jm;
    jm["from"] = triple(m.from);
    jm["to"] = triple(m.to);
    if (m.angle)
      jm["at"] = triple(m.at);
    // (Ends not resolved yet are left for the replay to resolve.)
    const auto ends = m.points().size();
    if (std::all_of(m.pieces.begin(), m.pieces.begin() + static_cast<long>(ends),
          [](int p) { return p != Measurement::kUnresolved; }))
      for (std::size_t k = 0; k < ends; ++k)
        jm["pieces"].append(m.pieces[k]);
    root["measurements"].append(jm);
  }
  if (s.surface.given)
  {
    root["surface"]["iso"] = s.surface.iso;
    if (s.surface.seeded)
      root["surface"]["seed"] = triple(s.surface.seed);
    if (s.surface.cropped)
      for (double v : s.surface.crop)
        root["surface"]["crop"].append(v);
    if (s.surface.closed)
      root["surface"]["close"] = true;
    if (s.surface.series >= 0)
      root["surface"]["series"] = static_cast<Json::Int64>(s.surface.series);
    if (s.surface.smoothing >= 0)
      root["surface"]["smooth"] = static_cast<Json::Int64>(s.surface.smoothing);
    if (s.surface.imageSmoothing >= 0.0)
      root["surface"]["image_smooth"] = s.surface.imageSmoothing;
    if (!s.surface.labelName.empty())
      root["surface"]["label"] = s.surface.labelName;
    else if (s.surface.label > 0)
      root["surface"]["label"] = static_cast<Json::Int64>(s.surface.label);
  }
  if (!s.inputFile.empty())
    root["input"]["file"] = s.inputFile;
  if (s.inputBoundsKnown)
    for (double v : s.inputBounds)
      root["input"]["bounds"].append(v);
  Json::StreamWriterBuilder builder;
  builder["indentation"] = " ";
  return Json::writeString(builder, root) + "\n";
}

bool saveSession(const Session& s, const std::string& path, std::string& error)
{
  // Whole or not at all: a session saved on a full disk must not leave a
  // truncated file in place of the one saved before.
  return lkapp::writeFileAtomically(path, sessionText(s), error);
}

std::string unsavedSessionPath(const std::string& sessionPath)
{
  const lkapp::FileNameParts p = lkapp::splitFileName(sessionPath);
  return p.folder + p.stem + "-unsaved" + (p.extension.empty() ? ".json" : p.extension);
}

std::vector<std::array<double, 3>> Measurement::points() const
{
  if (angle)
    return { from, to, at };
  return { from, to };
}

double Measurement::length() const
{
  return std::hypot(to[0] - from[0], to[1] - from[1], to[2] - from[2]);
}

double Measurement::degrees() const
{
  return angleAt(from, at, to);
}

double angleAt(const std::array<double, 3>& a, const std::array<double, 3>& at, const std::array<double, 3>& b)
{
  const double u[3] = { a[0] - at[0], a[1] - at[1], a[2] - at[2] };
  const double v[3] = { b[0] - at[0], b[1] - at[1], b[2] - at[2] };
  const double lu = std::hypot(u[0], u[1], u[2]), lv = std::hypot(v[0], v[1], v[2]);
  if (!(lu > 0.0) || !(lv > 0.0))
    return std::numeric_limits<double>::quiet_NaN();
  // atan2 of the cross and dot products: exact near 0 and 180 degrees too.
  const double cross[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0] };
  const double dot = u[0] * v[0] + u[1] * v[1] + u[2] * v[2];
  return std::atan2(std::hypot(cross[0], cross[1], cross[2]), dot) * 180.0 / 3.14159265358979323846;
}

bool validPieceName(const std::string& name, std::string& why)
{
  why.clear();
  const std::string shown = lkvtk::shownText(name, kPieceNameLength);
  const std::string problem = lkvtk::dicomTextProblem(name, kPieceNameLength);
  if (name.empty())
    why = "a piece's name is empty";
  else if (!problem.empty())
    why = "the piece name '" + shown + "' " + problem;
  else if (name.front() == ' ' || name.back() == ' ')
    why = "the piece name '" + shown + "' starts or ends with a space";
  return why.empty();
}

namespace
{
/// Notes the members of `object` that are not in `known` (a misspelt field,
/// or one of a newer planner): a replay ignores them, and says so.
void noteUnknownMembers(const Json::Value& object, std::initializer_list<const char*> known, const std::string& where,
  std::string* notes)
{
  if (!notes)
    return;
  const std::string names = lkapp::unknownMembers(object, known);
  if (!names.empty())
    *notes += (notes->empty() ? "" : "\n") + where + " has fields this planner does not know, ignored: " + names;
}
} // namespace

bool planeThrough(const std::vector<std::array<double, 3>>& points, std::array<double, 3>& origin,
  std::array<double, 3>& normal, std::string& why)
{
  if (points.size() != 3)
  {
    why = "a plane needs three points";
    return false;
  }
  // The sine of each corner's angle: |e1 x e2| / (|e1| |e2|).
  double smallest = 1.0;
  for (std::size_t k = 0; k < 3; ++k)
  {
    double e1[3], e2[3], c[3];
    vtkMath::Subtract(points[(k + 1) % 3].data(), points[k].data(), e1);
    vtkMath::Subtract(points[(k + 2) % 3].data(), points[k].data(), e2);
    vtkMath::Cross(e1, e2, c);
    const double lengths = vtkMath::Norm(e1) * vtkMath::Norm(e2);
    smallest = std::min(smallest, lengths > 0.0 ? vtkMath::Norm(c) / lengths : 0.0);
  }
  double a[3], b[3], n[3];
  vtkMath::Subtract(points[1].data(), points[0].data(), a);
  vtkMath::Subtract(points[2].data(), points[0].data(), b);
  vtkMath::Cross(a, b, n);
  const double length = vtkMath::Norm(n);
  if (!std::isfinite(length) || !std::isfinite(smallest))
  {
    why = "the three points must be finite";
    return false;
  }
  if (!(smallest >= std::sin(vtkMath::RadiansFromDegrees(2.0))))
  {
    why = "the three points are nearly in a line (a corner of their triangle under 2 degrees): no plane is "
          "defined well by them";
    return false;
  }
  const double sign = n[0] < 0.0 ? -1.0 : 1.0;
  for (std::size_t i = 0; i < 3; ++i)
  {
    normal[i] = sign * n[i] / length;
    origin[i] = (points[0][i] + points[1][i] + points[2][i]) / 3.0;
  }
  return true;
}

bool readSession(
  const Json::Value& root, const std::string& path, Session& s, std::string& error, std::string* notes)
{
  using namespace lkapp;
  const std::string session = "the session '" + path + "'";
  s = Session();
  // A session saved before December 2026 does not name the smoothing (below).
  s.surface.labelMapDefaultsOfBefore = !(root["surface"].isObject() && root["surface"].isMember("image_smooth"));
  noteUnknownMembers(root,
    { "strokes", "cut", "capping", "lattice", "latticeVertices", "metro", "mirror", "guides", "guidesOtherSide", "guidesJoined", "mirrorPlane", "scanOnLine", "scanAcross", "scanWindow", "scanWindowLevel", "scanOffset", "patient", "segment",
      "deformations", "names",
      "measurements",
      "surface", "input" },
    session, notes);
  const Json::Value& strokes = root["strokes"];
  if (!strokes.isNull() && !strokes.isArray())
  {
    error = session + ": \"strokes\" must be a list";
    return false;
  }
  for (Json::ArrayIndex i = 0; strokes.isArray() && i < strokes.size(); ++i)
  {
    const Json::Value& js = strokes[i];
    const std::string where = "stroke " + std::to_string(i + 1) + " in '" + path + "'";
    std::string mode = "nearest";
    if (!js.isObject())
    {
      error = where + " is not an object ({\"mode\": ..., \"points\": [...]})";
      return false;
    }
    noteUnknownMembers(js, { "mode", "points", "saw", "guideOtherSide" }, where, notes);
    noteUnknownMembers(js["saw"], { "origin", "normal" }, "the saw line of " + where, notes);
    if (!jsonMember(js, "mode", mode, jsonString, where, "a string", error))
      return false;
    if (mode != "paint" && mode != "nearest" && mode != "snap" && mode != "split")
    {
      error = where + " has the mode '" + mode + "' (paint, nearest, snap or split)";
      return false;
    }
    Stroke st;
    st.mode = modeOf(mode);
    const Json::Value& points = js["points"];
    if (!points.isArray())
    {
      error = where + " needs \"points\": a list of [x, y, z]";
      return false;
    }
    for (const auto& jp : points)
    {
      std::array<double, 3> p{};
      if (!jsonNumbers(jp, p))
      {
        error = "a stroke point in '" + path + "' is not [x, y, z]";
        return false;
      }
      st.points.push_back(p);
    }
    if (js.isMember("saw"))
    {
      const Json::Value& saw = js["saw"];
      if (!saw.isObject() || !jsonNumbers(saw["origin"], st.sawOrigin) || !jsonNumbers(saw["normal"], st.sawNormal) ||
        !(std::hypot(st.sawNormal[0], st.sawNormal[1], st.sawNormal[2]) > 0.0))
      {
        error = where + ": \"saw\" must be {\"origin\": [x, y, z], \"normal\": [x, y, z]} with a non-zero normal";
        return false;
      }
      if (st.mode != vtkLKStrokeFeatureLineFilter::SPLIT)
      {
        error = where + " is a saw line, which cuts in split mode, but its mode is '" + mode + "'";
        return false;
      }
      st.saw = true;
    }
    if (!jsonMember(js, "guideOtherSide", st.guideOtherSide, jsonBool, where, "true or false", error))
      return false;
    if (st.guideOtherSide && !st.saw)
    {
      error = where + " has \"guideOtherSide\", but only a saw line has a cutting guide";
      return false;
    }
    s.strokes.push_back(st);
  }
  long long vertices = s.latticeVertices;
  const auto count = [](const Json::Value& v, long long& out) {
    return jsonInteger(v, kFewestLatticeVertices, kMostLatticeVertices, out);
  };
  if (!jsonMember(root, "cut", s.cut, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "capping", s.capping, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "lattice", s.lattice, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "metro", s.metro, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "mirror", s.mirror, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "guides", s.guides, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "guidesOtherSide", s.guidesOtherSide, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "guidesJoined", s.guidesJoined, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "scanAcross", s.scanAcross, jsonBool, session, "true or false", error) ||
    !jsonMember(root, "latticeVertices", vertices, count, session, kLatticeVerticesRange, error))
    return false;
  s.latticeVertices = static_cast<long>(vertices);
  long long scanLine = 0;
  if (!jsonMember(
        root, "scanOnLine", scanLine, [](const Json::Value& v, long long& out) { return jsonInteger(v, 0, 1000000, out); },
        session, "a cut line's number (0: none)", error))
    return false;
  s.scanOnLine = static_cast<int>(scanLine);
  std::string window = "bone";
  if (!jsonMember(root, "scanWindow", window, jsonString, session, "\"bone\" or \"soft tissue\"", error))
    return false;
  if (window != "bone" && window != "soft tissue")
  {
    error = session + ": \"scanWindow\" is '" + window + "' (\"bone\" or \"soft tissue\")";
    return false;
  }
  s.softTissueWindow = window == "soft tissue";
  if (root.isMember("scanWindowLevel") && !root["scanWindowLevel"].isNull())
  {
    std::array<double, 2> wl{ 0, 0 };
    if (!jsonNumbers(root["scanWindowLevel"], wl) || !(wl[0] > 0.0) || wl[0] > lkapp::kLargestHandWindow ||
      std::abs(wl[1]) > lkapp::kLargestHandWindow)
    {
      error = session + ": \"scanWindowLevel\" must be [width, level]: a width above 0 and both at most 100,000";
      return false;
    }
    s.scanWindowWidth = wl[0];
    s.scanWindowLevel = wl[1];
  }
  if (root.isMember("patient") && !root["patient"].isNull())
  {
    if (!lkapp::jsonHeadAndFront(root["patient"], s.patient))
    {
      error = session + ": \"patient\" must be {\"head\": [x, y, z], \"front\": [x, y, z]}, non-zero and not parallel";
      return false;
    }
    s.patientGiven = true;
  }
  if (!jsonMember(
        root, "scanOffset", s.scanOffset,
        [](const Json::Value& v, double& out) { return jsonNumber(v, out) && std::abs(out) <= 200.0; }, session,
        "a number of mm from -200 to 200", error))
    return false;
  if (root.isMember("mirrorPlane"))
  {
    const Json::Value& plane = root["mirrorPlane"];
    const std::string where = session + ": \"mirrorPlane\"";
    if (!plane.isArray() || plane.size() != 3)
    {
      error = where + " must be three points [[x, y, z], [x, y, z], [x, y, z]]";
      return false;
    }
    s.mirrorPlane.resize(3);
    for (Json::ArrayIndex k = 0; k < 3; ++k)
      if (!jsonNumbers(plane[k], s.mirrorPlane[k]))
      {
        error = where + " must be three points [[x, y, z], [x, y, z], [x, y, z]] of finite numbers";
        return false;
      }
    std::array<double, 3> origin, normal;
    std::string why;
    if (!planeThrough(s.mirrorPlane, origin, normal, why))
    {
      error = where + ": " + why;
      return false;
    }
  }
  if (root.isMember("segment"))
  {
    const Json::Value& seg = root["segment"];
    noteUnknownMembers(seg, { "piece", "matrix", "at" }, "the segment in '" + path + "'", notes);
    long long piece = -1;
    std::array<double, 16> m{};
    if (!seg.isObject() || !jsonInteger(seg["piece"], 0, std::numeric_limits<int>::max(), piece) ||
      !jsonNumbers(seg["matrix"], m))
    {
      error = "the segment in '" + path + "' needs a piece index and a 16-number matrix";
      return false;
    }
    s.segment = static_cast<int>(piece);
    s.segmentMatrix = m;
    if (seg.isMember("at"))
    {
      if (!jsonNumbers(seg["at"], s.segmentAnchor))
      {
        error = "the segment in '" + path + "': \"at\" must be [x, y, z]";
        return false;
      }
      s.segmentAnchored = true;
    }
  }
  const Json::Value& deformations = root["deformations"];
  if (!deformations.isNull() && !deformations.isArray())
  {
    error = session + ": \"deformations\" must be a list";
    return false;
  }
  for (Json::ArrayIndex i = 0; deformations.isArray() && i < deformations.size(); ++i)
  {
    const Json::Value& jd = deformations[i];
    Deformation d;
    const std::string where = "deformation " + std::to_string(s.deformations.size()) + " in '" + path + "'";
    noteUnknownMembers(
      jd, { "tool", "piece", "centre", "radius", "normal", "amount", "falloff", "iterations", "stroke" }, where, notes);
    if (!jd.isObject() || !jsonString(jd["tool"], d.tool) || (d.tool != "bump" && d.tool != "box" && d.tool != "smooth"))
    {
      error = where + " has the tool '" + (jd.isObject() && jd["tool"].isString() ? jd["tool"].asString() : std::string("?")) +
        "' (bump, box or smooth)";
      return false;
    }
    long long piece = -1;
    if (!jsonInteger(jd["piece"], 0, std::numeric_limits<int>::max(), piece) || !jsonNumbers(jd["centre"], d.centre) ||
      !jsonNumber(jd["radius"], d.radius) || !(d.radius > 0.0))
    {
      error = where + " needs a piece index, a centre [x, y, z] and a radius above 0";
      return false;
    }
    d.piece = static_cast<int>(piece);
    if (d.tool == "smooth")
    {
      long long iterations = d.iterations;
      const auto upTo100 = [](const Json::Value& v, long long& out) { return jsonInteger(v, 1, 100, out); };
      if (!jsonMember(jd, "iterations", iterations, upTo100, where, "1 to 100", error))
      {
        error = where + " needs 1 to 100 smoothing iterations";
        return false;
      }
      d.iterations = static_cast<int>(iterations);
      long long stroke = 0;
      const auto strokeNumber = [](const Json::Value& v, long long& out) {
        return jsonInteger(v, 0, std::numeric_limits<int>::max(), out);
      };
      if (!jsonMember(jd, "stroke", stroke, strokeNumber, where, "a whole number, 1 or more (0: not known)", error))
        return false;
      d.stroke = static_cast<int>(stroke);
    }
    else if (!jsonNumbers(jd["normal"], d.normal) || !jsonNumber(jd["amount"], d.amount))
    {
      error = where + " needs a normal [x, y, z] and an amount";
      return false;
    }
    if (d.tool == "bump")
    {
      d.falloff = bumpFalloff(d.radius);
      if (!jsonMember(jd, "falloff", d.falloff, jsonNumber, where, "a number", error) || !(d.falloff >= 0.0))
      {
        error = where + " needs a falloff of 0 or more";
        return false;
      }
    }
    s.deformations.push_back(d);
  }
  const Json::Value& names = root["names"];
  if (!names.isNull() && !names.isArray())
  {
    error = session + ": \"names\" must be a list";
    return false;
  }
  for (Json::ArrayIndex i = 0; names.isArray() && i < names.size(); ++i)
  {
    const Json::Value& jn = names[i];
    PieceName n;
    const std::string where = "name " + std::to_string(i) + " in '" + path + "'";
    noteUnknownMembers(jn, { "name", "at" }, where, notes);
    if (!jn.isObject() || !jsonString(jn["name"], n.name) || !jsonNumbers(jn["at"], n.at))
    {
      error = where + " needs a name and a point \"at\" [x, y, z] on its piece";
      return false;
    }
    std::string why;
    if (!validPieceName(n.name, why))
    {
      error = where + ": " + why;
      return false;
    }
    s.names.push_back(n);
  }
  const Json::Value& measurements = root["measurements"];
  if (!measurements.isNull() && !measurements.isArray())
  {
    error = session + ": \"measurements\" must be a list";
    return false;
  }
  for (Json::ArrayIndex i = 0; measurements.isArray() && i < measurements.size(); ++i)
  {
    const Json::Value& jm = measurements[i];
    Measurement m;
    const std::string where = "measurement " + std::to_string(i) + " in '" + path + "'";
    noteUnknownMembers(jm, { "from", "to", "at", "pieces" }, where, notes);
    if (!jm.isObject() || !jsonNumbers(jm["from"], m.from) || !jsonNumbers(jm["to"], m.to) ||
      !std::isfinite(m.length()))
    {
      error = where + " needs two points \"from\" and \"to\", [x, y, z] each";
      return false;
    }
    m.angle = jm.isMember("at");
    if (m.angle && (!jsonNumbers(jm["at"], m.at) || !std::isfinite(m.degrees())))
    {
      error = where + ": an angle's vertex \"at\" must be a point [x, y, z] apart from \"from\" and \"to\"";
      return false;
    }
    if (jm.isMember("pieces"))
    {
      const Json::Value& jp = jm["pieces"];
      const Json::ArrayIndex count = m.angle ? 3 : 2;
      bool valid = jp.isArray() && jp.size() == count;
      for (Json::ArrayIndex k = 0; valid && k < count; ++k)
      {
        long long piece = -1;
        valid = jsonInteger(jp[k], -1, std::numeric_limits<int>::max(), piece);
        m.pieces[k] = static_cast<int>(piece);
      }
      if (!valid)
      {
        error = where + (m.angle ? ": \"pieces\" must be three piece numbers [i, j, k] (from, to, at; -1: none)"
                                 : ": \"pieces\" must be two piece numbers [i, j] (-1: none)");
        return false;
      }
    }
    s.measurements.push_back(m);
  }
  if (root.isMember("surface"))
  {
    const Json::Value& js = root["surface"];
    const std::string where = "the surface of " + session;
    noteUnknownMembers(js, { "iso", "seed", "crop", "series", "close", "smooth", "image_smooth", "label" }, where, notes);
    long long series = -1;
    const auto seriesIndex = [](const Json::Value& v, long long& out) {
      return jsonInteger(v, 0, std::numeric_limits<int>::max(), out);
    };
    long long smoothing = 0, label = 0;
    const auto iterations = [](const Json::Value& v, long long& out) { return jsonInteger(v, 0, 1000, out); };
    double imageSmoothing = -1.0;
    const auto gaussian = [](const Json::Value& v, double& out) {
      return jsonNumber(v, out) && out >= 0.0 && out <= 20.0;
    };
    const auto labelValue = [](const Json::Value& v, long long& out) {
      return jsonInteger(v, 1, std::numeric_limits<int>::max(), out);
    };
    if (!js.isObject() || !jsonMember(js, "iso", s.surface.iso, jsonNumber, where, "a number", error) ||
      !jsonMember(js, "series", series, seriesIndex, where, "a whole number of 0 or more", error) ||
      !jsonMember(js, "smooth", smoothing, iterations, where, "a whole number from 0 to 1000", error) ||
      !jsonMember(js, "image_smooth", imageSmoothing, gaussian, where,
        "a standard deviation from 0 to 20 voxels", error) ||
      (js.isMember("label") && js["label"].isString()
          ? !jsonMember(js, "label", s.surface.labelName, jsonString, where, "a segment's name", error)
          : !jsonMember(js, "label", label, labelValue, where, "a label value of 1 or more or a segment's name",
              error)) ||
      !jsonMember(js, "close", s.surface.closed, jsonBool, where, "true or false", error))
    {
      if (!js.isObject())
        error = session + ": \"surface\" must be an object (iso, seed, crop, series, close, smooth, image_smooth, label)";
      return false;
    }
    if (js.isMember("seed"))
    {
      if (!jsonNumbers(js["seed"], s.surface.seed))
      {
        error = where + ": \"seed\" must be [x, y, z]";
        return false;
      }
      s.surface.seeded = true;
    }
    if (js.isMember("crop"))
    {
      if (!jsonNumbers(js["crop"], s.surface.crop) || !lkapp::isOrderedBox(s.surface.crop.data()))
      {
        error = where + ": \"crop\" must be [xmin, xmax, ymin, ymax, zmin, zmax], each min below its max";
        return false;
      }
      s.surface.cropped = true;
    }
    s.surface.series = static_cast<long>(series);
    // Sessions saved before December 2026 left out a smoothing of 0 and
    // the automatic Gaussian, both then the defaults.
    s.surface.smoothing = static_cast<long>(smoothing);
    s.surface.imageSmoothing = imageSmoothing;
    s.surface.label = static_cast<long>(label);
    s.surface.given = true;
  }
  if (root.isMember("input"))
  {
    const Json::Value& ji = root["input"];
    const std::string where = "the input of " + session;
    noteUnknownMembers(ji, { "file", "bounds" }, where, notes);
    if (!ji.isObject() || !jsonMember(ji, "file", s.inputFile, jsonString, where, "a string", error))
    {
      if (!ji.isObject())
        error = session + ": \"input\" must be an object (file, bounds)";
      return false;
    }
    if (ji.isMember("bounds"))
    {
      const std::array<double, 6>& b = s.inputBounds;
      if (!jsonNumbers(ji["bounds"], s.inputBounds) || !(b[0] <= b[1] && b[2] <= b[3] && b[4] <= b[5]))
      {
        error = where + ": \"bounds\" must be [xmin, xmax, ymin, ymax, zmin, zmax], no min above its max";
        return false;
      }
      s.inputBoundsKnown = true;
    }
  }
  return true;
}

bool loadSession(const std::string& path, Session& s, std::string& error, std::string* notes)
{
  return lkapp::loadJsonObject(
    path, "session",
    [&](const Json::Value& root, std::string& message) { return readSession(root, path, s, message, notes); }, error);
}
} // namespace lkplanner
