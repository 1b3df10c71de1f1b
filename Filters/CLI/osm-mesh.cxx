// SPDX-License-Identifier: BSD-3-Clause
// Copyright (c) 2026, the Overlay Stitch Meshing authors
//
// osm-mesh: the command-line tool. A thin driver around the VTK pipeline
// reader -> vtkOverlayStitchMesher -> writer, so that the command line, C++
// and pvpython give the same meshes. Triangle's files and the SVG drawing are
// written by the core's writer (MeshWriter.h) from the filter's outputs.
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkCellData.h"
#include "vtkCellType.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataReader.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkIdTypeArray.h"
#include "vtkLogger.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkOutputWindow.h"
#include "vtkOverlayStitchMesher.h"
#include "vtkPointData.h"
#include "vtkPointSet.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataReader.h"
#include "vtkPolyDataWriter.h"
#include "vtkSmartPointer.h"
#include "vtkTrianglePolyReader.h"
#include "vtkUnstructuredGrid.h"
#include "vtkUnstructuredGridReader.h"
#include "vtkXMLPolyDataReader.h"
#include "vtkXMLPolyDataWriter.h"
#include "vtkXMLUnstructuredGridReader.h"
#include "vtkXMLUnstructuredGridWriter.h"

#include "Clean.h" // formatNumber
#include "MeshWriter.h"
#include "OutputFile.h"
#include "Overlay.h" // gammaForMinAngle, minAngleForGamma
#include "OverlayStitchArrayNames.h"
#include "OverlayStitchSeeds.h"
#include "PolyReader.h"
#include "StagedOutput.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#if defined(__unix__) || defined(__APPLE__)
#include <sys/stat.h>
#include <unistd.h> // access
#endif
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

#ifndef OSM_VERSION
#define OSM_VERSION "unknown"
#endif

namespace Names = OverlayStitchArrayNames;

namespace
{

// zlib level 1 writes a mesh in about half the time of VTK's default level 5,
// for files about 2% larger (aust.poly's 1.3 million triangles: 4.7 s -> 2.4 s,
// 49.9 -> 50.8 MB); LZ4 is faster still but 40% larger and less widely read.
constexpr int kZLibLevel = 1;

const char* const Usage =
  R"(Usage: osm-mesh INPUT [-o OUTPUT] [--domain auto|enclosed|hull|box]
                [--min-angle DEG | --gamma G] [--max-edge H] [--no-resolve]
                [--merge-tolerance D] [--max-steiner N] [--project-xy]
                [--region-areas] [--no-holes] [--gap-ratio] [--no-point-data]
                [--stats]
                [--svg FILE]
                [--help] [--version]

Mesh a Planar Straight Line Graph with Overlay Stitch Meshing: a conforming
triangulation in which no angle exceeds 180 - theta2 degrees (about 170 at
the default --min-angle 30).

INPUT                  Triangle .poly (holes honoured) or .node file, or
                       .vtp / .vtu / .vtk polydata or unstructured grid
                       (lines and polylines are segments, polygons give
                       their edges, every point kept; quadratic, cubic
                       and Lagrange cells read through their nodes;
                       volumes and Bezier cells ignored)
  -o, --output FILE    write the mesh, in the format of FILE's extension:
                       .vtp, .vtu (VTK XML, zlib level 1), .vtk (legacy VTK),
                       or .node (Triangle: FILE.node, .ele, .edge and .poly
                       side by side, numbered as Triangle does: node i is
                       input point i, from the input file's first index; the
                       .poly, as Triangle's -p writes it, lists the mesh's
                       input subsegments and boundary edges, and the holes
                       and regions, unless it is the input file)
  --domain MODE        auto (default: enclosed if segments enclose a region
                       with an input point on its boundary, else hull;
                       where they cross, specks do not count), enclosed,
                       hull or box (a square 4 times the input's larger
                       extent on a side, centred on it)
  --min-angle DEG      theta1, the overlay's smallest angle: 1 to 35 (default 30;
                       above 30 no guarantee: the mesh grows fast, and from
                       about 32.5 (31.7 with --gap-ratio) the refinement may
                       not end). Not Triangle's -q: the output's smallest
                       angle is not bounded (input angles stay), its largest is
  --gamma G            the overlay's radius/edge bound instead:
                       theta1 = asin(1/(2G)), G from 0.8718 to 28.64
  --max-edge H         no edge longer than H: refine the overlay, split the
                       few longer completed edges (default 0: no limit)
  --no-resolve         crossing segments are an error (default: split them)
  --merge-tolerance D  merge points at most D apart, and split segments at
                       points within D of them; crossings of segments within
                       D of a point or crossing join it (default 0:
                       exact duplicates)
  --max-steiner N      fail if the overlay of a meshing round needs more than
                       N Steiner points (as the statistic OverlaySteinerPoints
                       counts them for the last round, its padding box's 4
                       corners included; 0: no cap)
  --project-xy         mesh the projection onto the XY plane of input points
                       not in a plane z = constant, at their mean z, their z
                       kept as point data InputZ (default: points in a
                       tilted plane are meshed in it, others are an error)
  --region-areas       apply the maximum areas of a .poly's region lines to
                       their regions, as Triangle's -a (default: ignored,
                       with a warning); a line without one takes its
                       attribute as the area, as in Triangle
  --no-holes           ignore the input's hole points, as Triangle's -O
                       (default: every region holding one is removed)
  --gap-ratio          refine the overlay to the paper's gap-ratio quality,
                       the premise of its proof of the bound, at once (up to
                       12.5 times the triangles on real inputs; default: the
                       radius/edge quality, and a mesh from it with an angle
                       above the bound is made again from a gap-ratio overlay)
  --no-point-data      do not carry the input's point data (a .poly's vertex
                       attributes and markers) to the mesh, nor its polygons'
                       cell data, nor its segment markers to .edge (default:
                       input vertices keep theirs, new points take them
                       linear along their segment or in the triangle of those
                       around them; markers as Triangle's: a segment's on it,
                       else 1 on the mesh's boundary, else 0; a triangle its
                       innermost polygon's)
  --stats              print the run statistics as JSON on stdout
  --svg FILE           draw the mesh: input segments bold, discarded overlay
                       edges dashed
  -h, --help           print this help and exit
  --version            print the version and exit

Written files hold no timings, so the same input gives the same bytes.
Exit status: 0 on success, 1 if the input cannot be read or meshed or the
output cannot be written, 2 for a bad command line; the reason is one line
"osm-mesh: ..." on stderr. Warnings go to stderr as "osm-mesh: warning: ...".
)";

/// Raised for any failure; main() prints it as the one line on stderr.
struct Failure
{
  std::string message;
  int status;
};

[[noreturn]] void Fail(const std::string& message, int status = 1)
{
  throw Failure{ message, status };
}

/// VTK's messages come as "ERROR: In file, line N\nclass (0x...): text\n\n".
/// Keep only the text, on one line.
std::string CleanMessage(const char* raw)
{
  std::string text = raw ? raw : "";
  const char* const headers[] = { "ERROR: In ", "Warning: In ", "Generic Warning: In " };
  for (const char* header : headers)
  {
    if (text.compare(0, std::strlen(header), header) == 0)
    {
      const std::size_t newline = text.find('\n');
      text = newline == std::string::npos ? std::string() : text.substr(newline + 1);
      break;
    }
  }
  // "vtkSomeClass (0x1234abcd): " before the text proper.
  const std::size_t open = text.find(" (0x");
  const std::size_t close = text.find("): ");
  if (open != std::string::npos && close != std::string::npos && open < close &&
    text.find('\n') > close)
  {
    bool identifier = open > 0;
    for (std::size_t i = 0; i < open; ++i)
    {
      identifier = identifier &&
        (std::isalnum(static_cast<unsigned char>(text[i])) || text[i] == '_' || text[i] == ':');
    }
    if (identifier)
    {
      text = text.substr(close + 3);
    }
  }
  std::string line;
  for (char c : text)
  {
    const bool space = c == '\n' || c == '\r' || c == '\t' || c == ' ';
    if (space)
    {
      if (!line.empty() && line.back() != ' ')
      {
        line += ' ';
      }
    }
    else
    {
      line += c;
    }
  }
  while (!line.empty() && line.back() == ' ')
  {
    line.pop_back();
  }
  return line;
}

/// Replaces VTK's output window: warnings go to stderr with our prefix, the
/// first error is kept for the one-line failure message, the rest is dropped.
class OsmOutputWindow : public vtkOutputWindow
{
public:
  static OsmOutputWindow* New();
  vtkTypeMacro(OsmOutputWindow, vtkOutputWindow);

  void DisplayText(const char*) override {}
  void DisplayDebugText(const char*) override {}
  void DisplayErrorText(const char* text) override
  {
    if (this->FirstError.empty())
    {
      this->FirstError = CleanMessage(text);
    }
    ++this->Errors;
  }
  void DisplayWarningText(const char* text) override { this->Warn(text); }
  void DisplayGenericWarningText(const char* text) override { this->Warn(text); }

  bool HasErrors() const { return this->Errors > 0; }
  /// Forgets the errors reported so far.
  void Reset()
  {
    this->Errors = 0;
    this->FirstError.clear();
  }

  /// Fails with the first error, if any was reported since the last call,
  /// after prefix (e.g. "cannot read 'a.vtp': ").
  void Check(const std::string& prefix, const std::string& context)
  {
    if (this->Errors > 0)
    {
      const std::string message =
        this->Numbered(prefix + (this->FirstError.empty() ? context : this->FirstError));
      this->Errors = 0;
      this->FirstError.clear();
      Fail(message);
    }
  }

  std::vector<std::string> Warnings;
  /// --stats was given: a failure prints its JSON too, with "ok": false.
  bool Stats = false;
  /// The input file's path, named in the filter's note on a file that counts
  /// from 1 ("...; the input counts from 1)").
  std::string InputPath;

protected:
  OsmOutputWindow() = default;
  ~OsmOutputWindow() override = default;

private:
  std::string Numbered(std::string message) const
  {
    const std::string generic = "; the input counts from 1)";
    const std::size_t at = message.find(generic);
    if (at != std::string::npos && !this->InputPath.empty())
    {
      message.replace(at, generic.size(), "; " + this->InputPath + " counts from 1)");
    }
    return message;
  }

  void Warn(const char* text)
  {
    const std::string message = this->Numbered(CleanMessage(text));
    this->Warnings.push_back(message);
    std::cerr << "osm-mesh: warning: " << message << "\n";
  }

  int Errors = 0;
  std::string FirstError;

  OsmOutputWindow(const OsmOutputWindow&) = delete;
  void operator=(const OsmOutputWindow&) = delete;
};
vtkStandardNewMacro(OsmOutputWindow);

struct Arguments
{
  std::string input;
  std::string output;
  std::string svg;
  int domain = vtkOverlayStitchMesher::DOMAIN_AUTO;
  bool minAngleGiven = false;
  bool gammaGiven = false;
  double minAngle = 30.0;
  double maxEdge = 0.0;
  bool resolve = true;
  bool projectXY = false;
  bool regionAreas = false;
  bool holes = true;
  bool gapRatio = false;
  bool pointData = true;
  double mergeTolerance = 0.0;
  long long maxSteiner = 0;
  bool stats = false;
  /// A .node output's .poly is the input file, which it must not replace.
  bool polyIsInput = false;
};

std::string Lower(std::string s)
{
  for (char& c : s)
  {
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  }
  return s;
}

/// The extension, lower case, with its dot ("" if none).
std::string Extension(const std::string& path)
{
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash))
  {
    return std::string();
  }
  return Lower(path.substr(dot));
}

double ParseNumber(const std::string& option, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(begin, &end);
  // strtod also reads hexadecimal ("0x10" is 16), which nobody means here.
  if (text.empty() || end != begin + text.size() ||
    std::isspace(static_cast<unsigned char>(*begin)) || text.find_first_of("xX") != text.npos)
  {
    Fail(option + ": expected a number, got '" + text + "'", 2);
  }
  // strtod flags subnormal results too (1e-310): those are numbers; a text
  // that rounds to 0 or to infinity is not in range.
  const bool subnormal = value != 0 && std::fabs(value) < DBL_MIN;
  if (!std::isfinite(value) || (errno == ERANGE && !subnormal))
  {
    Fail(option + ": " + text + " is not a finite number in range", 2);
  }
  return value;
}

long long ParseCount(const std::string& option, const std::string& text)
{
  const char* begin = text.c_str();
  char* end = nullptr;
  errno = 0;
  const long long value = std::strtoll(begin, &end, 10);
  if (text.empty() || end != begin + text.size() ||
    !std::isdigit(static_cast<unsigned char>(*begin)))
  {
    Fail(option + ": expected a non-negative integer, got '" + text + "'", 2);
  }
  if (errno == ERANGE)
  {
    Fail(option + ": " + text + " is too large", 2);
  }
  return value;
}

std::string Number(double value)
{
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.10g", value);
  return buf;
}

/// A file, or the folder a new file goes into, that the user may not write
/// to (its permissions, a read-only file system) fails here, not after
/// minutes of meshing.
void FailIfNotWritable(const std::string& path, const std::string& folder)
{
#if defined(__unix__) || defined(__APPLE__)
  std::error_code ec;
  const std::string& target = std::filesystem::exists(path, ec) ? path : folder;
  const int error = access(target.c_str(), W_OK) == 0 ? 0 : errno;
  if (error == EACCES || error == EPERM || error == EROFS)
  {
    Fail("cannot write '" + path + "': " + std::generic_category().message(error) +
      (target == path ? "" : " (in '" + folder + "')") + "; nothing is meshed or written");
  }
#endif
}

/// Fails, before meshing, which can take long, if path cannot be a file: a
/// directory is there, or its folder is missing or not a directory (as the
/// system resolves it: "missing/../x" has none), or it may not be written.
void FailIfNoFolderFor(const std::string& path)
{
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
  {
    Fail("cannot write '" + path + "': " + std::generic_category().message(EISDIR));
  }
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (folder.empty() || std::filesystem::is_directory(folder, ec))
  {
    FailIfNotWritable(path, folder.empty() ? "." : folder.string());
    return;
  }
  const bool exists = std::filesystem::exists(folder, ec);
  Fail("cannot write '" + path +
    "': " + std::generic_category().message(exists ? ENOTDIR : ENOENT) + " ('" + folder.string() +
    "' " + (exists ? "is not a directory" : "does not exist") + "; nothing is meshed or written)");
}

/// Where writing to path lands: absolute, normalised, through symbolic links
/// (a dangling one too: it names the file a write creates).
std::filesystem::path Resolved(const std::filesystem::path& path)
{
  std::error_code ec;
  const std::filesystem::path p = osm::linkTarget(std::filesystem::absolute(path, ec));
  // (weakly_canonical leaves a relative path to a new file relative.)
  const std::filesystem::path resolved = std::filesystem::weakly_canonical(p, ec);
  return ec ? p.lexically_normal() : resolved;
}

/// Whether a .poly file's first line (after comments) lists 0 vertices, which
/// it then reads from the .node file beside it.
bool ListsNoVertices(const std::string& path)
{
  // Not a pipe (opening one waits for a writer) or a device: refused later.
  struct stat info;
  if (stat(path.c_str(), &info) != 0 || !S_ISREG(info.st_mode))
  {
    return false;
  }
  // Read as the reader reads it (a review: '.0' and CR-only files were
  // missed by a check of its own here, and their .node overwritten).
  std::ifstream file(path, std::ios::binary);
  return osm::polyListsNoVertices(file);
}

/// One command-line argument: "--name=value" split at its '=', and the
/// argument after it taken as the value where the option needs one.
class Option
{
public:
  Option(int argc, char* argv[], int& i)
    : Argc(argc)
    , Argv(argv)
    , I(i)
    , Name(argv[i])
  {
    if (this->Name.size() > 2 && this->Name.compare(0, 2, "--") == 0)
    {
      const std::size_t eq = this->Name.find('=');
      if (eq != std::string::npos)
      {
        this->Value = this->Name.substr(eq + 1);
        this->Name = this->Name.substr(0, eq);
        this->HasValue = true;
      }
    }
  }

  const std::string& name() const { return this->Name; }

  std::string value()
  {
    if (this->HasValue)
    {
      return this->Value;
    }
    if (this->I + 1 >= this->Argc)
    {
      Fail(this->Name + " needs a value (see --help)", 2);
    }
    // An option next is a value forgotten (--svg --stats), not a file name.
    const std::string next = this->Argv[this->I + 1];
    if (next.size() > 2 && next.compare(0, 2, "--") == 0)
    {
      Fail(this->Name + " needs a value, not the option " + next +
          " (a file named so: " + this->Name + "=" + next + " or ./" + next + ")",
        2);
    }
    return this->Argv[++this->I];
  }

  void noValue() const
  {
    if (this->HasValue)
    {
      Fail(this->Name + " takes no value", 2);
    }
  }

private:
  int Argc;
  char** Argv;
  int& I;
  std::string Name;
  std::string Value;
  bool HasValue = false;
};

int DomainNamed(const std::string& mode)
{
  if (mode == "auto")
  {
    return vtkOverlayStitchMesher::DOMAIN_AUTO;
  }
  if (mode == "enclosed")
  {
    return vtkOverlayStitchMesher::DOMAIN_ENCLOSED;
  }
  if (mode == "hull")
  {
    return vtkOverlayStitchMesher::DOMAIN_HULL;
  }
  if (mode == "box")
  {
    return vtkOverlayStitchMesher::DOMAIN_BOX;
  }
  Fail("--domain: expected auto, enclosed, hull or box, got '" + mode + "'", 2);
}

/// Sets the flag an option without a value names; false if it names none.
bool ReadFlag(Option& option, Arguments& args)
{
  static const std::pair<const char*, std::pair<bool Arguments::*, bool>> Flags[] = {
    { "--no-resolve", { &Arguments::resolve, false } },
    { "--project-xy", { &Arguments::projectXY, true } },
    { "--region-areas", { &Arguments::regionAreas, true } },
    { "--no-holes", { &Arguments::holes, false } },
    { "--gap-ratio", { &Arguments::gapRatio, true } },
    { "--no-point-data", { &Arguments::pointData, false } },
    { "--stats", { &Arguments::stats, true } },
  };
  for (const auto& [name, flag] : Flags)
  {
    if (option.name() == name)
    {
      option.noValue();
      args.*flag.first = flag.second;
      return true;
    }
  }
  return false;
}

/// Reads an option that takes a value; false if it is none of them.
bool ReadValueOption(Option& option, Arguments& args, double& gamma)
{
  const std::string& arg = option.name();
  if (arg == "-o" || arg == "--output")
  {
    // One mesh per run: a second -o wrote only the last file (a review).
    const std::string earlier = args.output;
    args.output = option.value();
    if (!earlier.empty())
    {
      Fail("more than one output file: '" + earlier + "' and '" + args.output + "'", 2);
    }
    if (args.output.empty())
    {
      Fail(arg + ": empty file name", 2);
    }
  }
  else if (arg == "--domain")
  {
    args.domain = DomainNamed(option.value());
  }
  else if (arg == "--min-angle")
  {
    args.minAngle = ParseNumber(arg, option.value());
    args.minAngleGiven = true;
    if (args.minAngle < osm::kMinAngleDegLowest || args.minAngle > osm::kMinAngleDegHighest)
    {
      Fail("--min-angle must be between 1 and 35 degrees, got " + Number(args.minAngle), 2);
    }
  }
  else if (arg == "--gamma")
  {
    gamma = ParseNumber(arg, option.value());
    args.gammaGiven = true;
  }
  else if (arg == "--max-edge")
  {
    args.maxEdge = ParseNumber(arg, option.value());
    if (args.maxEdge < 0.0)
    {
      Fail("--max-edge must be 0 (no limit) or positive, got " + Number(args.maxEdge), 2);
    }
  }
  else if (arg == "--merge-tolerance")
  {
    args.mergeTolerance = ParseNumber(arg, option.value());
    if (args.mergeTolerance < 0.0)
    {
      Fail("--merge-tolerance must be 0 or positive, got " + Number(args.mergeTolerance), 2);
    }
  }
  else if (arg == "--max-steiner")
  {
    args.maxSteiner = ParseCount(arg, option.value());
  }
  else if (arg == "--svg")
  {
    args.svg = option.value();
    if (args.svg.empty())
    {
      Fail("--svg: empty file name", 2);
    }
  }
  else
  {
    return false;
  }
  return true;
}

/// Reads the options and the input file's name into args (--gamma's value
/// into gamma); false after --help or --version.
bool ReadOptions(int argc, char* argv[], Arguments& args, double& gamma)
{
  bool inputGiven = false;
  for (int i = 1; i < argc; ++i)
  {
    Option option(argc, argv, i);
    const std::string& arg = option.name();
    if (arg == "-h" || arg == "--help" || arg == "--version")
    {
      option.noValue();
      std::cout << (arg == "--version" ? "osm-mesh " OSM_VERSION "\n" : Usage);
      return false;
    }
    if (ReadFlag(option, args) || ReadValueOption(option, args, gamma))
    {
      continue;
    }
    if (arg.size() > 1 && arg[0] == '-')
    {
      Fail("unknown option '" + arg + "' (see --help)", 2);
    }
    if (inputGiven)
    {
      Fail("more than one input file: '" + args.input + "' and '" + arg + "'", 2);
    }
    args.input = arg;
    inputGiven = true;
  }
  if (!inputGiven)
  {
    Fail("no input file (see --help)", 2);
  }
  return true;
}

/// --gamma sets the minimum angle: theta1 = asin(1 / (2 gamma)).
void SetMinAngleFromGamma(Arguments& args, double gamma)
{
  if (args.minAngleGiven && args.gammaGiven)
  {
    Fail("--min-angle and --gamma set the same thing: give only one", 2);
  }
  if (!args.gammaGiven)
  {
    return;
  }
  // theta1 must lie in [1, 35] degrees.
  const double lo = osm::gammaForMinAngle(osm::kMinAngleDegHighest);
  const double hi = osm::gammaForMinAngle(osm::kMinAngleDegLowest);
  if (!(gamma >= lo && gamma <= hi))
  {
    Fail("--gamma must be between " + Number(lo) + " and " + Number(hi) +
        " (theta1 = asin(1/(2G)) from 35 to 1 degrees), got " + Number(gamma),
      2);
  }
  args.minAngle = osm::minAngleForGamma(gamma);
  // Rounding at the ends of the range must not fall outside the filter's clamp.
  args.minAngle =
    std::min(osm::kMinAngleDegHighest, std::max(osm::kMinAngleDegLowest, args.minAngle));
}

/// The files a run writes (a .node output's .ele, .edge and .poly beside
/// it); sets args.polyIsInput.
std::vector<std::string> FilesWritten(Arguments& args)
{
  std::vector<std::string> written;
  if (Extension(args.output) == ".node")
  {
    const std::string base = args.output.substr(0, args.output.size() - 5);
    written = { base + ".node", base + ".ele", base + ".edge" };
    // Beside them the mesh's segments (Triangle's -p), unless that file is
    // the input: "osm-mesh square.poly -o square.node" keeps square.poly.
    const std::string poly = base + ".poly";
    std::error_code ec;
    args.polyIsInput = std::filesystem::equivalent(poly, args.input, ec) && !ec;
    if (!args.polyIsInput)
    {
      written.push_back(poly);
    }
  }
  else if (!args.output.empty())
  {
    written = { args.output };
  }
  if (!args.svg.empty())
  {
    written.push_back(args.svg);
  }
  return written;
}

/// Never overwrite the input (e.g. "osm-mesh points.node -o points.node"),
/// nor write one file twice.
void FailIfWrittenTwiceOrRead(const Arguments& args, const std::vector<std::string>& written)
{
  // A .poly file without vertices reads them from the .node beside it.
  std::vector<std::string> read = { args.input };
  if (Extension(args.input) == ".poly" && ListsNoVertices(args.input))
  {
    read.push_back(args.input.substr(0, args.input.size() - 5) + ".node");
  }
  std::vector<std::filesystem::path> targets;
  for (const std::string& path : written)
  {
    for (const std::string& input : read)
    {
      std::error_code ec;
      if (std::filesystem::equivalent(path, input, ec) && !ec)
      {
        Fail("'" + path + "' is " +
            (input == args.input ? "the input file"
                                 : "the .node file the input reads its vertices from") +
            ": choose another output name",
          2);
      }
    }
    const std::filesystem::path target = Resolved(path);
    if (std::find(targets.begin(), targets.end(), target) != targets.end())
    {
      Fail("'" + path + "' would be written twice (-o and --svg): choose another name", 2);
    }
    targets.push_back(target);
  }
}

/// The input must be a regular file of a kind read, the output of a kind written.
void FailIfUnknownKinds(const Arguments& args)
{
  const std::string in = Extension(args.input);
  if (in != ".poly" && in != ".node" && in != ".vtp" && in != ".vtu" && in != ".vtk")
  {
    Fail("cannot read '" + args.input + "': the input must end in .poly, .node, .vtp, .vtu or .vtk",
      2);
  }
  // The input is opened more than once (and reading a device may not end): a
  // pipe is read empty the second time, or its open waits for ever (a
  // review). stat() does not open it.
  struct stat info;
  if (stat(args.input.c_str(), &info) == 0 && !S_ISREG(info.st_mode))
  {
    Fail("cannot read '" + args.input + "': " +
      (S_ISDIR(info.st_mode) ? std::string("it is a directory")
                             : std::string("it is not a regular file (a pipe or a device), and "
                                           "osm-mesh reads its input more than once: save it "
                                           "to a file first")));
  }
  if (!args.output.empty())
  {
    const std::string out = Extension(args.output);
    if (out != ".vtp" && out != ".vtu" && out != ".vtk" && out != ".node")
    {
      Fail(
        "cannot write '" + args.output + "': the output must end in .vtp, .vtu, .vtk or .node", 2);
    }
  }
}

/// Reads the command line into args; false after --help or --version. Past
/// the options, the files are checked, and a check failing with --stats
/// prints its JSON too (window->Stats).
bool ParseArguments(int argc, char* argv[], Arguments& args, OsmOutputWindow* window)
{
  double gamma = 0.0;
  if (!ReadOptions(argc, argv, args, gamma))
  {
    return false;
  }
  // A script reading --stats gets its JSON for an output it cannot write
  // too (a review: a missing output folder printed none).
  window->Stats = args.stats;
  SetMinAngleFromGamma(args, gamma);
  const std::vector<std::string> written = FilesWritten(args);
  FailIfWrittenTwiceOrRead(args, written);
  FailIfUnknownKinds(args);
  for (const std::string& path : written)
  {
    FailIfNoFolderFor(path);
  }
  return true;
}

/// A legacy reader reads only the first SCALARS, VECTORS, ... section of each
/// kind unless told otherwise; ParaView's reads them all, and so do we, so
/// that no array is dropped without a word.
void ReadEveryArray(vtkDataReader* reader)
{
  reader->ReadAllScalarsOn();
  reader->ReadAllVectorsOn();
  reader->ReadAllNormalsOn();
  reader->ReadAllTensorsOn();
  reader->ReadAllColorScalarsOn();
  reader->ReadAllTCoordsOn();
  reader->ReadAllFieldsOn();
}

/// The input reader, chosen by extension; the file must exist.
vtkSmartPointer<vtkAlgorithm> MakeReader(const std::string& path)
{
  {
    std::ifstream probe(path);
    if (!probe)
    {
      const int error = errno;
      Fail("cannot open '" + path +
        "': " + (error ? std::generic_category().message(error) : std::string("unreadable")));
    }
  }
  const std::string ext = Extension(path);
  if (ext == ".poly" || ext == ".node")
  {
    auto reader = vtkSmartPointer<vtkTrianglePolyReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == ".vtp")
  {
    auto reader = vtkSmartPointer<vtkXMLPolyDataReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  if (ext == ".vtu")
  {
    auto reader = vtkSmartPointer<vtkXMLUnstructuredGridReader>::New();
    reader->SetFileName(path.c_str());
    return reader;
  }
  auto reader = vtkSmartPointer<vtkPolyDataReader>::New();
  reader->SetFileName(path.c_str());
  if (reader->IsFilePolyData())
  {
    ReadEveryArray(reader);
    return reader;
  }
  auto grid = vtkSmartPointer<vtkUnstructuredGridReader>::New();
  grid->SetFileName(path.c_str());
  if (!grid->IsFileUnstructuredGrid())
  {
    Fail("'" + path + "' is not a legacy VTK polydata or unstructured grid file");
  }
  ReadEveryArray(grid);
  return grid;
}

/// A copy of the mesh without the run's timings (field data "Seconds*"), so
/// that written files are the same for the same input.
vtkSmartPointer<vtkPolyData> WithoutTimings(vtkPolyData* mesh)
{
  auto copy = vtkSmartPointer<vtkPolyData>::New();
  copy->ShallowCopy(mesh);
  vtkNew<vtkFieldData> fields;
  vtkFieldData* source = mesh->GetFieldData();
  for (int a = 0; a < source->GetNumberOfArrays(); ++a)
  {
    vtkAbstractArray* array = source->GetAbstractArray(a);
    const char* name = array ? array->GetName() : nullptr;
    if (name && std::strncmp(name, "Seconds", 7) == 0)
    {
      continue;
    }
    fields->AddArray(array);
  }
  copy->SetFieldData(fields);
  return copy;
}

/// The filter's Mesh and Edges outputs as the core's result, for its writers.
osm::Result ToResult(vtkPolyData* mesh, vtkPolyData* edges)
{
  osm::Result r;
  r.ok = true;
  const vtkIdType numberOfPoints = mesh->GetNumberOfPoints();
  r.mesh.vertices.resize(static_cast<std::size_t>(numberOfPoints));
  r.vertexOrigin.assign(static_cast<std::size_t>(numberOfPoints), osm::VertexOrigin::Other);
  vtkDataArray* origin = mesh->GetPointData()->GetArray(Names::VertexOrigin);
  for (vtkIdType i = 0; i < numberOfPoints; ++i)
  {
    double p[3];
    mesh->GetPoint(i, p);
    r.mesh.vertices[static_cast<std::size_t>(i)] = osm::Point{ p[0], p[1] };
    if (origin)
    {
      r.vertexOrigin[static_cast<std::size_t>(i)] =
        static_cast<osm::VertexOrigin>(static_cast<int>(origin->GetComponent(i, 0)));
    }
  }
  vtkDataArray* region = mesh->GetCellData()->GetArray(Names::RegionId);
  vtkDataArray* attribute = mesh->GetCellData()->GetArray(Names::RegionAttribute);
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  vtkIdType cellId = mesh->GetNumberOfVerts() + mesh->GetNumberOfLines();
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell(), ++cellId)
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    cells->GetCurrentCell(n, ids);
    if (n != 3)
    {
      Fail("internal error: the mesh has a cell with " + std::to_string(n) + " points");
    }
    r.mesh.triangles.push_back(
      { static_cast<int>(ids[0]), static_cast<int>(ids[1]), static_cast<int>(ids[2]) });
    r.regionId.push_back(region ? static_cast<int>(region->GetComponent(cellId, 0)) : 0);
    if (attribute)
    {
      r.regionAttribute.push_back(attribute->GetComponent(cellId, 0));
    }
  }

  if (edges && edges->GetNumberOfPoints() > 0)
  {
    r.edgeVertices.resize(static_cast<std::size_t>(edges->GetNumberOfPoints()));
    for (vtkIdType i = 0; i < edges->GetNumberOfPoints(); ++i)
    {
      double p[3];
      edges->GetPoint(i, p);
      r.edgeVertices[static_cast<std::size_t>(i)] = osm::Point{ p[0], p[1] };
    }
    vtkCellData* cd = edges->GetCellData();
    const std::pair<const char*, std::uint8_t> flags[] = { { Names::Overlay, osm::EdgeOverlay },
      { Names::Kept, osm::EdgeKept }, { Names::Discarded, osm::EdgeDiscarded },
      { Names::Input, osm::EdgeInput } };
    auto lines = vtk::TakeSmartPointer(edges->GetLines()->NewIterator());
    vtkIdType lineId = edges->GetNumberOfVerts();
    for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++lineId)
    {
      vtkIdType n = 0;
      const vtkIdType* ids = nullptr;
      lines->GetCurrentCell(n, ids);
      if (n != 2)
      {
        continue;
      }
      osm::Edge e;
      e.a = static_cast<int>(ids[0]);
      e.b = static_cast<int>(ids[1]);
      for (const auto& flag : flags)
      {
        vtkDataArray* array = cd->GetArray(flag.first);
        if (array && array->GetComponent(lineId, 0) != 0.0)
        {
          e.flags |= flag.second;
        }
      }
      r.edges.push_back(e);
    }
  }
  return r;
}

vtkSmartPointer<vtkUnstructuredGrid> ToUnstructuredGrid(vtkPolyData* mesh)
{
  auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
  grid->SetPoints(mesh->GetPoints());
  grid->Allocate(mesh->GetNumberOfPolys());
  auto cells = vtk::TakeSmartPointer(mesh->GetPolys()->NewIterator());
  for (cells->GoToFirstCell(); !cells->IsDoneWithTraversal(); cells->GoToNextCell())
  {
    vtkIdType n = 0;
    const vtkIdType* ids = nullptr;
    cells->GetCurrentCell(n, ids);
    grid->InsertNextCell(VTK_TRIANGLE, n, ids);
  }
  // The mesh has triangles only, so its cell data lines up with the grid's cells.
  grid->GetPointData()->ShallowCopy(mesh->GetPointData());
  grid->GetCellData()->ShallowCopy(mesh->GetCellData());
  grid->GetFieldData()->ShallowCopy(mesh->GetFieldData());
  return grid;
}

/// The .node file's vertex attributes and markers, as Triangle writes them:
/// the mesh's point arrays Attribute0, Attribute1, ... (the .poly reader's,
/// carried to the mesh by the filter) and PointMarker, when it has them;
/// and the .edge file's markers, the Edges output's SegmentMarker.
osm::NodeData NodeDataOf(vtkPolyData* mesh, vtkPolyData* edges)
{
  osm::NodeData data;
  vtkPointData* pd = mesh->GetPointData();
  std::vector<vtkDataArray*> attributes;
  for (vtkDataArray* a = pd->GetArray("Attribute0"); a && a->GetNumberOfComponents() == 1;
       a = pd->GetArray(("Attribute" + std::to_string(attributes.size())).c_str()))
  {
    attributes.push_back(a);
  }
  const vtkIdType n = mesh->GetNumberOfPoints();
  data.attributeCount = attributes.size();
  data.attributes.reserve(static_cast<std::size_t>(n) * attributes.size());
  for (vtkIdType v = 0; v < n; ++v)
  {
    for (vtkDataArray* a : attributes)
    {
      data.attributes.push_back(a->GetComponent(v, 0));
    }
  }
  vtkDataArray* markers = pd->GetArray(Names::PointMarker);
  if (markers && markers->GetNumberOfComponents() == 1)
  {
    for (vtkIdType v = 0; v < n; ++v)
    {
      data.markers.push_back(static_cast<int>(markers->GetComponent(v, 0)));
    }
  }
  // The Edges output's segment markers, per line as ToResult lists them.
  vtkDataArray* edgeMarkers =
    edges ? edges->GetCellData()->GetArray(Names::SegmentMarker) : nullptr;
  if (edgeMarkers)
  {
    auto lines = vtk::TakeSmartPointer(edges->GetLines()->NewIterator());
    vtkIdType lineId = edges->GetNumberOfVerts();
    for (lines->GoToFirstCell(); !lines->IsDoneWithTraversal(); lines->GoToNextCell(), ++lineId)
    {
      if (lines->GetCurrentCell()->GetNumberOfIds() == 2)
      {
        data.edgeMarkers.push_back(static_cast<int>(edgeMarkers->GetComponent(lineId, 0)));
      }
    }
  }
  return data;
}

/// Renumbers r and data as Triangle numbers its output: node i is input point
/// i (by the mesh's InputPointId), those no triangle uses written too, with
/// their own coordinates, attributes and markers (merged duplicates, points
/// in holes: Triangle writes them unless -j), then the other vertices in the
/// mesh's order; numbers from the input file's first index.
void ToTriangleNumbering(osm::Result& r, osm::NodeData& data, vtkPolyData* mesh, vtkPointSet* input)
{
  vtkDataArray* first = input->GetFieldData()->GetArray(Names::FileFirstIndex);
  data.firstIndex =
    first && first->GetNumberOfTuples() == 1 && first->GetComponent(0, 0) == 0 ? 0 : 1;
  auto* inputIds =
    vtkIdTypeArray::SafeDownCast(mesh->GetPointData()->GetArray(Names::InputPointId));
  const std::size_t inputs = static_cast<std::size_t>(input->GetNumberOfPoints());
  const std::size_t vertices = r.mesh.vertices.size();
  if (!inputIds || static_cast<std::size_t>(inputIds->GetNumberOfTuples()) != vertices)
  {
    return;
  }
  std::vector<int> node(vertices, -1);
  std::vector<int> meshVertex(inputs, -1);
  int next = static_cast<int>(inputs);
  for (std::size_t v = 0; v < vertices; ++v)
  {
    const vtkIdType i = inputIds->GetValue(static_cast<vtkIdType>(v));
    if (i >= 0 && static_cast<std::size_t>(i) < inputs && meshVertex[i] < 0)
    {
      meshVertex[i] = static_cast<int>(v);
      node[v] = static_cast<int>(i);
    }
    else
    {
      node[v] = next++;
    }
  }
  const std::size_t nodes = static_cast<std::size_t>(next);
  osm::Array<osm::Point> points(nodes);
  const std::size_t k = data.attributeCount;
  std::vector<double> attributes(nodes * k, 0.0);
  std::vector<int> markers(data.markers.empty() ? 0 : nodes, 0);
  vtkPointData* in = input->GetPointData();
  vtkDataArray* inMarkers = in->GetArray(Names::PointMarker);
  for (std::size_t i = 0; i < inputs; ++i)
  {
    if (meshVertex[i] >= 0)
    {
      continue;
    }
    double p[3];
    input->GetPoint(static_cast<vtkIdType>(i), p);
    points[i] = osm::Point{ p[0], p[1] };
    for (std::size_t a = 0; a < k; ++a)
    {
      vtkDataArray* attribute = in->GetArray(("Attribute" + std::to_string(a)).c_str());
      attributes[i * k + a] =
        attribute ? attribute->GetComponent(static_cast<vtkIdType>(i), 0) : 0.0;
    }
    if (!markers.empty() && inMarkers)
    {
      markers[i] = static_cast<int>(inMarkers->GetComponent(static_cast<vtkIdType>(i), 0));
    }
  }
  for (std::size_t v = 0; v < vertices; ++v)
  {
    const auto to = static_cast<std::size_t>(node[v]);
    points[to] = r.mesh.vertices[v];
    std::copy_n(data.attributes.begin() + static_cast<std::ptrdiff_t>(v * k), k,
      attributes.begin() + static_cast<std::ptrdiff_t>(to * k));
    if (!markers.empty())
    {
      markers[to] = data.markers[v];
    }
  }
  for (osm::Triangle& t : r.mesh.triangles)
  {
    t = { node[static_cast<std::size_t>(t[0])], node[static_cast<std::size_t>(t[1])],
      node[static_cast<std::size_t>(t[2])] };
  }
  r.mesh.vertices = std::move(points);
  data.attributes = std::move(attributes);
  data.markers = std::move(markers);
}

/// A .node file holds a .poly's numbered vertex attributes and markers (as
/// NodeDataOf takes them: Attribute0, Attribute1, ... of one component each,
/// PointMarker of one), and an .ele file region ids: say which of the mesh's
/// other arrays (a .vtp input's point data, polygon cell data) it leaves out.
void WarnNotInNodeFiles(vtkPolyData* mesh, const osm::NodeData& data, OsmOutputWindow* window)
{
  std::vector<std::string> points(Names::MeshPointArrays.begin(), Names::MeshPointArrays.end());
  points.emplace_back(Names::InputBlockId);
  for (std::size_t a = 0; a < data.attributeCount; ++a)
  {
    points.push_back("Attribute" + std::to_string(a));
  }
  if (!data.markers.empty())
  {
    points.emplace_back(Names::PointMarker);
  }
  std::string left;
  auto note = [&left](
                vtkFieldData* arrays, const char* kind, const std::vector<std::string>& written) {
    for (int a = 0; a < arrays->GetNumberOfArrays(); ++a)
    {
      const char* name = arrays->GetAbstractArray(a)->GetName();
      const std::string text = name ? name : "(unnamed)";
      if (std::find(written.begin(), written.end(), text) == written.end())
      {
        left += (left.empty() ? "" : ", ") + std::string(kind) + " " + text;
      }
    }
  };
  note(mesh->GetPointData(), "point data", points);
  std::vector<std::string> cells(Names::MeshCellArrays.begin(), Names::MeshCellArrays.end());
  cells.emplace_back(Names::InputBlockId);
  note(mesh->GetCellData(), "cell data", cells);
  if (!left.empty())
  {
    window->DisplayWarningText(
      ("not written to the .node/.ele files, which hold a .poly's numbered vertex attributes "
       "(Attribute0, Attribute1, ... of one component) and markers and the region ids only: " +
        left + " (write .vtp, .vtu or .vtk to keep them)")
        .c_str());
  }
}

/// How a failed write's message ends: what became of the partial file, and
/// of a file it was to replace where it was written beside it; more adds to
/// the note.
std::string Removed(bool removed, bool oldKept, const std::string& more = "")
{
  return removed ? " (the partial file is removed" +
      std::string(oldKept ? "; the old one is kept" : "") + more + ")"
                 : "";
}

/// The input's hole and region seeds (its HolePoints and RegionAttributes
/// field data, as the .poly reader makes them) as the filter takes them,
/// moved with the points (SeedReferencePoints), for the output .poly; no
/// holes when they were not used (a review: --no-holes, or a 4-component
/// array the filter ignores, wrote holes that meshing the .poly again used).
void SeedsOf(vtkPointSet* input, bool useHoles, osm::NodeData& data)
{
  std::string note;
  vtkSmartPointer<vtkDataObject> moved =
    input ? OverlayStitchSeedsFollowingPoints(input, note) : nullptr;
  vtkDataObject* seeds = moved ? moved.GetPointer() : input;
  vtkFieldData* field = seeds ? seeds->GetFieldData() : nullptr;
  vtkDataArray* holes = field && useHoles ? field->GetArray(Names::HolePoints) : nullptr;
  if (holes && Names::IsHolePointsShape(holes->GetNumberOfComponents()))
  {
    for (vtkIdType i = 0; i < holes->GetNumberOfTuples(); ++i)
    {
      data.holes.push_back({ holes->GetComponent(i, 0), holes->GetComponent(i, 1) });
    }
  }
  vtkDataArray* regions = field ? field->GetArray(Names::RegionAttributes) : nullptr;
  const int components = regions ? regions->GetNumberOfComponents() : 0;
  if (Names::IsRegionAttributesShape(components))
  {
    for (vtkIdType i = 0; i < regions->GetNumberOfTuples(); ++i)
    {
      data.regions.push_back({ { regions->GetComponent(i, 0), regions->GetComponent(i, 1) },
        regions->GetComponent(i, 2), components == 4 ? regions->GetComponent(i, 3) : -1.0 });
    }
  }
}

void WriteMesh(const std::string& path, vtkPolyData* mesh, vtkPolyData* edges, vtkPointSet* input,
  const Arguments& args, OsmOutputWindow* window)
{
  const std::string ext = Extension(path);
  int ok = 1;
  if (ext == ".node")
  {
    const std::string base = path.substr(0, path.size() - 5);
    osm::Result result = ToResult(mesh, edges);
    osm::NodeData data = NodeDataOf(mesh, edges);
    if (input)
    {
      ToTriangleNumbering(result, data, mesh, input);
    }
    WarnNotInNodeFiles(mesh, data, window);
    SeedsOf(input, args.holes, data);
    data.writePoly = !args.polyIsInput;
    if (args.polyIsInput)
    {
      window->DisplayWarningText(("the mesh's segments are not written to " + base +
        ".poly, which is the input: name the output otherwise to have them (as Triangle "
        "numbers its outputs: -o " +
        base + ".1.node)")
                                   .c_str());
    }
    const std::string error = osm::writeTriangleFiles(base, result, data);
    if (!error.empty())
    {
      Fail(error);
    }
    return;
  }
  vtkSmartPointer<vtkPolyData> clean = WithoutTimings(mesh);
  // Written beside the file and renamed over it; where that cannot be, on a
  // failure only a file this write made or changed is removed.
  StagedOutput staged(path);
  const char* file = staged.WritePath().c_str();
  unsigned long code = vtkErrorCode::NoError;
  errno = 0;
  if (ext == ".vtp")
  {
    vtkNew<vtkXMLPolyDataWriter> writer;
    writer->SetInputData(clean);
    writer->SetFileName(file);
    writer->SetCompressionLevel(kZLibLevel);
    ok = writer->Write();
    code = writer->GetErrorCode();
  }
  else if (ext == ".vtu")
  {
    vtkNew<vtkXMLUnstructuredGridWriter> writer;
    writer->SetInputData(ToUnstructuredGrid(clean));
    writer->SetFileName(file);
    writer->SetCompressionLevel(kZLibLevel);
    ok = writer->Write();
    code = writer->GetErrorCode();
  }
  else
  {
    vtkNew<vtkPolyDataWriter> writer;
    writer->SetInputData(clean);
    writer->SetFileName(file);
    // Binary: ASCII legacy files keep about 11 significant digits, which would
    // move the input's points.
    writer->SetFileTypeToBinary();
    ok = writer->Write();
    code = writer->GetErrorCode();
  }
  if (!ok || code != vtkErrorCode::NoError || window->HasErrors())
  {
    // Say why in a line, not VTK's pipeline report, and leave no partial
    // file (a review: a full disk left one, with that report).
    const int error = errno;
    window->Reset();
    const bool removed = staged.RemoveWritten();
    const bool oldKept = staged.OldFileIntact();
    const std::string why = code == vtkErrorCode::OutOfDiskSpaceError
      ? std::string("out of disk space, or over the file size limit")
      : error != 0 ? std::generic_category().message(error)
                   : "the writer failed (VTK error code " + std::to_string(code) + ")";
    Fail("cannot write '" + path + "': " + why + Removed(removed, oldKept));
  }
  if (const int error = staged.Commit())
  {
    const bool removed = staged.RemoveWritten();
    Fail("cannot write '" + path + "': " + std::generic_category().message(error) +
      Removed(removed, staged.OldFileIntact()));
  }
}

std::string JsonString(const std::string& s)
{
  std::string out = "\"";
  for (char c : s)
  {
    if (c == '"' || c == '\\')
    {
      out += '\\';
      out += c;
    }
    else if (static_cast<unsigned char>(c) < 0x20)
    {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\u%04x", static_cast<unsigned char>(c));
      out += buf;
    }
    else
    {
      out += c;
    }
  }
  return out + "\"";
}

/// The Mesh output's statistics (its single-value field data), as JSON.
void PrintStatistics(vtkPolyData* mesh, const std::vector<std::string>& warnings)
{
  std::cout << "{\n  \"ok\": true,\n";
  vtkFieldData* fields = mesh->GetFieldData();
  char buf[64];
  for (int a = 0; a < fields->GetNumberOfArrays(); ++a)
  {
    vtkDataArray* array = fields->GetArray(a);
    if (!array || !array->GetName() || array->GetNumberOfTuples() != 1 ||
      array->GetNumberOfComponents() != 1)
    {
      continue;
    }
    const double value = array->GetComponent(0, 0);
    std::snprintf(buf, sizeof buf, "%.17g", std::isfinite(value) ? value : 0.0);
    std::cout << "  " << JsonString(array->GetName()) << ": " << buf << ",\n";
  }
  std::cout << "  \"Warnings\": [";
  for (std::size_t i = 0; i < warnings.size(); ++i)
  {
    std::cout << (i ? ", " : "") << JsonString(warnings[i]);
  }
  std::cout << "]\n}\n";
}

/// --stats after a failure: whether it succeeded, why not, and the warnings.
void PrintFailure(const std::string& error, const std::vector<std::string>& warnings)
{
  std::cout << "{\n  \"ok\": false,\n  \"Error\": " << JsonString(error) << ",\n  \"Warnings\": [";
  for (std::size_t i = 0; i < warnings.size(); ++i)
  {
    std::cout << (i ? ", " : "") << JsonString(warnings[i]);
  }
  std::cout << "]\n}\n";
}

int Run(int argc, char* argv[], OsmOutputWindow* window)
{
  Arguments args;
  if (!ParseArguments(argc, argv, args, window))
  {
    return 0;
  }

  vtkSmartPointer<vtkAlgorithm> reader = MakeReader(args.input);
  reader->Update();
  // The .poly reader's messages already say "file:line: reason".
  const std::string ext = Extension(args.input);
  window->Check(ext == ".poly" || ext == ".node" ? "" : "cannot read '" + args.input + "': ",
    "the reader failed");

  // The filter's messages say when the .poly/.node file counts from 1; they
  // name the file.
  window->InputPath = args.input;

  vtkNew<vtkOverlayStitchMesher> mesher;
  mesher->SetInputConnection(reader->GetOutputPort());
  mesher->SetMinimumAngle(args.minAngle);
  mesher->SetMaximumEdgeLength(args.maxEdge);
  mesher->SetDomain(args.domain);
  mesher->SetResolveIntersections(args.resolve);
  mesher->SetMergeTolerance(args.mergeTolerance);
  mesher->SetProjectToXYPlane(args.projectXY);
  mesher->SetApplyRegionAreas(args.regionAreas);
  mesher->SetGapRatioOverlay(args.gapRatio);
  mesher->SetUseInputHolePoints(args.holes);
  mesher->SetInterpolatePointData(args.pointData);
  mesher->SetPassCellData(args.pointData); // polygons' data, .edge markers
  mesher->SetMaximumSteinerPoints(static_cast<vtkIdType>(args.maxSteiner));
  // The edges are only written to .edge files and drawn.
  mesher->SetGenerateEdges(Extension(args.output) == ".node" || !args.svg.empty());
  mesher->SetGenerateOverlay(false);
  mesher->Update();
  window->Check("", "meshing failed");

  vtkPolyData* mesh = mesher->GetOutput(0);
  vtkPolyData* edges = mesher->GetEdgesOutput();
  if (mesh->GetNumberOfPolys() == 0)
  {
    Fail("the mesh of '" + args.input + "' is empty");
  }

  // Input in a tilted plane is meshed in that plane: x and y alone do not
  // describe it, so the 2D outputs would be wrong. Refuse before writing any.
  vtkDataArray* fitted = mesh->GetFieldData()->GetArray(Names::InputPlaneFitted);
  const bool tilted = fitted && fitted->GetNumberOfTuples() > 0 && fitted->GetComponent(0, 0) != 0;
  const bool nodeOutput = Extension(args.output) == ".node";
  if (tilted && (nodeOutput || !args.svg.empty()))
  {
    Fail("the points of '" + args.input +
      "' lie in a plane that is not z = constant, and the mesh lies in that plane; " +
      (nodeOutput ? "a .node file" : "--svg") +
      " holds x and y only: write .vtp, .vtu or .vtk, or mesh the XY projection with "
      "--project-xy");
  }
  // In a plane z = c, x and y describe the mesh, but c is lost: say so.
  const double z = mesh->GetNumberOfPoints() > 0 ? mesh->GetPoint(0)[2] : 0.0;
  if (nodeOutput && !tilted && z != 0.0)
  {
    window->DisplayWarningText(("the mesh lies in the plane z = " + osm::formatNumber(z) +
      ", and a .node file holds x and y only: z is not written")
                                 .c_str());
  }

  if (!args.output.empty())
  {
    WriteMesh(args.output, mesh, edges, vtkPointSet::SafeDownCast(reader->GetOutputDataObject(0)),
      args, window);
  }
  if (!args.svg.empty())
  {
    // The mesh file is written by now: a failure here says it is kept, and
    // leaves no partial drawing (a review: a full disk left half of one).
    const std::string kept =
      args.output.empty() ? "" : "; the mesh is written to '" + args.output + "'";
    StagedOutput staged(args.svg);
    errno = 0;
    std::ofstream svg(staged.WritePath(), std::ios::binary);
    if (svg)
    {
      osm::writeSvg(svg, ToResult(mesh, edges));
      svg.close();
    }
    const int error = svg ? staged.Commit() : errno;
    if (!svg || error != 0)
    {
      const bool removed = staged.RemoveWritten();
      Fail("cannot write '" + args.svg +
        "': " + (error != 0 ? std::generic_category().message(error) : std::string("failed")) +
        (removed           ? Removed(true, staged.OldFileIntact(), kept)
            : kept.empty() ? ""
                           : " (" + kept.substr(2) + ")"));
    }
  }
  if (args.stats)
  {
    PrintStatistics(mesh, window->Warnings);
  }
  return 0;
}

} // namespace

int main(int argc, char* argv[])
{
  // VTK's messages reach the user only through OsmOutputWindow: the logger's
  // own copy on stderr (VTK 9.2 logs errors as well) is turned off.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
  StagedOutput::HandleSignals();
#ifdef SIGXFSZ
  // Over a file size limit (ulimit -f) the default action of SIGXFSZ kills
  // the process mid-write, with no message and a partial file left. Ignored,
  // the write fails with EFBIG and is reported and cleaned up like any other.
  std::signal(SIGXFSZ, SIG_IGN);
#endif
  vtkNew<OsmOutputWindow> window;
  vtkOutputWindow::SetInstance(window);
  int status = 0;
  try
  {
    status = Run(argc, argv, window);
  }
  catch (const Failure& failure)
  {
    std::cerr << "osm-mesh: " << failure.message << "\n";
    status = failure.status;
    if (status == 1 && window->Stats)
    {
      PrintFailure(failure.message, window->Warnings);
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "osm-mesh: " << e.what() << "\n";
    status = 1;
  }
  std::cout.flush();
  if (!std::cout)
  {
    std::cerr << "osm-mesh: error while writing to standard output\n";
    status = 1;
  }
  vtkOutputWindow::SetInstance(nullptr);
  return status;
}
