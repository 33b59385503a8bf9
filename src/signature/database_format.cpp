/*
 * pcl_flowseg - the signature database's text format: reading with every value checked, writing.
 * SPDX-License-Identifier: GPL-3.0-or-later
 */
#include "database_format.h"

#include <array>
#include <cmath>
#include <cstring>
#include <iomanip>
#include <limits>
#include <sstream>
#include <utility>
#include <vector>

namespace pcl_flowseg {

namespace {

const char* const kMagic = "pcl_flowseg signature database";

Status
lineError (const std::string& path, std::size_t line, const std::string& what)
{
  return Status::error (path + ":" + std::to_string (line) + ": " + what);
}

} // namespace

Status
LineReader::error (const std::string& what) const
{
  return lineError (path, number, what);
}

Status
readDatabaseHeader (std::istream& in, const std::string& path, std::size_t& count)
{
  std::string line, word;
  if (!std::getline (in, line) || line.compare (0, std::strlen (kMagic), kMagic) != 0)
    return Status::error (path + ": not a pcl_flowseg signature database");
  int version = 0;
  if (!(std::istringstream (line.substr (std::strlen (kMagic))) >> version))
    return lineError (path, 1, "no database version");
  if (version >= 1 && version <= 6)
    return lineError (path, 1, "a version " + std::to_string (version) + " database (signatures without " +
                                   (version == 1   ? "shape descriptions"
                                    : version == 2 ? "inner-distance and thickness profiles"
                                    : version == 3 ? "2D contours"
                                    : version == 4 ? "inner-distance contexts"
                                    : version == 5 ? "the parts' remoteness"
                                                   : "views for single-view scans") +
                                   ", written by an older pcl_flowseg): rebuild it with flowseg_db build");
  if (version != kDatabaseVersion)
    return lineError (path, 1, "unsupported database version (this build reads version " +
                                   std::to_string (kDatabaseVersion) + ")");
  if (!std::getline (in, line) || !(std::istringstream (line) >> word >> count) || word != "shapes")
    return lineError (path, 2, "expected 'shapes N'");
  // Every shape takes a line of at least 20 bytes ("shape L 3 1 1 0 0 0 0 0 N\n"), so a count the rest
  // of the file cannot hold is refused before anything is allocated for it.
  in.clear (); // a file that ends right after this line has set eof
  const std::streampos here = in.tellg ();
  in.seekg (0, std::ios::end);
  const auto rest = static_cast<unsigned long long> (in.tellg () - here);
  in.seekg (here);
  if (count > rest / 20)
    return lineError (path, 2, std::to_string (count) + " shapes cannot fit in the " + std::to_string (rest) +
                                   " bytes that follow");
  return Status::success ();
}

namespace {

Status
readPoint (LineReader& reader, WeightedPoint& p)
{
  std::string line, word;
  if (!reader.next (line) || !(std::istringstream (line) >> word >> p.position.x () >> p.position.y () >> p.position.z () >> p.weight) ||
      word != "p")
    return reader.error ("expected 'p X Y Z WEIGHT'");
  if (!p.position.allFinite () || p.position.cwiseAbs ().maxCoeff () > kLargestSignatureCoordinate)
    return reader.error ("coordinates must be finite numbers of at most 1e9 in size");
  if (!(p.weight >= 0.0 && p.weight <= 1.0))
    return reader.error ("the weight must be a number in [0, 1]");
  return Status::success ();
}

Status
readPart (LineReader& reader, PartDescription& p)
{
  std::string line, word;
  if (!reader.next (line) || !(std::istringstream (line) >> word >> p.weight >> p.thickness >> p.extent >> p.middle_ratio >>
                               p.smallest_ratio >> p.remoteness) ||
      word != "q")
    return reader.error ("expected 'q WEIGHT THICKNESS EXTENT MIDDLE SMALLEST REMOTENESS'");
  return Status::success ();
}

/** A line of \a tag followed by the N numbers of \a values (a distribution's bins, a profile). */
template <typename Number, std::size_t N>
Status
readTaggedNumbers (LineReader& reader, const char* tag, std::array<Number, N>& values)
{
  std::string line, word;
  std::istringstream fields;
  if (reader.next (line))
    fields.str (line);
  bool ok = static_cast<bool> (fields >> word) && word == tag;
  for (Number& v : values)
    ok = ok && static_cast<bool> (fields >> v);
  if (!ok)
    return reader.error (std::string ("expected '") + tag + "' and " + std::to_string (N) + " numbers");
  return Status::success ();
}

/** An 'x' line: the source's thickness, then its kContextBins histogram entries. */
Status
readInnerContext (LineReader& reader, InnerContext& context)
{
  std::string line, word;
  std::istringstream fields;
  if (reader.next (line))
    fields.str (line);
  bool ok = static_cast<bool> (fields >> word >> context.thickness) && word == "x";
  for (float& v : context.distances)
    ok = ok && static_cast<bool> (fields >> v);
  if (!ok)
    return reader.error ("expected 'x' and " + std::to_string (kContextBins + 1) + " numbers");
  return Status::success ();
}

/** A line of \a tag, a count N of at most \a most, and N points with their normals (6 numbers). */
Status
readTaggedPoints (LineReader& reader, const char* tag, std::size_t most, std::vector<Eigen::Vector3f>& points,
                  std::vector<Eigen::Vector3f>& normals)
{
  std::string line, word;
  std::size_t count = 0;
  std::istringstream fields (reader.next (line) ? line : std::string ());
  if (!(fields >> word >> count) || word != tag || count > most)
    return reader.error (std::string ("expected '") + tag + " N' (N at most " + std::to_string (most) +
                         ") and N points with normals");
  points.resize (count);
  normals.resize (count);
  for (std::size_t i = 0; i < count; ++i)
  {
    if (!(fields >> points[i].x () >> points[i].y () >> points[i].z () >> normals[i].x () >> normals[i].y () >> normals[i].z ()))
      return reader.error (std::string ("expected '") + tag + " N' and " + std::to_string (count) + " points of 6 numbers");
  }
  return Status::success ();
}

/** A 'v' line (the view's direction, centre, scale and histogram) and a 'u' line (its points). */
Status
readView (LineReader& reader, ViewDescription& view)
{
  std::string line, word;
  std::istringstream fields;
  if (reader.next (line))
    fields.str (line);
  bool ok = static_cast<bool> (fields >> word >> view.direction.x () >> view.direction.y () >> view.direction.z () >>
                               view.roll >> view.centre.x () >> view.centre.y () >> view.centre.z () >> view.scale) &&
            word == "v";
  for (float& v : view.histogram)
    ok = ok && static_cast<bool> (fields >> v);
  if (!ok)
    return reader.error ("expected 'v DX DY DZ ROLL CX CY CZ SCALE' and " + std::to_string (kViewHistogramBins) + " numbers");
  return readTaggedPoints (reader, "u", kViewPoints, view.points, view.normals);
}

/** The 'views N SINGLE' line and the N views that follow it. */
Status
readViewSet (LineReader& reader, ViewSet& set)
{
  std::string line, word;
  std::size_t count = 0;
  int single = 0;
  if (!reader.next (line) || !(std::istringstream (line) >> word >> count >> single) || word != "views" ||
      count > 10 * kDefaultViewCount || (single != 0 && single != 1))
    return reader.error ("expected 'views N SINGLE' (SINGLE 0 or 1)");
  set.single_view = single == 1;
  set.views.resize (count);
  for (ViewDescription& view : set.views)
    if (const Status read = readView (reader, view); !read)
      return read;
  return readTaggedPoints (reader, "o", kShapePoints, set.shape_points, set.shape_normals);
}

/** The points with the stream's precision, their normals with 2 digits (they only weigh offsets;
  * such a normal's length is within 1% of 1, which checkViewSet allows). */
void
writeTaggedPoints (std::ostream& out, const char* tag, const std::vector<Eigen::Vector3f>& points,
                   const std::vector<Eigen::Vector3f>& normals)
{
  const std::streamsize precision = out.precision ();
  out << tag << " " << points.size ();
  for (std::size_t i = 0; i < points.size (); ++i)
  {
    out.precision (precision);
    out << " " << points[i].x () << " " << points[i].y () << " " << points[i].z ();
    out.precision (2);
    out << " " << normals[i].x () << " " << normals[i].y () << " " << normals[i].z ();
  }
  out.precision (precision);
  out << "\n";
}

/** The description's distribution, profile, contour and context lines (a shape with parts). */
void
writeDescribedLines (std::ostream& out, const ShapeDescription& d)
{
  std::vector<std::pair<const char*, const Distribution*>> tagged{{"t", &d.thickness}, {"i", &d.inner_distance}, {"s", &d.solid_distance}};
  for (const Distribution& row : d.inner_profiles)
    tagged.emplace_back ("r", &row);
  for (const auto& [tag, bins] : tagged)
  {
    out << tag;
    for (double v : *bins)
      out << " " << v;
    out << "\n";
  }
  out << "h";
  for (double v : d.thickness_profile)
    out << " " << v;
  out << "\n";
  // Nine digits read back every float exactly, in half the bytes of the doubles' seventeen.
  const std::streamsize precision = out.precision (std::numeric_limits<float>::max_digits10);
  for (const ContourHistogram& row : d.contour)
  {
    out << "c";
    for (float v : row)
      out << " " << v;
    out << "\n";
  }
  for (const InnerContext& context : d.inner_contexts)
  {
    out << "x " << context.thickness;
    for (float v : context.distances)
      out << " " << v;
    out << "\n";
  }
  out.precision (precision);
}

void
writeViewSet (std::ostream& out, const ViewSet& set)
{
  // Four digits: a view's numbers are about 1 (RMS radii, shares), and matching needs no more.
  const std::streamsize precision = out.precision (4);
  out << "views " << set.views.size () << " " << (set.single_view ? 1 : 0) << "\n";
  for (const ViewDescription& view : set.views)
  {
    out << "v " << view.direction.x () << " " << view.direction.y () << " " << view.direction.z () << " " << view.roll << " "
        << view.centre.x ()
        << " " << view.centre.y () << " " << view.centre.z () << " " << view.scale;
    for (float v : view.histogram)
      out << " " << v;
    out << "\n";
    writeTaggedPoints (out, "u", view.points, view.normals);
  }
  // The shape's points are in input units: seven digits keep them to a millionth of its size.
  out.precision (7);
  writeTaggedPoints (out, "o", set.shape_points, set.shape_normals);
  out.precision (precision);
}

} // namespace

Status
readShape (LineReader& reader, std::size_t s, std::size_t count, ShapeEntry& e)
{
  std::string line, word;
  if (!reader.next (line))
    return Status::error (reader.path + ": ends after " + std::to_string (s) + " of " + std::to_string (count) + " shapes");
  std::istringstream head (line);
  std::size_t points = 0, parts = 0, contour = 0, contexts = 0;
  Signature& sig = e.signature;
  if (!(head >> word >> e.label >> sig.dimension >> sig.unit >> sig.interior_volume >> sig.significance >> points >> parts >>
        contour >> contexts) ||
      word != "shape" || (sig.dimension != 2 && sig.dimension != 3) || points > 100000 || parts > kMaxParts ||
      contour > kContourPoints || contexts > kDistanceSources || !std::isfinite (sig.unit) ||
      !std::isfinite (sig.interior_volume))
    return reader.error ("expected 'shape LABEL DIMENSION UNIT VOLUME SIGNIFICANCE POINTS PARTS CONTOUR CONTEXTS NAME'");
  std::getline (head >> std::ws, e.name);
  if (e.name.empty ())
    return reader.error ("shape without a name");
  const std::size_t shape_line = reader.number;
  sig.points.resize (points);
  for (WeightedPoint& p : sig.points)
    if (const Status read = readPoint (reader, p); !read)
      return read;
  sig.description.parts.resize (parts);
  for (PartDescription& p : sig.description.parts)
    if (const Status read = readPart (reader, p); !read)
      return read;
  if (parts > 0)
    for (const auto& [tag, bins] : {std::pair<const char*, Distribution*> ("t", &sig.description.thickness),
                                    {"i", &sig.description.inner_distance}, {"s", &sig.description.solid_distance}})
      if (const Status read = readTaggedNumbers (reader, tag, *bins); !read)
        return read;
  if (parts > 0)
    for (Distribution& row : sig.description.inner_profiles)
      if (const Status read = readTaggedNumbers (reader, "r", row); !read)
        return read;
  if (parts > 0)
    if (const Status read = readTaggedNumbers (reader, "h", sig.description.thickness_profile); !read)
      return read;
  sig.description.contour.resize (contour);
  for (ContourHistogram& row : sig.description.contour)
    if (const Status read = readTaggedNumbers (reader, "c", row); !read)
      return read;
  sig.description.inner_contexts.resize (contexts);
  for (InnerContext& context : sig.description.inner_contexts)
    if (const Status read = readInnerContext (reader, context); !read)
      return read;
  if (const Status read = readViewSet (reader, sig.views); !read)
    return read;
  if (const Status checked = checkSignature (sig); !checked)
    return lineError (reader.path, shape_line, "shape '" + e.name + "': " + checked.message);
  return Status::success ();
}

void
writeShape (std::ostream& out, const ShapeEntry& e)
{
  const Signature& s = e.signature;
  const ShapeDescription& d = s.description;
  out << "shape " << (e.label.empty () ? "-" : e.label) << " " << s.dimension << " " << s.unit << " " << s.interior_volume << " "
      << s.significance << " " << s.points.size () << " " << d.parts.size () << " " << d.contour.size () << " "
      << d.inner_contexts.size () << " " << e.name << "\n";
  for (const auto& p : s.points)
    out << "p " << p.position.x () << " " << p.position.y () << " " << p.position.z () << " " << p.weight << "\n";
  for (const auto& p : d.parts)
    out << "q " << p.weight << " " << p.thickness << " " << p.extent << " " << p.middle_ratio << " " << p.smallest_ratio << " "
        << p.remoteness << "\n";
  if (!d.parts.empty ())
    writeDescribedLines (out, d);
  writeViewSet (out, s.views);
}

void
writeDatabaseHeader (std::ostream& out, std::size_t count)
{
  out << kMagic << " " << kDatabaseVersion << "\nshapes " << count << "\n" << std::setprecision (17);
}

} // namespace pcl_flowseg
