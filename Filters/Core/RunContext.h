// Internal: progress reporting and abort polling shared by the phases.
#ifndef osm_RunContext_h
#define osm_RunContext_h

#include "Mesher.h"

#include <array>
#include <cstdint>
#include <string>

namespace osm
{

/// The error of a run the user aborted (Progress::aborted).
inline constexpr const char* kAbortedByTheUser = "aborted by the user";

/// How a refusal of points too close for double precision begins. Where the
/// round has points where segments cross, the mesher names them too
/// (Mesher::execute), by replacing this subject.
inline constexpr const char* kPointsTooCloseSubject = "input points are closer";

/// Thrown inside the core only, caught by mesh(): the user aborted or a cap was hit.
struct Stop
{
  std::string reason;
  bool located = false; ///< at is where, in the core's scaled coordinates
  Point at;
  /// The segments at fault (indices of the round's segments), -1 for none.
  std::array<int, 2> segments{ -1, -1 };
  /// What a merge tolerance may do about it, which the message then says.
  enum class Remedy : std::uint8_t
  {
    None,
    /// Input points too close for double precision: it merges them.
    MergePoints,
    /// Segments too close (crossings rounded apart, segments at tiny
    /// angles): it joins crossings and bends segments onto points.
    JoinSegments,
    /// A segment within rounding of an input point: it bends it onto it.
    BendOntoPoint
  };
  Remedy remedy = Remedy::None;
  /// The mesh outgrew a cap (Steiner points, this machine's memory).
  bool outgrown = false;
  /// Said after the segments and the point.
  std::string tail;
  /// at is a point of the round, which the segment passes within rounding.
  bool atPoint = false;
};

class RunContext
{
public:
  explicit RunContext(Progress* p)
    : progress(p)
  {}

  /// A context without progress, for phases called on their own (tests):
  /// nothing in it changes, so every thread may share it.
  static RunContext& silent()
  {
    static RunContext none(nullptr);
    return none;
  }
  /// Report progress of the current phase, which spans [begin, end] of a
  /// round (of the run, in the first round).
  void phase(const char* name, double begin, double end)
  {
    if (!progress)
      return;
    phaseName = name;
    phaseBegin = roundBegin + (roundEnd - roundBegin) * begin;
    phaseEnd = roundBegin + (roundEnd - roundBegin) * end;
    report(0.0);
  }
  /// The mesher meshes the input again (after splitting crossings, or with
  /// another domain): the new round's phases share what is left of the run,
  /// so that progress never goes back.
  void newRound()
  {
    roundBegin = phaseBegin + (phaseEnd - phaseBegin) * lastFraction;
    roundEnd = 1.0;
  }
  /// This round is expected to be followed by a larger one: it takes only
  /// share of what is left.
  void shareRound(double share) { roundEnd = roundBegin + share * (1.0 - roundBegin); }
  /// fraction of the current phase; also polls for an abort.
  void report(double fraction)
  {
    if (!progress)
      return;
    lastFraction = fraction;
    progress->report(phaseBegin + (phaseEnd - phaseBegin) * fraction, phaseName);
    if (progress->aborted())
      throw Stop{ kAbortedByTheUser };
  }
  /// Polls for an abort between steps that report no fraction of their own
  /// (reports the last fraction again).
  void poll()
  {
    if (progress)
      report(lastFraction);
  }
  /// The same, for inner loops: polls every 'every' calls.
  void pollEvery(unsigned every)
  {
    if (progress && ++ticks % every == 0)
      report(lastFraction);
  }
  /// Cheap call for inner loops: reports every 'every' calls.
  void tick(double fraction, unsigned every = 4096)
  {
    if (progress && ++ticks % every == 0)
      report(fraction);
  }
  /// The same, with the fraction computed only when it is reported.
  template <typename Fraction>
  void tickWith(Fraction&& fraction, unsigned every = 4096)
  {
    if (progress && ++ticks % every == 0)
      report(fraction());
  }

private:
  Progress* progress;
  const char* phaseName = "";
  double phaseBegin = 0.0;
  double phaseEnd = 1.0;
  double lastFraction = 0.0; ///< of the current phase, as last reported
  double roundBegin = 0.0;
  double roundEnd = 1.0;
  unsigned ticks = 0;
};

} // namespace osm

#endif
