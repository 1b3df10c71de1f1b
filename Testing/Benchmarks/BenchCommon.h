// What every benchmark driver shares: loading an input (a .poly/.node file or
// a generator spec), timing the meshing call, peak memory, the quality figures
// of the output, the conformity check, and the one JSON line a driver prints.
//
// A driver is `bench_<tool> <input> [--no-check]` and prints one line:
//   {"tool": ..., "input": ..., "ok": true, "seconds": ..., "out_vertices": ..., ...}
// seconds covers the meshing call only (no reading, generating or converting).
// With --no-check the output is not inspected (counts only): the runner uses it
// for repeated timing runs, whose output is the same as the first run's.
#ifndef osm_bench_BenchCommon_h
#define osm_bench_BenchCommon_h

#include "Generators.h"
#include "PolyReader.h"
#include "Predicates.h"
#include "Pslg.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <sys/resource.h>
#include <unordered_map>
#include <utility>
#include <vector>

namespace osmbench
{

// ---------------------------------------------------------------- input

inline bool endsWith(const std::string& s, const std::string& tail)
{
  if (s.size() < tail.size())
    return false;
  for (std::size_t i = 0; i < tail.size(); ++i)
  {
    const char c = s[s.size() - tail.size() + i];
    if (std::tolower(static_cast<unsigned char>(c)) != tail[i])
      return false;
  }
  return true;
}

/// A file path ending in .poly or .node is read; anything else is a generator spec.
inline bool loadInput(const std::string& spec, osm::Pslg& pslg, std::string& error)
{
  if (endsWith(spec, ".poly") || endsWith(spec, ".node"))
  {
    osm::PolyFile f = osm::readPolyFile(spec);
    if (!f.ok)
    {
      error = f.error;
      return false;
    }
    pslg = std::move(f.pslg);
    return true;
  }
  return generate(spec, pslg, error);
}

// ---------------------------------------------------------------- time, memory

/// CPU time of the whole process (every thread), in seconds.
inline double processCpuSeconds()
{
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

/// The part of the process's CPU time spent in the kernel on its behalf (page
/// faults, clearing fresh pages), in seconds. The kernel splits CPU time into user
/// and system by sampling at its tick: read it for runs of a second or more.
inline double processSystemSeconds()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_stime.tv_sec) +
    1e-6 * static_cast<double>(usage.ru_stime.tv_usec);
}

/// Wall time and process CPU time since construction. On a loaded machine the CPU
/// time is the steadier figure: it does not count the time the process waited for
/// a core (it still feels the caches and memory bandwidth that others share).
class Stopwatch
{
public:
  Stopwatch()
    : t0(std::chrono::steady_clock::now())
    , cpu0(processCpuSeconds())
    , system0(processSystemSeconds())
  {}
  double seconds() const
  {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  double cpuSeconds() const { return processCpuSeconds() - cpu0; }
  /// The kernel's part of cpuSeconds().
  double systemSeconds() const { return processSystemSeconds() - system0; }

private:
  std::chrono::steady_clock::time_point t0;
  double cpu0;
  double system0;
};

/// A field of /proc/self/status in bytes (VmRSS, VmHWM), or -1.
inline long long procStatusBytes(const char* field)
{
  std::ifstream in("/proc/self/status");
  std::string line;
  const std::size_t n = std::strlen(field);
  while (std::getline(in, line))
  {
    if (line.compare(0, n, field) == 0 && line.size() > n && line[n] == ':')
    {
      long long kb = -1;
      std::istringstream(line.substr(n + 1)) >> kb;
      return kb < 0 ? -1 : kb * 1024;
    }
  }
  return -1;
}

/// Resets the kernel's peak-RSS mark (VmHWM) to the current RSS (Linux >= 4.0).
/// Returns false if that is not possible; VmHWM is then the peak of the whole process.
inline bool resetPeakRss()
{
  std::ofstream out("/proc/self/clear_refs");
  if (!out)
    return false;
  out << "5";
  out.flush();
  return static_cast<bool>(out);
}

/// Page faults served without a disk read so far in this process.
inline long long processMinorFaults()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_minflt;
}

/// Memory around the meshing call: RSS just before it, and the peak RSS during it.
struct MemoryProbe
{
  long long baseRss = -1;
  long long peakRss = -1;
  bool peakWasReset = false;
  long long minorFaults = -1; ///< page faults the call took (no disk read)
  void before()
  {
    peakWasReset = resetPeakRss();
    baseRss = procStatusBytes("VmRSS");
    minorFaults = processMinorFaults();
  }
  void after()
  {
    peakRss = procStatusBytes("VmHWM");
    minorFaults = processMinorFaults() - minorFaults;
  }
};

// ---------------------------------------------------------------- output checks

/// Output of one meshing call in a common form: vertices and triangles (any orientation).
struct MeshOut
{
  osm::Array<osm::Point> vertices;
  osm::Array<osm::Triangle> triangles;
};

struct Quality
{
  double minAngleDeg = 0.0;
  double maxAngleDeg = 0.0;
  std::size_t degenerate = 0;       ///< triangles with a zero area (in double arithmetic)
  std::size_t usedVertices = 0;     ///< vertices referenced by at least one triangle
  std::size_t missingSegments = 0;  ///< not a chain of mesh edges, though inside the domain
  std::size_t outsideSegments = 0;  ///< an endpoint lies outside the tool's domain
  std::size_t missingVertices = 0;  ///< input points inside the domain that are not mesh vertices
  std::size_t nonManifoldEdges = 0; ///< edges of three or more triangles
  std::size_t foldedEdges = 0;      ///< edges whose two triangles lie on the same side
};

/// Edges that show triangles overlapping, whatever the tool's orientation: an
/// edge in three or more triangles, or one whose two triangles' third vertices
/// lie strictly on the same side of it (exact test). It does not see overlaps
/// between triangles that share no edge (two separate sheets), which a tool
/// would have to make on purpose.
inline void countOverlapEdges(const MeshOut& mesh, Quality& q)
{
  // Row u lists (w, apex) for each triangle edge u-w with u < w.
  const std::size_t nv = mesh.vertices.size();
  std::vector<std::size_t> start(nv + 1, 0);
  for (const osm::Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
      ++start[std::min(t[i], t[(i + 1) % 3]) + 1];
  for (std::size_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  std::vector<std::pair<int, int>> row(start[nv]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const osm::Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
    {
      const int u = t[i], w = t[(i + 1) % 3];
      row[fill[std::min(u, w)]++] = { std::max(u, w), t[(i + 2) % 3] };
    }
  for (std::size_t u = 0; u < nv; ++u)
  {
    std::sort(row.begin() + start[u], row.begin() + start[u + 1]);
    for (std::size_t k = start[u]; k < start[u + 1];)
    {
      std::size_t end = k + 1;
      while (end < start[u + 1] && row[end].first == row[k].first)
        ++end;
      if (end - k > 2)
        ++q.nonManifoldEdges;
      else if (end - k == 2)
      {
        const osm::Point &a = mesh.vertices[u], &b = mesh.vertices[row[k].first];
        const double s1 = osm::orient2d(a, b, mesh.vertices[row[k].second]);
        const double s2 = osm::orient2d(a, b, mesh.vertices[row[k + 1].second]);
        if ((s1 > 0 && s2 > 0) || (s1 < 0 && s2 < 0))
          ++q.foldedEdges;
      }
      k = end;
    }
  }
}

/// Angle at b of triangle abc in degrees, from atan2(|cross|, dot): accurate near 0 and 180.
inline double angleDeg(const osm::Point& a, const osm::Point& b, const osm::Point& c)
{
  const double ux = a.x - b.x, uy = a.y - b.y, vx = c.x - b.x, vy = c.y - b.y;
  return std::atan2(std::fabs(ux * vy - uy * vx), ux * vx + uy * vy) * (180.0 / std::acos(-1.0));
}

struct PointHash
{
  std::size_t operator()(const osm::Point& p) const
  {
    std::uint64_t x, y;
    std::memcpy(&x, &p.x, 8);
    std::memcpy(&y, &p.y, 8);
    x ^= y + 0x9E3779B97F4A7C15ull + (x << 6) + (x >> 2);
    x ^= x >> 33;
    x *= 0xFF51AFD7ED558CCDull;
    x ^= x >> 33;
    return static_cast<std::size_t>(x);
  }
};

/// Angles, and conformity: is every input segment a chain of mesh edges? An input
/// point is found in the mesh by its exact coordinates (every tool here keeps input
/// vertices bit for bit). From one endpoint the check steps to the neighbour that
/// lies on the segment (within rounding of a computed Steiner point: 1e-9 of the
/// segment's length plus 1e-14 of its coordinates) and is the nearest one further
/// along, until it reaches the other endpoint or gets stuck.
/// inDomain[i] == 0 says that the tool legitimately left input point i out (it lies
/// outside the domain the tool meshed); empty means every point must be in the mesh.
inline Quality inspect(
  const osm::Pslg& input, const MeshOut& mesh, const std::vector<char>& inDomain)
{
  Quality q;
  const std::size_t nv = mesh.vertices.size();
  q.minAngleDeg = 180.0;
  q.maxAngleDeg = 0.0;
  std::vector<char> used(nv, 0);
  for (const osm::Triangle& t : mesh.triangles)
  {
    const osm::Point &a = mesh.vertices[t[0]], &b = mesh.vertices[t[1]], &c = mesh.vertices[t[2]];
    const double angles[3] = { angleDeg(c, a, b), angleDeg(a, b, c), angleDeg(b, c, a) };
    for (double x : angles)
    {
      q.minAngleDeg = std::min(q.minAngleDeg, x);
      q.maxAngleDeg = std::max(q.maxAngleDeg, x);
    }
    if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) == 0.0)
      ++q.degenerate;
    used[t[0]] = used[t[1]] = used[t[2]] = 1;
  }
  if (mesh.triangles.empty())
    q.minAngleDeg = q.maxAngleDeg = 0.0;
  for (char u : used)
    q.usedVertices += u ? 1 : 0;
  countOverlapEdges(mesh, q);

  // Vertex adjacency (compressed rows; an edge may be listed twice, which is harmless).
  std::vector<std::size_t> start(nv + 1, 0);
  for (const osm::Triangle& t : mesh.triangles)
    for (int v : t)
      start[v + 1] += 2;
  for (std::size_t v = 0; v < nv; ++v)
    start[v + 1] += start[v];
  std::vector<int> nbr(start[nv]);
  std::vector<std::size_t> fill(start.begin(), start.end() - 1);
  for (const osm::Triangle& t : mesh.triangles)
    for (int i = 0; i < 3; ++i)
    {
      const int v = t[i];
      nbr[fill[v]++] = t[(i + 1) % 3];
      nbr[fill[v]++] = t[(i + 2) % 3];
    }

  std::unordered_map<osm::Point, int, PointHash> vertexAt;
  vertexAt.reserve(q.usedVertices * 2);
  for (std::size_t v = 0; v < nv; ++v)
    if (used[v])
      vertexAt.emplace(mesh.vertices[v], static_cast<int>(v));
  auto expected = [&](int i) { return inDomain.empty() || inDomain[i] != 0; };
  std::vector<int> inputVertex(input.points.size(), -1);
  for (std::size_t i = 0; i < input.points.size(); ++i)
  {
    const auto it = vertexAt.find(input.points[i]);
    if (it != vertexAt.end())
      inputVertex[i] = it->second;
    else if (expected(static_cast<int>(i)))
      ++q.missingVertices;
  }

  for (const osm::Segment& s : input.segments)
  {
    if (!expected(s[0]) || !expected(s[1]))
    {
      ++q.outsideSegments;
      continue;
    }
    const int va = inputVertex[s[0]], vb = inputVertex[s[1]];
    if (va < 0 || vb < 0)
    {
      ++q.missingSegments;
      continue;
    }
    if (va == vb)
      continue; // a zero-length segment: nothing to conform to
    const osm::Point a = input.points[s[0]], b = input.points[s[1]];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy, len = std::sqrt(len2);
    const double scale =
      std::max({ std::fabs(a.x), std::fabs(a.y), std::fabs(b.x), std::fabs(b.y) });
    const double tol = 1e-9 * len + 1e-14 * scale;
    int cur = va;
    double tCur = 0.0;
    bool reached = false;
    for (std::size_t steps = 0; steps <= nv; ++steps)
    {
      if (cur == vb)
      {
        reached = true;
        break;
      }
      int best = -1;
      double bestT = 0.0;
      for (std::size_t k = start[cur]; k < start[cur + 1]; ++k)
      {
        const int w = nbr[k];
        const osm::Point& p = mesh.vertices[w];
        const double px = p.x - a.x, py = p.y - a.y;
        const double t = (px * dx + py * dy) / len2;
        const double off = std::fabs(px * dy - py * dx) / len;
        if (off > tol || !(t > tCur) || t > 1.0 + tol / len)
          continue;
        if (best < 0 || t < bestT)
        {
          best = w;
          bestT = t;
        }
      }
      if (best < 0)
        break;
      cur = best;
      tCur = bestT;
    }
    if (!reached)
      ++q.missingSegments;
  }
  return q;
}

// ---------------------------------------------------------------- JSON line

class JsonLine
{
public:
  JsonLine& add(const std::string& key, const std::string& value)
  {
    std::string e;
    for (char c : value)
    {
      if (c == '"' || c == '\\')
        e += '\\', e += c;
      else if (static_cast<unsigned char>(c) < 0x20)
      {
        char buf[8];
        std::snprintf(buf, sizeof buf, "\\u%04x", c);
        e += buf;
      }
      else
        e += c;
    }
    return raw(key, "\"" + e + "\"");
  }
  JsonLine& add(const std::string& key, const char* value) { return add(key, std::string(value)); }
  JsonLine& add(const std::string& key, double value)
  {
    if (!std::isfinite(value))
      return raw(key, "null");
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.9g", value);
    return raw(key, buf);
  }
  JsonLine& add(const std::string& key, long long value) { return raw(key, std::to_string(value)); }
  JsonLine& add(const std::string& key, std::size_t value)
  {
    return raw(key, std::to_string(value));
  }
  JsonLine& add(const std::string& key, int value) { return raw(key, std::to_string(value)); }
  JsonLine& add(const std::string& key, bool value) { return raw(key, value ? "true" : "false"); }
  std::string str() const { return "{" + body + "}"; }

private:
  JsonLine& raw(const std::string& key, const std::string& value)
  {
    if (!body.empty())
      body += ", ";
    body += "\"" + key + "\": " + value;
    return *this;
  }
  std::string body;
};

// ---------------------------------------------------------------- driver main

/// What a tool returns from one meshing call.
struct RunOutput
{
  bool ok = true;
  std::string error;
  double seconds = 0.0;       ///< the meshing call only, wall time
  double cpuSeconds = 0.0;    ///< the same call, process CPU time
  double systemSeconds = -1;  ///< the kernel's part of it, if the driver measured it
  MeshOut mesh;               ///< filled after the timed call (conversion not timed)
  std::vector<char> inDomain; ///< per input point, see inspect(); empty: all
  std::size_t triangles = 0;
  std::size_t vertices = 0;
  MemoryProbe memory;
  JsonLine extra;                ///< tool-specific figures (phase times, ...)
  std::vector<std::string> args; ///< the driver's own options (after the input)
  bool has(const std::string& arg) const
  {
    return std::find(args.begin(), args.end(), arg) != args.end();
  }
  /// The number after option name (as in --max-edge 0.01), or fallback.
  double number(const std::string& name, double fallback) const
  {
    const auto it = std::find(args.begin(), args.end(), name);
    return it != args.end() && it + 1 != args.end() ? std::strtod((it + 1)->c_str(), nullptr)
                                                    : fallback;
  }
};

/// Runs one tool on the input named by argv[1] and prints its JSON line.
/// The tool must call memory.before() / memory.after() around its meshing call.
inline int driverMain(int argc, char** argv, const char* tool,
  const std::function<void(const osm::Pslg&, RunOutput&, bool wantMesh)>& run)
{
  if (argc < 2)
  {
    std::fprintf(stderr,
      "usage: %s <file.poly | family:N:seed> [--no-check] [--warm K] [tool options]\n", argv[0]);
    return 2;
  }
  const std::string spec = argv[1];
  bool check = true;
  int warm = 0;
  RunOutput out;
  for (int i = 2; i < argc; ++i)
  {
    if (std::string(argv[i]) == "--no-check")
      check = false;
    else if (std::string(argv[i]) == "--warm")
    {
      char* end = nullptr;
      const long k = i + 1 < argc ? std::strtol(argv[++i], &end, 10) : -1;
      if (!end || *end != '\0' || k < 0 || k > 1000000)
      {
        std::fprintf(stderr, "%s: --warm needs a count of calls from 0 to 1000000\n", argv[0]);
        return 2;
      }
      warm = static_cast<int>(k);
    }
    else
      out.args.push_back(argv[i]);
  }
  JsonLine line;
  line.add("tool", tool).add("input", spec);
  osm::Pslg pslg;
  std::string error;
  if (!loadInput(spec, pslg, error))
  {
    line.add("ok", false).add("error", "input: " + error);
    std::printf("%s\n", line.str().c_str());
    return 1;
  }
  line.add("input_vertices", pslg.points.size()).add("input_segments", pslg.segments.size());
  // Unmeasured calls first (--warm): the measured one then finds the code,
  // the caches and the allocator's memory warm, as a long-lived application's
  // repeated calls do, instead of paying a fresh process's first touches.
  for (int k = 0; k < warm; ++k)
  {
    RunOutput discarded;
    discarded.args = out.args;
    run(pslg, discarded, false);
  }
  if (warm > 0)
    line.add("warm_calls", warm);
  run(pslg, out, check);
  line.add("ok", out.ok);
  if (!out.ok)
    line.add("error", out.error);
  line.add("seconds", out.seconds)
    .add("cpu_seconds", out.cpuSeconds)
    .add("out_vertices", out.vertices)
    .add("out_triangles", out.triangles)
    .add("base_rss", out.memory.baseRss)
    .add("peak_rss", out.memory.peakRss)
    .add("peak_reset", out.memory.peakWasReset)
    .add("minor_faults", out.memory.minorFaults);
  if (out.systemSeconds >= 0)
    line.add("system_seconds", out.systemSeconds);
  if (out.ok && check)
  {
    const Quality q = inspect(pslg, out.mesh, out.inDomain);
    line.add("min_angle", q.minAngleDeg)
      .add("max_angle", q.maxAngleDeg)
      .add("degenerate", q.degenerate)
      .add("missing_segments", q.missingSegments)
      .add("outside_segments", q.outsideSegments)
      .add("missing_vertices", q.missingVertices)
      .add("nonmanifold_edges", q.nonManifoldEdges)
      .add("folded_edges", q.foldedEdges);
  }
  std::string extra = out.extra.str();
  std::string text = line.str();
  if (extra.size() > 2)
    text = text.substr(0, text.size() - 1) + ", " + extra.substr(1);
  std::printf("%s\n", text.c_str());
  std::fflush(stdout);
  return out.ok ? 0 : 1;
}

} // namespace osmbench

#endif
