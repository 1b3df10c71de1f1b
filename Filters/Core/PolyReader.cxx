// Reader of Shewchuk's Triangle .poly and .node formats.
//
// The whole text is read into memory and split into lines and tokens in place;
// numbers are converted with std::from_chars. That is several times faster than
// iostream >> per token and does not depend on the C locale's decimal point.
// Every failure is reported as "<name>:<line>: <reason>"; nothing throws out of
// the public functions.
#include "PolyReader.h"

#include "NumberText.h"
#include "Predicates.h"

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <string_view>
#include <system_error>
#include <utility>

namespace osm
{
namespace
{

namespace fs = std::filesystem;

/// Attribute values a file may declare without writing them (read as 0):
/// 8 MB of them, however short the file.
constexpr long long kUnwrittenAttributeValues = 1 << 20;
using Tokens = std::vector<std::string_view>;

// '\r' counts as blank so that CRLF files read like LF files.
bool isBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// A token for an error message: quoted, cut short, control bytes escaped,
/// so that binary garbage cannot make the message unreadable.
std::string quote(std::string_view token)
{
  constexpr std::size_t maxShown = 40;
  static const char hex[] = "0123456789ABCDEF";
  std::string q = "'";
  for (const unsigned char c : token.substr(0, maxShown))
  {
    if (c >= 0x20 && c < 0x7F)
      q += static_cast<char>(c);
    else
      q += std::string("\\x") + hex[c >> 4] + hex[c & 15];
  }
  if (token.size() > maxShown)
    q += "...";
  return q + "'";
}

/// Triangle reads numbers with strtod/strtol, which accept a leading '+';
/// std::from_chars does not, so drop it here.
std::string_view withoutPlus(std::string_view t)
{
  if (t.size() > 1 && t[0] == '+' && t[1] != '+' && t[1] != '-')
    t.remove_prefix(1);
  return t;
}

enum class Conversion
{
  Ok,
  NotNumber,
  OutOfRange,
  NotFinite
};

Conversion toInteger(std::string_view token, long long& value)
{
  const std::string_view t = withoutPlus(token);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (ec == std::errc::result_out_of_range)
    return Conversion::OutOfRange;
  if (ec == std::errc() && end == t.data() + t.size())
    return Conversion::Ok;
  // A whole number written as a real ("1.0", "2.000000000000000000e+00", as
  // numpy's savetxt writes every column): its value (a review: such files
  // meshed in Triangle and were refused here; Triangle's strtol reads the
  // digits before the point, 1 for 1.0e+01, which no such file means).
  double real = 0;
  const auto [realEnd, realEc] = std::from_chars(t.data(), t.data() + t.size(), real);
  if (realEc != std::errc() || realEnd != t.data() + t.size() || real != std::floor(real))
    return Conversion::NotNumber;
  if (!(std::fabs(real) < 9.2e18))
    return Conversion::OutOfRange;
  value = static_cast<long long>(real);
  return Conversion::Ok;
}

Conversion toReal(std::string_view token, double& value)
{
  const std::string_view t = withoutPlus(token);
  const auto [end, ec] = std::from_chars(t.data(), t.data() + t.size(), value);
  if (end != t.data() + t.size() || (ec != std::errc() && ec != std::errc::result_out_of_range))
    return Conversion::NotNumber;
  if (ec == std::errc::result_out_of_range)
  {
    // Underflow (1e-400) is a harmless zero, as with strtod; overflow is not finite.
    // from_chars leaves value unset here, so let strtod say which one it was
    // (in the C locale: in a German one, it read 1.5e-400 as 1, a review).
    value = cLocaleReal(std::string(t));
  }
  return std::isfinite(value) ? Conversion::Ok : Conversion::NotFinite;
}

/// Walks a text one data line at a time: blank lines and '#' comments are skipped
/// and each line is split into whitespace-separated tokens.
class LineReader
{
public:
  explicit LineReader(std::string_view text)
    : text_(text)
  {
    // A UTF-8 byte order mark written by some editors is not part of the data.
    if (text_.substr(0, 3) == "\xEF\xBB\xBF")
      text_.remove_prefix(3);
  }

  /// Advances to the next line holding data; false at the end of the text.
  bool next()
  {
    while (pos_ < text_.size())
    {
      const std::size_t end = lineEnd(pos_);
      ++line_;
      split(text_.substr(pos_, end - pos_));
      pos_ = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
      if (!tokens_.empty())
        return true;
    }
    tokens_.clear();
    return false;
  }

  const Tokens& tokens() const { return tokens_; }

  /// The current line; at the end of the text, the last line (1 for an empty text).
  std::size_t line() const { return std::max<std::size_t>(line_, 1); }

  /// An upper bound on the data lines after the current one, to refuse absurd counts
  /// before allocating for them. A final newline does not start another line.
  std::size_t linesLeft() const
  {
    if (pos_ >= text_.size())
      return 0;
    std::size_t lines = 0;
    for (std::size_t at = pos_; at < text_.size(); ++lines)
    {
      const std::size_t end = lineEnd(at);
      at = end + (text_.compare(end, 2, "\r\n") == 0 ? 2 : 1);
    }
    return lines;
  }

  std::size_t bytesLeft() const { return pos_ >= text_.size() ? 0 : text_.size() - pos_; }

private:
  /// Where the line from 'from' ends: at LF, CRLF or a CR alone (classic Mac
  /// OS; a review: such a file read as one line, "4 vertices announced, but
  /// only 0 lines follow", and one mixing CR with CRLF misread), else at the
  /// end of the text.
  std::size_t lineEnd(std::size_t from) const
  {
    return std::min(text_.find_first_of("\r\n", from), text_.size());
  }

  void split(std::string_view s)
  {
    tokens_.clear();
    s = s.substr(0, s.find('#')); // a comment runs to the end of the line
    std::size_t i = 0;
    while (true)
    {
      while (i < s.size() && isBlank(s[i]))
        ++i;
      if (i == s.size())
        return;
      const std::size_t start = i;
      while (i < s.size() && !isBlank(s[i]))
        ++i;
      tokens_.push_back(s.substr(start, i - start));
    }
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t line_ = 0;
  Tokens tokens_;
};

PolyFile failure(std::string error)
{
  PolyFile f;
  f.error = std::move(error);
  return f;
}

/// The .node text that a .poly listing zero vertices refers to.
struct NodeText
{
  std::string text;
  std::string name;
  std::string problem; ///< why it is unavailable; empty when text is valid
};
using NodeLoader = std::function<NodeText()>;

/// The first line of a node section.
struct NodeHeader
{
  long long count = 0;
  long long attributes = 0;
  bool markers = false;
  std::size_t line = 0;
};

/// Parses one text (a .poly or a .node) into a PolyFile.
class Parser
{
public:
  Parser(std::string_view text, std::string name)
    : lines_(text)
    , name_(std::move(name))
  {}

  PolyFile parseNode()
  {
    if (readNodeFile())
      out_.ok = true;
    return finish();
  }

  PolyFile parsePoly(const NodeLoader& loadNodes)
  {
    if (readPolyFile(loadNodes))
      out_.ok = true;
    return finish();
  }

private:
  PolyFile finish()
  {
    if (!out_.ok)
      return failure(std::move(out_.error)); // no half-read data on failure
    return std::move(out_);
  }

  // --- Errors -------------------------------------------------------------------

  bool fail(std::size_t line, const std::string& reason)
  {
    out_.error = name_ + ":" + std::to_string(line) + ": " + reason;
    return false;
  }
  bool fail(const std::string& reason) { return fail(lines_.line(), reason); }

  /// Names a field in messages, e.g. "y coordinate of vertex 3". Built only on failure,
  /// so that the per-token path allocates nothing.
  std::string subject(const char* field) const
  {
    if (!item_)
      return field;
    return std::string(field) + " of " + item_ + " " + std::to_string(itemId_);
  }

  void setItem(const char* kind, long long id)
  {
    item_ = kind;
    itemId_ = id;
  }

  // --- Fields of the current line -------------------------------------------------

  bool present(std::size_t i) const { return i < lines_.tokens().size(); }

  bool integer(std::size_t i, const char* field, long long& value)
  {
    if (!present(i))
      return fail("missing " + subject(field));
    const std::string_view t = lines_.tokens()[i];
    switch (toInteger(t, value))
    {
      case Conversion::Ok:
        return true;
      case Conversion::OutOfRange:
        return fail(subject(field) + " is out of range: " + quote(t));
      default:
        return fail("expected an integer for the " + subject(field) + ", found " + quote(t));
    }
  }

  bool smallInteger(std::size_t i, const char* field, int& value)
  {
    long long v = 0;
    if (!integer(i, field, v))
      return false;
    if (v < std::numeric_limits<int>::min() || v > std::numeric_limits<int>::max())
      return fail(subject(field) + " is out of range: " + quote(lines_.tokens()[i]));
    value = static_cast<int>(v);
    return true;
  }

  bool real(std::size_t i, const char* field, double& value)
  {
    if (!present(i))
      return fail("missing " + subject(field));
    const std::string_view t = lines_.tokens()[i];
    switch (toReal(t, value))
    {
      case Conversion::Ok:
        return true;
      case Conversion::NotFinite:
        return fail(subject(field) + " is not a finite number: " + quote(t));
      default:
        return fail("expected a number for the " + subject(field) + ", found " + quote(t));
    }
  }

  // Triangle gives absent optional fields (attributes, markers) the value 0.
  bool optionalInteger(std::size_t i, const char* field, long long& value)
  {
    return !present(i) || integer(i, field, value);
  }
  bool optionalSmallInteger(std::size_t i, const char* field, int& value)
  {
    return !present(i) || smallInteger(i, field, value);
  }
  bool optionalReal(std::size_t i, const char* field, double& value)
  {
    return !present(i) || real(i, field, value);
  }

  // --- Sections -------------------------------------------------------------------

  /// Reads the item count of a section header (token 0) and refuses counts that the
  /// rest of the text cannot hold, so nothing absurd is ever allocated.
  bool count(const char* items, long long& n)
  {
    setItem(nullptr, 0);
    const std::string field = std::string("number of ") + items;
    if (!integer(0, field.c_str(), n))
      return false;
    if (n < 0)
      return fail("negative " + field + ": " + std::to_string(n));
    if (n > std::numeric_limits<int>::max())
      return fail("too many " + std::string(items) + ": " + std::to_string(n));
    const std::size_t left = lines_.linesLeft();
    if (static_cast<std::size_t>(n) > left)
      return fail(std::to_string(n) + " " + items + " announced, but only " + std::to_string(left) +
        (left == 1 ? " line follows" : " lines follow"));
    return true;
  }

  /// Reads n items with readItem(i), one data line each; running out of text is
  /// reported at the header that announced them.
  template <typename ReadItem>
  bool items(
    const char* section, const char* plural, long long n, std::size_t headerLine, ReadItem readItem)
  {
    for (long long i = 0; i < n; ++i)
    {
      if (!lines_.next())
        return fail(headerLine,
          std::string(section) + " section truncated: " + std::to_string(n) + " " + plural +
            " announced, " + std::to_string(i) + " found");
      setItem(nullptr, 0);
      if (!readItem(i))
      {
        // A line like the next section's header where an item was due (a
        // bare count; after the vertices, "<#segments> [<markers>]") most
        // often is that header: the count announced more items than follow.
        if (lines_.tokens().size() <= (std::strcmp(section, "vertex") == 0 ? 2u : 1u))
          out_.error += " (line " + std::to_string(lines_.line()) + " is read as " + section + " " +
            std::to_string(i + 1) + " of the " + std::to_string(n) + " " + plural + " line " +
            std::to_string(headerLine) + " announces: does the file list fewer than it announces?)";
        return false;
      }
    }
    return true;
  }

  /// "<#vertices> [<dimension>] [<#attributes>] [<#markers>]"; absent fields take
  /// Triangle's defaults (2, 0, 0). In a .poly listing zero vertices the rest of the
  /// line is unused (the .node header rules), so its dimension is not checked.
  bool nodeHeader(NodeHeader& h, bool inPoly)
  {
    h.line = lines_.line();
    long long dimension = 2, markers = 0;
    if (!count("vertices", h.count) || !optionalInteger(1, "dimension", dimension) ||
      !optionalInteger(2, "number of vertex attributes", h.attributes) ||
      !optionalInteger(3, "number of vertex boundary markers", markers))
      return false;
    if (inPoly && h.count == 0)
      return true;
    if (dimension != 2)
      return fail("dimension must be 2, not " + std::to_string(dimension));
    if (h.attributes < 0)
      return fail("negative number of vertex attributes: " + std::to_string(h.attributes));
    // A written attribute takes at least two bytes (a digit and a separator).
    // Lines may leave attributes out (read as 0, as Triangle does): more than
    // the file holds are refused only where their zeros would be many (a
    // review: 3 vertices with 5 attributes left out were refused, or read when
    // a long comment followed).
    if (h.count > 0 && h.attributes > static_cast<long long>(lines_.bytesLeft() / 2) / h.count &&
      h.attributes > kUnwrittenAttributeValues / h.count)
      return fail(std::to_string(h.count) + " vertices with " + std::to_string(h.attributes) +
        " attributes each cannot fit in the rest of the file");
    h.markers = markers != 0; // any nonzero value means markers, as in triangle.c
    return true;
  }

  /// "<index> <x> <y> [attributes...] [marker]". The first index fixes the numbering.
  bool vertex(long long i, const NodeHeader& h)
  {
    long long index = 0;
    if (!integer(0, "vertex index", index))
      return false;
    if (i == 0 && index != 0 && index != 1)
      return fail("the first vertex must be numbered 0 or 1, not " + std::to_string(index));
    if (i == 0)
      out_.firstIndex = static_cast<int>(index);
    else if (index != out_.firstIndex + i)
      return fail("vertex index " + std::to_string(index) + " is out of sequence, expected " +
        std::to_string(out_.firstIndex + i));
    setItem("vertex", index);
    Point p;
    if (!real(1, "x coordinate", p.x) || !real(2, "y coordinate", p.y))
      return false;
    out_.pslg.points.push_back(p);
    const std::size_t attributes = static_cast<std::size_t>(h.attributes);
    if (attributes > 0)
    {
      std::vector<double> values(attributes, 0.0);
      for (std::size_t k = 0; k < attributes; ++k)
        if (!optionalReal(3 + k, "attribute", values[k]))
          return false;
      out_.pointAttributes.push_back(std::move(values));
    }
    if (h.markers)
    {
      int marker = 0;
      if (!optionalSmallInteger(3 + attributes, "boundary marker", marker))
        return false;
      out_.pointMarkers.push_back(marker);
    }
    return true;
  }

  bool vertices(const NodeHeader& h)
  {
    const std::size_t n = static_cast<std::size_t>(h.count);
    out_.pslg.points.reserve(n);
    if (h.attributes > 0)
      out_.pointAttributes.reserve(n);
    if (h.markers)
      out_.pointMarkers.reserve(n);
    return items("vertex", "vertices", h.count, h.line, [&](long long i) { return vertex(i, h); });
  }

  bool readNodeFile()
  {
    if (!lines_.next())
      return fail("no vertex count: the text is empty or holds only comments");
    NodeHeader h;
    return nodeHeader(h, false) && vertices(h);
  }

  /// A .poly listing zero vertices takes them, their numbering, attributes and
  /// markers from the .node text; errors there are reported against that text.
  bool verticesFromNodeText(const NodeLoader& loadNodes, std::size_t headerLine)
  {
    const NodeText node = loadNodes();
    if (!node.problem.empty())
      return fail(headerLine, "the file lists 0 vertices, so they must come from " + node.problem);
    PolyFile nodes = Parser(node.text, node.name).parseNode();
    if (!nodes.ok)
    {
      out_.error = std::move(nodes.error);
      return false;
    }
    out_.pslg.points = std::move(nodes.pslg.points);
    out_.firstIndex = nodes.firstIndex;
    out_.pointAttributes = std::move(nodes.pointAttributes);
    out_.pointMarkers = std::move(nodes.pointMarkers);
    return true;
  }

  /// "<index> <end1> <end2> [marker]", endpoints in the file's numbering.
  bool segment(bool markers)
  {
    long long index = 0, ends[2] = { 0, 0 };
    if (!integer(0, "segment index", index))
      return false;
    setItem("segment", index);
    if (!integer(1, "first endpoint", ends[0]) || !integer(2, "second endpoint", ends[1]))
      return false;
    const long long first = out_.firstIndex;
    const long long last = first + static_cast<long long>(out_.pslg.points.size()) - 1;
    for (const long long e : ends)
      if (e < first || e > last)
        return fail("segment " + std::to_string(index) + " refers to vertex " + std::to_string(e) +
          ", which does not exist " +
          (out_.pslg.points.empty() ? std::string("(there are no vertices)")
                                    : "(vertices are numbered " + std::to_string(first) + " to " +
                std::to_string(last) + ")"));
    out_.pslg.segments.push_back(
      { static_cast<int>(ends[0] - first), static_cast<int>(ends[1] - first) });
    if (markers)
    {
      int marker = 0;
      if (!optionalSmallInteger(3, "boundary marker", marker))
        return false;
      out_.segmentMarkers.push_back(marker);
    }
    return true;
  }

  bool segments()
  {
    if (!lines_.next())
      return fail("the file ends where the number of segments was expected");
    const std::size_t line = lines_.line();
    long long n = 0, markers = 0;
    if (!count("segments", n) || !optionalInteger(1, "number of segment boundary markers", markers))
      return false;
    out_.pslg.segments.reserve(static_cast<std::size_t>(n));
    if (markers != 0)
      out_.segmentMarkers.reserve(static_cast<std::size_t>(n));
    return items("segment", "segments", n, line, [&](long long) { return segment(markers != 0); });
  }

  /// "<index> <x> <y>": a seed point of a hole.
  bool hole()
  {
    long long index = 0;
    if (!integer(0, "hole index", index))
      return false;
    setItem("hole", index);
    Point p;
    if (!real(1, "x coordinate", p.x) || !real(2, "y coordinate", p.y))
      return false;
    out_.pslg.holes.push_back(p);
    return true;
  }

  /// Some files stop after the segments; Triangle's own output never does, but
  /// an absent holes section can only mean "no holes".
  bool holes()
  {
    if (!lines_.next())
      return true;
    const std::size_t line = lines_.line();
    long long n = 0;
    if (!count("holes", n))
      return false;
    out_.pslg.holes.reserve(static_cast<std::size_t>(n));
    return items("hole", "holes", n, line, [&](long long) { return hole(); });
  }

  /// "<index> <x> <y> <attribute> [<maxarea>]". With one value Triangle uses it as both
  /// the attribute and the area limit, so that is what a 4-token line means here too.
  bool region()
  {
    long long index = 0;
    if (!integer(0, "region index", index))
      return false;
    setItem("region", index);
    RegionAttribute r;
    if (!real(1, "x coordinate", r.seed.x) || !real(2, "y coordinate", r.seed.y) ||
      !real(3, "attribute", r.attribute))
      return false;
    r.maxArea = r.attribute;
    if (!optionalReal(4, "maximum area", r.maxArea))
      return false;
    out_.pslg.regions.push_back(r);
    return true;
  }

  bool regions()
  {
    if (!lines_.next())
      return true; // the regional attributes section is optional
    const std::size_t line = lines_.line();
    long long n = 0;
    if (!count("regions", n))
      return false;
    out_.pslg.regions.reserve(static_cast<std::size_t>(n));
    return items("region", "regions", n, line, [&](long long) { return region(); });
  }

  bool readPolyFile(const NodeLoader& loadNodes)
  {
    if (!lines_.next())
      return fail("no vertex count: the text is empty or holds only comments");
    NodeHeader h;
    if (!nodeHeader(h, true))
      return false;
    const bool ok = h.count == 0 ? verticesFromNodeText(loadNodes, h.line) : vertices(h);
    return ok && segments() && holes() && regions();
  }

  LineReader lines_;
  std::string name_;
  PolyFile out_;
  const char* item_ = nullptr; ///< the kind of item being read, for messages
  long long itemId_ = 0;
};

/// Keeps the promise that nothing throws: allocation failures and the like become
/// an error message instead.
template <typename Body>
PolyFile guarded(const std::string& name, Body body) noexcept
{
  const RoundToNearest rounding; // numbers read as written, whatever the host's mode
  try
  {
    return body();
  }
  catch (const std::exception& e)
  {
    try
    {
      return failure(name + ": " + e.what());
    }
    catch (...)
    {
      return PolyFile{};
    }
  }
  catch (...)
  {
    return PolyFile{};
  }
}

/// Reads the rest of a stream; false when it was unusable or a read failed.
bool readAll(std::istream& in, std::string& text)
{
  if (!in)
    return false;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0)
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
  return !in.bad();
}

/// Reads a whole file; on failure explains why in `why`.
bool readFile(const std::string& path, std::string& text, std::string& why)
{
  std::error_code ec;
  if (fs::is_directory(path, ec))
  {
    why = "it is a directory";
    return false;
  }
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    const int err = errno;
    why = err ? std::error_code(err, std::generic_category()).message() : "cannot open it";
    return false;
  }
  const std::uintmax_t size = fs::file_size(path, ec);
  if (!ec)
    text.reserve(static_cast<std::size_t>(size));
  if (!readAll(in, text))
  {
    why = "read error";
    return false;
  }
  return true;
}

std::string lowercase(std::string s)
{
  for (char& c : s)
    if (c >= 'A' && c <= 'Z')
      c = static_cast<char>(c - 'A' + 'a');
  return s;
}

/// The name of the .node text that belongs to a .poly name: "x.poly" -> "x.node".
std::string nodeNameFor(const std::string& polyName)
{
  return fs::path(polyName).replace_extension(".node").string();
}

} // namespace

PolyFile parseNode(std::istream& in, const std::string& name)
{
  return guarded(name, [&] {
    std::string text;
    if (!readAll(in, text))
      return failure(name + ": cannot read the input stream");
    return Parser(text, name).parseNode();
  });
}

PolyFile parsePoly(std::istream& in, const std::string& name, std::istream* nodeText)
{
  return guarded(name, [&] {
    std::string text;
    if (!readAll(in, text))
      return failure(name + ": cannot read the input stream");
    const NodeLoader loadNodes = [&] {
      NodeText node;
      node.name = nodeNameFor(name);
      if (!nodeText)
        node.problem = "a .node text, but none was given";
      else if (!readAll(*nodeText, node.text))
        node.problem = "the .node text " + node.name + ", which cannot be read";
      return node;
    };
    return Parser(text, name).parsePoly(loadNodes);
  });
}

bool polyListsNoVertices(std::istream& in)
{
  std::string text;
  if (!readAll(in, text))
    return false;
  LineReader lines(text);
  long long count = -1;
  return lines.next() && toInteger(lines.tokens()[0], count) == Conversion::Ok && count == 0;
}

PolyFile readPolyFile(const std::string& path)
{
  return guarded(path, [&] {
    const std::string extension = lowercase(fs::path(path).extension().string());
    if (extension != ".poly" && extension != ".node")
      return failure(
        path + ": unknown file type " + quote(extension) + ", expected a .poly or .node file");
    std::string text, why;
    if (!readFile(path, text, why))
      return failure(path + ": cannot read the file: " + why);
    if (extension == ".node")
      return Parser(text, path).parseNode();
    const NodeLoader loadNodes = [&] {
      NodeText node;
      node.name = nodeNameFor(path);
      std::string reason;
      if (!readFile(node.name, node.text, reason))
        node.problem = node.name + ", which cannot be read: " + reason;
      return node;
    };
    return Parser(text, path).parsePoly(loadNodes);
  });
}

} // namespace osm
